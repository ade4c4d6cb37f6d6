#include "bemcontact/reference/flat_punch.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace bemcontact::reference {

double FlatPunchPlane::pressure(double x) const {
  const double a = half_width;
  if (std::abs(x) >= a) return std::abs(x) == a ? std::numeric_limits<double>::infinity() : 0.0;
  return (load + 2.0 * moment * x / (a * a)) / (std::numbers::pi * std::sqrt((a - x) * (a + x)));
}

double FlatPunchPlane::tilt() const {
  return 4.0 * moment / (std::numbers::pi * half_width * half_width * plane_modulus);
}

double FlatPunchPlane::indentation_drop(double x) const {
  const double t = std::abs(x) / half_width;
  if (t <= 1.0) return 0.0;
  return 2.0 * load / (std::numbers::pi * plane_modulus) * std::acosh(t);
}

}  // namespace bemcontact::reference

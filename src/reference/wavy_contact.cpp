#include "bemcontact/reference/wavy_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bemcontact::reference {

double WavyContact::full_contact_pressure() const { return std::numbers::pi * plane_modulus * amplitude / wavelength; }

double WavyContact::mean_pressure(double a) const {
  const double s = std::sin(std::numbers::pi * a / wavelength);
  return full_contact_pressure() * s * s;
}

double WavyContact::half_width(double p) const {
  return wavelength / std::numbers::pi * std::asin(std::sqrt(std::clamp(p / full_contact_pressure(), 0.0, 1.0)));
}

double WavyContact::pressure(double x, double a) const {
  if (std::abs(x) > a) return 0.0;
  const double s = std::sin(std::numbers::pi * a / wavelength), t = std::sin(std::numbers::pi * x / wavelength);
  return 2.0 * mean_pressure(a) / (s * s) * std::cos(std::numbers::pi * x / wavelength) *
         std::sqrt(std::max(s * s - t * t, 0.0));
}

}  // namespace bemcontact::reference

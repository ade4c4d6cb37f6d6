#include "bemcontact/reference/winkler.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bemcontact::reference {
namespace {

double circle_gap(double R, double x) { return R - std::sqrt(R * R - x * x); }

}  // namespace

double WinklerCylinder::load_at(double delta) const {
  const double a = std::sqrt(2.0 * radius * delta - delta * delta);
  // x = a (1 - s^2), s in [0, 1]: dx = 2 a s ds, panels crowding at the edge (s = 0).
  const auto integrand = [&](double s) {
    const double x = a * (1.0 - s * s);
    const double pen = delta - circle_gap(radius, x);
    return pen > 0.0 ? stiffness * std::pow(pen, exponent) * 2.0 * a * s : 0.0;
  };
  constexpr int panels = 4096;  // even
  const double h = 1.0 / panels;
  double sum = integrand(0.0) + integrand(1.0);
  for (int k = 1; k < panels; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * integrand(k * h);
  return 2.0 * sum * h / 3.0;
}

double WinklerCylinder::approach() const {
  // The parabolic gap's closed form as the first guess, then bisection on P(delta).
  const double beta = std::sqrt(std::numbers::pi) * std::tgamma(exponent + 1.0) / std::tgamma(exponent + 1.5);
  const double guess = std::pow(load / (stiffness * beta * std::sqrt(2.0 * radius)), 1.0 / (exponent + 0.5));
  double low = 0.5 * guess, high = 2.0 * guess;
  while (load_at(high) < load) high *= 2.0;
  while (load_at(low) > load) low *= 0.5;
  for (int k = 0; k < 200 && high - low > 1e-15 * high; ++k) {
    const double mid = 0.5 * (low + high);
    (load_at(mid) < load ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

double WinklerCylinder::half_width() const {
  const double delta = approach();
  return std::sqrt(2.0 * radius * delta - delta * delta);
}

double WinklerCylinder::pressure(double x) const {
  const double pen = approach() - circle_gap(radius, std::abs(x));
  return std::abs(x) < radius && pen > 0.0 ? stiffness * std::pow(pen, exponent) : 0.0;
}

}  // namespace bemcontact::reference

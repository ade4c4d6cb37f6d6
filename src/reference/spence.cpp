#include "bemcontact/reference/spence.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "bemcontact/core/error.hpp"

namespace bemcontact::reference {
namespace {

double arithmetic_geometric_mean(double x, double y) {
  // Quadratic convergence: 8 steps suffice for y >= 1e-300 / x; the loop stops at round-off.
  for (int i = 0; i < 64 && std::abs(x - y) > 4.0 * std::numeric_limits<double>::epsilon() * x; ++i) {
    const double m = 0.5 * (x + y);
    y = std::sqrt(x * y);
    x = m;
  }
  return 0.5 * (x + y);
}

}  // namespace

// (E.2); 1/G = 0 for a rigid body.
double spence_gamma(const Material& body1, const Material& body2, AnalysisType type) {
  const double nu1 = kernel_poisson_ratio(type, body1), nu2 = kernel_poisson_ratio(type, body2);
  const double g1 = 1.0 / body1.shear_modulus(), g2 = 1.0 / body2.shear_modulus();  // compliances
  return (0.5 * (1.0 - 2.0 * nu1) * g1 - 0.5 * (1.0 - 2.0 * nu2) * g2) /
         ((1.0 - nu1) * g1 + (1.0 - nu2) * g2);
}

double complementary_elliptic_k(double c) {
  if (!(c > 0.0 && c <= 1.0)) throw Error("reference::complementary_elliptic_k: need 0 < c <= 1");
  return 0.5 * std::numbers::pi / arithmetic_geometric_mean(1.0, c);
}

// (E.1), written with ln((1+c)/(1-c)) = log1p(c) - log1p(-c) for accuracy near c = 1.
double spence_friction_coefficient(double stick_ratio, double gamma) {
  const double c = stick_ratio;
  if (!(c > 0.0 && c < 1.0)) throw Error("reference::spence_friction_coefficient: need 0 < c < 1");
  return std::abs(gamma) * (std::log1p(c) - std::log1p(-c)) / (2.0 * c * complementary_elliptic_k(c));
}

double spence_stick_ratio(double friction_coefficient, double gamma) {
  const double beta = friction_coefficient;
  if (!(beta > 0.0) || !std::isfinite(beta))
    throw Error("reference::spence_stick_ratio: the friction coefficient must be positive");
  if (!(std::abs(gamma) > 0.0 && std::abs(gamma) <= 0.5))
    throw Error("reference::spence_stick_ratio: need 0 < |gamma| <= 1/2");
  auto residual = [&](double c) { return spence_friction_coefficient(c, gamma) - beta; };

  double lo = std::numeric_limits<double>::min();
  double hi = std::nextafter(1.0, 0.0);
  if (residual(lo) >= 0.0) return 0.0;  // root below the smallest normal double
  if (residual(hi) <= 0.0) return hi;   // root closer to 1 than one ulp
  for (int i = 0; i < 400; ++i) {
    // Geometric steps in c near 0 and in 1 - c near 1, arithmetic in between.
    double mid = 0.5 * (lo + hi);
    if (hi <= 0.5 && hi > 4.0 * lo) mid = std::sqrt(lo) * std::sqrt(hi);  // no underflow of lo * hi
    else if (lo >= 0.5 && (1.0 - lo) > 4.0 * (1.0 - hi)) mid = 1.0 - std::sqrt(1.0 - lo) * std::sqrt(1.0 - hi);
    if (!(mid > lo && mid < hi)) break;  // bracket is two adjacent doubles
    (residual(mid) < 0.0 ? lo : hi) = mid;
  }
  return std::abs(residual(lo)) <= std::abs(residual(hi)) ? lo : hi;
}

}  // namespace bemcontact::reference

#include "bemcontact/reference/fretting.hpp"

#include <cmath>
#include <numbers>

#include "bemcontact/core/error.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::reference {
namespace {

// The Cattaneo distribution with stick zone c: mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)].
double cattaneo(double x, double c, double a, double mu_p0) {
  double q = std::abs(x) < a ? std::sqrt(1.0 - x * x / (a * a)) : 0.0;
  if (std::abs(x) < c) q -= (c / a) * std::sqrt(1.0 - x * x / (c * c));
  return mu_p0 * q;
}

}  // namespace

double PartialSlipLine::stick_ratio(double Q) const {
  const double ratio = std::abs(Q) / (friction * hertz.load);
  if (!(ratio < 1.0)) throw Error("PartialSlipLine: Q must be below mu P (gross slip)");
  return std::sqrt(1.0 - ratio);
}

double PartialSlipLine::shear(double x, double Q) const {
  const double a = hertz.half_width();
  const double q = cattaneo(x, stick_ratio(Q) * a, a, friction * hertz.max_pressure());
  return Q >= 0.0 ? q : -q;
}

double PartialSlipLine::reversal_stick_ratio(double Q_star, double Q) const {
  const double ratio = (Q_star - Q) / (2.0 * friction * hertz.load);
  if (!(ratio >= 0.0 && ratio <= 1.0)) throw Error("PartialSlipLine: Q must lie between -Q* and Q*");
  return std::sqrt(1.0 - ratio);
}

double PartialSlipLine::unloading_shear(double x, double Q_star, double Q) const {
  const double a = hertz.half_width(), mu_p0 = friction * hertz.max_pressure();
  return cattaneo(x, stick_ratio(Q_star) * a, a, mu_p0) -
         2.0 * cattaneo(x, reversal_stick_ratio(Q_star, Q) * a, a, mu_p0);
}

double PartialSlipLine::dissipated_energy_per_cycle(double Q_star) const {
  const double g = stick_ratio(Q_star);
  // I(g): the integrand vanishes like (s - g)^(3/2) at s = g and has a square-root end at
  // s = 1; s = g + (1 - g) u^2 ... composite Gauss on u with s = 1 - (1 - g)(1 - u)^2 near 1
  // is not needed at this accuracy: 64 panels of 8 points on s give 1e-9.
  const auto& rule = quadrature::gauss_legendre(8);
  const int panels = 64;
  double integral = 0.0;
  for (int k = 0; k < panels; ++k) {
    const double lo = g + (1.0 - g) * k / panels, hi = g + (1.0 - g) * (k + 1) / panels;
    for (int i = 0; i < rule.size(); ++i) {
      const double s = 0.5 * (lo + hi) + 0.5 * (hi - lo) * rule.nodes[i];
      const double value = std::sqrt(std::max(1.0 - s * s, 0.0)) *
                           (s * std::sqrt(std::max(s * s - g * g, 0.0)) - g * g * std::acosh(std::max(s / g, 1.0)));
      integral += 0.5 * (hi - lo) * rule.weights[i] * value;
    }
  }
  const double mu_P = friction * hertz.load;
  return 32.0 * mu_P * mu_P / (std::numbers::pi * std::numbers::pi * hertz.effective_modulus) * integral;
}

}  // namespace bemcontact::reference

#include "bemcontact/reference/hertz.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "bemcontact/core/error.hpp"

namespace bemcontact::reference {
namespace {

using std::numbers::pi;

// 1 - zeta atan(1/zeta), without the cancellation of the direct form at large depth:
// there it is the series sum_k (-1)^(k+1) / ((2k+1) zeta^(2k)), whose terms fall by
// 1/zeta^2 <= 1e-2, so 9 terms reach round-off.
double one_minus_zeta_atan(double zeta) {
  if (zeta <= 0.0) return 1.0;
  if (zeta < 10.0) return 1.0 - zeta * std::atan(1.0 / zeta);
  const double w = 1.0 / (zeta * zeta);
  double term = w, sum = 0.0;
  for (int k = 1; k <= 9; ++k) {
    sum += ((k % 2) ? 1.0 : -1.0) * term / (2.0 * k + 1.0);
    term *= w;
  }
  return sum;
}

// (1 - (1 - x)^(3/2)) / x for 0 <= x <= 1 (x = r^2/a^2); 3/2 at x = 0.
double hertz_ring_factor(double x) {
  if (x <= 0.0) return 1.5;
  return -std::expm1(1.5 * std::log1p(-x)) / x;
}

void require_positive(double value, const char* what) {
  if (!(value > 0.0)) throw Error(std::string("reference: ") + what + " must be positive");
}

// Golden-section search of the maximum of a unimodal f on [lo, hi].
template <class F>
AxisMaxShear golden_section_max(F f, double lo, double hi) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  while (hi - lo > 1e-12) {
    if (f1 < f2) {
      lo = x1; x1 = x2; f1 = f2;
      x2 = lo + g * (hi - lo); f2 = f(x2);
    } else {
      hi = x2; x2 = x1; f2 = f1;
      x1 = hi - g * (hi - lo); f1 = f(x1);
    }
  }
  const double z = 0.5 * (lo + hi);
  return {z, f(z)};
}

}  // namespace

double contact_modulus(const Material& body, AnalysisType type) {
  const double nu = body.poisson_ratio;
  return type == AnalysisType::plane_stress ? body.young_modulus
                                            : body.young_modulus / (1.0 - nu * nu);
}

// (D.8); an infinite modulus (rigid body) contributes nothing.
double contact_modulus(const Material& body1, const Material& body2, AnalysisType type) {
  return 1.0 / (1.0 / contact_modulus(body1, type) + 1.0 / contact_modulus(body2, type));
}

// (D.3)
double relative_radius(double radius1, double radius2) {
  return 1.0 / (1.0 / radius1 + 1.0 / radius2);
}

HertzPointContact hertz_point_contact(double load, double radius1, const Material& body1,
                                      double radius2, const Material& body2) {
  return {load, relative_radius(radius1, radius2),
          contact_modulus(body1, body2, AnalysisType::axisymmetric)};
}

// (D.8)
double HertzPointContact::contact_radius() const {
  require_positive(load, "HertzPointContact.load");
  require_positive(radius, "HertzPointContact.radius");
  require_positive(effective_modulus, "HertzPointContact.effective_modulus");
  return std::cbrt(3.0 * load * radius / (4.0 * effective_modulus));
}

// (D.7)
double HertzPointContact::max_pressure() const {
  const double a = contact_radius();
  return 3.0 * load / (2.0 * pi * a * a);
}

// (D.9)
double HertzPointContact::approach() const {
  const double a = contact_radius();
  return a * a / radius;
}

// (D.6)
double HertzPointContact::pressure(double r) const {
  const double a = contact_radius(), x = r / a;
  return std::abs(x) < 1.0 ? max_pressure() * std::sqrt(1.0 - x * x) : 0.0;
}

// (D.10), (D.11)
SurfaceDisplacement HertzPointContact::surface_displacement(const Material& body, double r) const {
  const double a = contact_radius(), p0 = max_pressure();
  const double E = body.young_modulus, nu = body.poisson_ratio;
  const double radial_scale = -(1.0 - 2.0 * nu) * (1.0 + nu) * p0 / (3.0 * E);
  SurfaceDisplacement u;
  if (r < a) {
    const double x = (r / a) * (r / a);
    u.radial = radial_scale * r * hertz_ring_factor(x);  // a^2/r (1 - (1-x)^1.5) = r * factor
    u.indentation = (1.0 - nu * nu) * pi * p0 * (2.0 * a * a - r * r) / (4.0 * a * E);
  } else {
    u.radial = radial_scale * a * a / r;
    u.indentation = (1.0 - nu * nu) * p0 / (2.0 * a * E) *
                    ((2.0 * a * a - r * r) * std::asin(a / r) +
                     a * r * std::sqrt(1.0 - (a / r) * (a / r)));
  }
  return u;
}

// (D.12), (D.13); the scan lost the fraction bars: the factor is (1 - 2nu)/3 * a^2/r^2.
Stress HertzPointContact::surface_stress(double poisson_ratio, double r) const {
  const double a = contact_radius(), p0 = max_pressure(), nu = poisson_ratio;
  Stress s;
  if (r < a) {
    const double x = (r / a) * (r / a);
    const double ring = (1.0 - 2.0 * nu) / 3.0 * hertz_ring_factor(x);
    const double root = std::sqrt(1.0 - x);
    s.s11 = p0 * (ring - root);
    s.s33 = p0 * (-ring - 2.0 * nu * root);
    s.s22 = -p0 * root;
  } else {
    const double outer = (1.0 - 2.0 * nu) / 3.0 * (a / r) * (a / r);
    s.s11 = p0 * outer;
    s.s33 = -p0 * outer;
  }
  return s;
}

// (D.14)
Stress HertzPointContact::axis_stress(double poisson_ratio, double depth) const {
  const double a = contact_radius(), p0 = max_pressure();
  const double zeta = depth / a, q = 1.0 / (1.0 + zeta * zeta);
  Stress s;
  s.s11 = p0 * (-(1.0 + poisson_ratio) * one_minus_zeta_atan(zeta) + 0.5 * q);
  s.s33 = s.s11;
  s.s22 = -p0 * q;
  return s;
}

AxisMaxShear huber_max_shear_on_axis(double poisson_ratio) {
  const HertzPointContact unit{1.0, 1.0, 0.75};  // a = 1
  const double p0 = unit.max_pressure();
  auto tau = [&](double zeta) {
    const Stress s = unit.axis_stress(poisson_ratio, zeta);
    return 0.5 * (s.s11 - s.s22) / p0;
  };
  return golden_section_max(tau, 0.0, 4.0);
}

double HertzLineContact::half_width() const {
  require_positive(load, "HertzLineContact.load");
  require_positive(radius, "HertzLineContact.radius");
  require_positive(effective_modulus, "HertzLineContact.effective_modulus");
  return std::sqrt(4.0 * load * radius / (pi * effective_modulus));
}

double HertzLineContact::max_pressure() const { return 2.0 * load / (pi * half_width()); }

double HertzLineContact::pressure(double x) const {
  const double t = x / half_width();
  return std::abs(t) < 1.0 ? max_pressure() * std::sqrt(1.0 - t * t) : 0.0;
}

Stress HertzLineContact::axis_stress(double depth, double poisson_ratio, AnalysisType type) const {
  const double p0 = max_pressure(), zeta = depth / half_width();
  const double root = std::sqrt(1.0 + zeta * zeta);
  Stress s;
  s.s11 = -p0 * ((1.0 + 2.0 * zeta * zeta) / root - 2.0 * zeta);
  s.s22 = -p0 / root;
  if (type == AnalysisType::plane_strain) s.s33 = poisson_ratio * (s.s11 + s.s22);
  return s;
}

AxisMaxShear mcewen_max_shear_on_axis() {
  const HertzLineContact unit{1.0, 1.0, 4.0 / pi};  // a = 1
  const double p0 = unit.max_pressure();
  auto tau = [&](double zeta) {
    const Stress s = unit.axis_stress(zeta, 0.0, AnalysisType::plane_stress);
    return 0.5 * (s.s11 - s.s22) / p0;
  };
  return golden_section_max(tau, 0.0, 4.0);
}

FirstYield hertz_sphere_first_yield(double poisson_ratio) {
  const HertzPointContact unit{1.0, 1.0, 0.75};  // a = 1
  const double p0 = unit.max_pressure();
  const auto vm = [&](double zeta) { return unit.axis_stress(poisson_ratio, zeta).von_mises() / p0; };
  const auto max = golden_section_max(vm, 0.0, 4.0);
  return {max.depth_over_a, max.shear_over_p0};
}

FirstYield hertz_cylinder_first_yield(double poisson_ratio) {
  const HertzLineContact unit{1.0, 1.0, 4.0 / pi};  // a = 1
  const double p0 = unit.max_pressure();
  const auto vm = [&](double zeta) { return unit.axis_stress(zeta, poisson_ratio).von_mises() / p0; };
  const auto max = golden_section_max(vm, 0.0, 4.0);
  return {max.depth_over_a, max.shear_over_p0};
}

}  // namespace bemcontact::reference

#include "bemcontact/reference/curved_beam.hpp"

#include <cmath>

namespace bemcontact::reference {

namespace {

struct Constants {
  double A, B, C;
};

// [TimoshenkoGoodier1970, §29], with N the common denominator.
Constants constants(const CurvedBeamEndCouple& beam) {
  const double a = beam.inner_radius, b = beam.outer_radius, M = beam.moment;
  const double a2 = a * a, b2 = b * b, log_ratio = std::log(b / a);
  const double N = (b2 - a2) * (b2 - a2) - 4.0 * a2 * b2 * log_ratio * log_ratio;
  return {-4.0 * M / N * a2 * b2 * log_ratio, -2.0 * M / N * (b2 - a2),
          M / N * (b2 - a2 + 2.0 * (b2 * std::log(b) - a2 * std::log(a)))};
}

}  // namespace

PolarStress CurvedBeamEndCouple::polar_stress(double r) const {
  const auto [A, B, C] = constants(*this);
  PolarStress s;
  s.rr = A / (r * r) + B * (1.0 + 2.0 * std::log(r)) + 2.0 * C;
  s.tt = -A / (r * r) + B * (3.0 + 2.0 * std::log(r)) + 2.0 * C;
  s.rt = 0.0;
  if (type == AnalysisType::plane_strain) s.zz = material.poisson_ratio * (s.rr + s.tt);
  return s;
}

Stress CurvedBeamEndCouple::stress(const Vec2& x) const {
  return to_cartesian(polar_stress(x.norm()), std::atan2(x.y(), x.x()));
}

Vec2 CurvedBeamEndCouple::polar_displacement(double r, double theta) const {
  const auto [A, B, C] = constants(*this);
  const Material m = plane_stress_equivalent(type, material);
  const double E = m.young_modulus, nu = m.poisson_ratio;
  const double radial =
      (-(1.0 + nu) * A / r + 2.0 * (1.0 - nu) * B * r * std::log(r) - (1.0 + nu) * B * r + 2.0 * (1.0 - nu) * C * r) /
      E;
  return {radial, 4.0 * B * r * theta / E};
}

Vec2 CurvedBeamEndCouple::displacement(const Vec2& x) const {
  const double theta = std::atan2(x.y(), x.x());
  const Vec2 polar = polar_displacement(x.norm(), theta);
  return polar_to_cartesian(polar.x(), polar.y(), theta);
}

}  // namespace bemcontact::reference

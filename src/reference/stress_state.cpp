#include "bemcontact/reference/stress_state.hpp"

#include <cmath>

#include "bemcontact/core/error.hpp"

namespace bemcontact::reference {

Mat2 Stress::in_plane() const {
  Mat2 m;
  m << s11, s12, s12, s22;
  return m;
}

Vec2 Stress::traction(const Vec2& normal) const { return in_plane() * normal; }

double Stress::von_mises() const {
  const double d12 = s11 - s22, d23 = s22 - s33, d31 = s33 - s11;
  return std::sqrt(0.5 * (d12 * d12 + d23 * d23 + d31 * d31) + 3.0 * s12 * s12);
}

Stress to_cartesian(const PolarStress& polar, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Stress out;
  out.s11 = polar.rr * c * c + polar.tt * s * s - 2.0 * polar.rt * s * c;
  out.s22 = polar.rr * s * s + polar.tt * c * c + 2.0 * polar.rt * s * c;
  out.s12 = (polar.rr - polar.tt) * s * c + polar.rt * (c * c - s * s);
  out.s33 = polar.zz;
  return out;
}

Vec2 polar_to_cartesian(double radial, double tangential, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {radial * c - tangential * s, radial * s + tangential * c};
}

Material plane_stress_equivalent(AnalysisType type, const Material& material) {
  switch (type) {
    case AnalysisType::plane_stress: return material;
    case AnalysisType::plane_strain: {
      const double nu = material.poisson_ratio;
      return {material.young_modulus / (1.0 - nu * nu), nu / (1.0 - nu)};
    }
    case AnalysisType::axisymmetric: break;
  }
  throw Error("reference: a plane solution needs plane_strain or plane_stress, not axisymmetric");
}

}  // namespace bemcontact::reference

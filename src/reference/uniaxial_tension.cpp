#include "bemcontact/reference/uniaxial_tension.hpp"

namespace bemcontact::reference {

// Section II.7.1.2.
Vec2 PlateInTension::displacement(const Vec2& x) const {
  const Material m = plane_stress_equivalent(type, material);
  const double strain = applied_stress / m.young_modulus;
  return {-m.poisson_ratio * strain * x.x(), strain * x.y()};
}

Stress PlateInTension::stress(const Vec2& /*x*/) const {
  Stress s;
  s.s22 = applied_stress;
  if (type == AnalysisType::plane_strain) s.s33 = material.poisson_ratio * applied_stress;
  return s;
}

// Section II.7.4.2.
Vec2 CylinderInTension::displacement(double r, double z) const {
  const double strain = applied_stress / material.young_modulus;
  return {-material.poisson_ratio * strain * r, strain * z};
}

Stress CylinderInTension::stress(double /*r*/, double /*z*/) const {
  Stress s;
  s.s22 = applied_stress;
  return s;
}

}  // namespace bemcontact::reference

#pragma once
// Homogeneous uniaxial tension: the plate of section II.7.1 and the solid cylinder of II.7.4.
// Both fields are linear, so linear boundary elements reproduce them to round-off.
#include "bemcontact/core/types.hpp"
#include "bemcontact/reference/stress_state.hpp"

namespace bemcontact::reference {

// Plate under a uniform tension P along x2 (section II.7.1). Frame: any origin, fixed with
// u = 0 and no rotation at the origin. Thesis model: ]-1,1[ x ]0,2[, E = 1e5, nu = 0.1, P = 1,
// p2 = P on x2 = 2, u2 = 0 and p1 = 0 on x2 = 0.
//   plane stress: s22 = P, u1 = -nu P x1 / E, u2 = P x2 / E
//   plane strain: the same with (E, nu) -> (E/(1-nu^2), nu/(1-nu)) and s33 = nu P.
struct PlateInTension {
  double applied_stress = 1.0;  // P (tension positive)
  Material material;
  AnalysisType type = AnalysisType::plane_stress;

  Vec2 displacement(const Vec2& x) const;
  Stress stress(const Vec2& x) const;
};

// Solid cylinder (axis z) under a uniform axial tension P on its ends (section II.7.4),
// axisymmetric (r, z), fixed with u_z = 0 on z = 0:
//   s_zz = P, u_r = -nu P r / E, u_z = P z / E. Thesis: E = 1, nu = 0.25, P = 10, radius 60.
struct CylinderInTension {
  double applied_stress = 1.0;  // P
  Material material;

  Vec2 displacement(double r, double z) const;  // (u_r, u_z)
  Stress stress(double r, double z) const;      // s11 = rr, s22 = zz, s12 = rz, s33 = hoop
};

}  // namespace bemcontact::reference

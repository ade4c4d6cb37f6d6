#pragma once
// Small value types returned by the closed-form solutions of bemcontact::reference.
//
// Sign convention everywhere in this module: tension positive; a traction is p = sigma n
// with n the outward unit normal of the body; a pressure is a compressive normal traction
// (p_n = -pressure).
#include "bemcontact/core/types.hpp"

namespace bemcontact::reference {

// Stress at a point of a 2D or axisymmetric body, in the same layout as bem::StressTensor:
// in-plane components (x1, x2) = (x, y) in plane problems or (r, z) in axisymmetry, and the
// out-of-plane normal stress s33 (sigma_zz in plane strain, 0 in plane stress,
// the hoop stress sigma_theta_theta in axisymmetry). s13 = s23 = 0 in all these problems.
struct Stress {
  double s11 = 0.0, s22 = 0.0, s12 = 0.0, s33 = 0.0;
  Mat2 in_plane() const;
  // p = sigma n for an in-plane unit normal n (components (n1, n2) or (n_r, n_z)).
  Vec2 traction(const Vec2& normal) const;
  // Hencky-von Mises equivalent stress of the full 3D tensor (section II.6).
  double von_mises() const;
};

// Stress in polar components (r, theta) of a plane problem (e_r, e_theta at angle theta
// from the x1 axis), with the out-of-plane normal stress zz.
struct PolarStress {
  double rr = 0.0, tt = 0.0, rt = 0.0, zz = 0.0;
};

// Rotate polar components at polar angle theta (from x1) to Cartesian (x1, x2).
Stress to_cartesian(const PolarStress& polar, double theta);
// Displacement u_r e_r + u_theta e_theta at polar angle theta, in Cartesian components.
Vec2 polar_to_cartesian(double radial, double tangential, double theta);

// In-plane Hooke law of a plane body: plane strain with (E, nu) has the in-plane response of
// plane stress with E' = E / (1 - nu^2), nu' = nu / (1 - nu). Plane stress returns the
// material unchanged. Axisymmetric is not a plane analysis and is rejected (bemcontact::Error).
Material plane_stress_equivalent(AnalysisType type, const Material& material);

}  // namespace bemcontact::reference

#pragma once
// Lamé solutions: thick cylinder (section II.7.5) and thick sphere (section II.7.6) under
// internal and external pressure. Pressures are positive in compression (p_n = -pressure on
// the loaded surface); stresses are tension positive.
#include "bemcontact/core/types.hpp"
#include "bemcontact/reference/stress_state.hpp"

namespace bemcontact::reference {

// Axial condition of the thick cylinder.
enum class CylinderEnds {
  plane_strain,  // e_zz = 0, s_zz = 2 nu A (long tube between fixed walls; 2D plane strain)
  open,          // s_zz = 0, e_zz = -2 nu A / E, u_z = e_zz z (free ends; thesis II.7.5)
  closed,        // s_zz = A (capped tube: end caps carry the pressure), e_zz = (1 - 2nu) A / E
};

// Thick cylinder a <= r <= b, axis z. With A = (p_i a^2 - p_o b^2) / (b^2 - a^2) and
// B = (p_i - p_o) a^2 b^2 / (b^2 - a^2):
//   s_rr = A - B / r^2,  s_tt = A + B / r^2,  s_rz = 0
//   u_r = [ (1 - nu) A r + (1 + nu) B / r ] / E                        (open ends)
//   u_r = (1 + nu) [ (1 - 2 nu) A r + B / r ] / E                      (plane strain)
//   u_r = [ (1 - 2 nu) A r + (1 + nu) B / r ] / E                      (closed ends)
// All three are exact 3D solutions (u_z = e_zz z, fixed at z = 0). Open ends with p_o = 0 is
// the printed (II.7.5.2) with sigma_0 = A: a = 45, b = 90, E = 1, nu = 0.25, p_i = 10 give
// u_r(a) = 862.5, u_r(b) = 600.
// Two views: axisymmetric (r, z) and the plane cross-section (x1, x2) (for a plane-strain
// quarter annulus), where s33 is s_zz.
struct ThickCylinder {
  double inner_radius = 1.0;  // a
  double outer_radius = 2.0;  // b
  double inner_pressure = 0.0;
  double outer_pressure = 0.0;
  Material material;
  CylinderEnds ends = CylinderEnds::open;

  double radial_displacement(double r) const;
  double axial_strain() const;  // e_zz
  PolarStress polar_stress(double r) const;  // rr, tt, rt = 0, zz

  // Axisymmetric view: (u_r, u_z) and s11 = rr, s22 = zz, s12 = rz, s33 = hoop.
  Vec2 axisymmetric_displacement(double r, double z) const;
  Stress axisymmetric_stress(double r, double z) const;
  // Cross-section view: Cartesian (x1, x2), s33 = s_zz.
  Vec2 displacement(const Vec2& x) const;
  Stress stress(const Vec2& x) const;
};

// Stress of the thick sphere in spherical components: radial s_rho_rho and tangential
// s_theta_theta = s_phi_phi.
struct SphericalStress {
  double radial = 0.0, tangential = 0.0;
};

// Thick sphere a <= rho <= b. With A = (p_i a^3 - p_o b^3) / (b^3 - a^3) and
// B = (p_i - p_o) a^3 b^3 / (2 (b^3 - a^3)):
//   s_rho = A - 2 B / rho^3,  s_tt = A + B / rho^3,  u_rho = [ (1 - 2nu) A rho + (1 + nu) B / rho^2 ] / E
// For p_o = 0 this is (II.7.6.2) once the scan's fractions are restored:
//   s_rho = -p a^3 (b^3 - rho^3) / (rho^3 (b^3 - a^3)), s_tt = p a^3 (b^3 + 2 rho^3) / (2 rho^3 (b^3 - a^3)).
// Thesis data a = 1, b = 2, E = 2e5, p = 100 need nu = 0.3 (not the printed 0.25) for
// u(a) = 4.000e-4, u(b) = 1.500e-4; s_tt(a) = 71.43, s_tt(b) = 21.43 (Table II.9).
// Axisymmetric view: centre at the origin, axis z, rho = sqrt(r^2 + z^2).
struct ThickSphere {
  double inner_radius = 1.0;  // a
  double outer_radius = 2.0;  // b
  double inner_pressure = 0.0;
  double outer_pressure = 0.0;
  Material material;

  double radial_displacement(double rho) const;
  SphericalStress spherical_stress(double rho) const;
  Vec2 axisymmetric_displacement(double r, double z) const;  // (u_r, u_z)
  Stress axisymmetric_stress(double r, double z) const;      // rr, zz, rz, hoop
};

}  // namespace bemcontact::reference

#pragma once
// Kirsch: infinite plate with a traction-free circular hole under a remote uniaxial
// tension P (section II.7.3, after Muskhelishvili/Kolosov [INF 4]).
//
// Frame: hole of radius a centred at the origin; polar angle theta measured from the x1
// axis, counter-clockwise. The remote tension acts along the direction at angle
// load_angle from x1; the default pi/2 is the thesis case (tension along x2). With
// phi = theta - load_angle and rho = a / r:
//   s_rr = P/2 (1 - rho^2) + P/2 (1 - 4 rho^2 + 3 rho^4) cos 2phi
//   s_tt = P/2 (1 + rho^2) - P/2 (1 + 3 rho^4) cos 2phi
//   s_rt = -P/2 (1 + 2 rho^2 - 3 rho^4) sin 2phi
//   u_r  = P/(8 mu) [ (kappa - 1) r + 2 a^2/r + (2 r + 2 (kappa + 1) a^2/r - 2 a^4/r^3) cos 2phi ]
//   u_t  = -P/(8 mu) [ 2 r + 2 (kappa - 1) a^2/r + 2 a^4/r^3 ] sin 2phi
// kappa = 3 - 4 nu (plane strain) or (3 - nu)/(1 + nu) (plane stress); s_zz = nu (s_rr + s_tt)
// in plane strain. With the load along x2 (phi = theta - pi/2) these are the formulas printed
// in II.7.3.2 with theta from x1: on the hole s_tt = P (1 + 2 cos 2theta), so s_tt = 3P at
// theta = 0, the point (a, 0) where the hole's tangent is along the load, and s_tt = -P at
// theta = 90 deg. ([thesis.md]: "3P at theta = 90 deg" measures theta from the load axis.)
// The displacement carries no rigid-body motion: for the default load u2 = 0 on x2 = 0 and
// u1 = 0 on x1 = 0, the symmetry conditions of the thesis quarter model. Loading a finite model with traction(x, n) or displacement(x) on its outer
// boundary reproduces the field exactly.
#include "bemcontact/core/types.hpp"
#include "bemcontact/reference/stress_state.hpp"

namespace bemcontact::reference {

struct KirschPlate {
  double hole_radius = 1.0;      // a
  double applied_stress = 1.0;   // P, remote tension
  double load_angle = 1.5707963267948966;  // direction of the tension from x1 (pi/2: along x2)
  Material material;
  AnalysisType type = AnalysisType::plane_stress;

  PolarStress polar_stress(double r, double theta) const;
  Stress stress(const Vec2& x) const;  // Cartesian
  // (u_r, u_theta) at polar coordinates (r, theta).
  Vec2 polar_displacement(double r, double theta) const;
  Vec2 displacement(const Vec2& x) const;  // Cartesian
  Vec2 traction(const Vec2& x, const Vec2& normal) const { return stress(x).traction(normal); }
  double kolosov_constant() const;  // kappa
};

}  // namespace bemcontact::reference

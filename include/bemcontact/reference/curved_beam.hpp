#pragma once
// Curved bar (annular sector a <= r <= b) in pure bending by end couples M per unit
// thickness: [TimoshenkoGoodier1970, §29]. With the stress
// function phi = A ln r + B r^2 ln r + C r^2,
//   s_rr = A/r^2 + B (1 + 2 ln r) + 2C,   s_tt = -A/r^2 + B (3 + 2 ln r) + 2C,   s_rt = 0,
//   A = -4M/N a^2 b^2 ln(b/a),   B = -2M/N (b^2 - a^2),
//   C = M/N [b^2 - a^2 + 2 (b^2 ln b - a^2 ln a)],   N = (b^2 - a^2)^2 - 4 a^2 b^2 ln^2(b/a),
// so that s_rr = 0 on both arcs, the end sections carry no force (int s_tt dr = 0) and the
// moment int_a^b s_tt r dr = -M (M > 0 opens the bar: s_tt > 0 on the inner arc).
// Displacements (plane stress; plane strain through plane_stress_equivalent), without
// rigid motion:
//   u_r = [-(1 + nu) A/r + 2 (1 - nu) B r ln r - (1 + nu) B r + 2 (1 - nu) C r] / E
//   u_t = 4 B r theta / E
// Checked in tests/unit/reference against equilibrium, Hooke's law, the free arcs and the
// end resultants.
#include "bemcontact/core/types.hpp"
#include "bemcontact/reference/stress_state.hpp"

namespace bemcontact::reference {

struct CurvedBeamEndCouple {
  double inner_radius = 1.0;  // a
  double outer_radius = 2.0;  // b
  double moment = 1.0;        // M per unit thickness
  Material material;
  AnalysisType type = AnalysisType::plane_stress;

  PolarStress polar_stress(double r) const;  // the same at every theta
  Stress stress(const Vec2& x) const;        // Cartesian; centre at the origin
  // (u_r, u_theta) at polar coordinates (r, theta), theta from the x1 axis.
  Vec2 polar_displacement(double r, double theta) const;
  Vec2 displacement(const Vec2& x) const;  // Cartesian
  Vec2 traction(const Vec2& x, const Vec2& normal) const { return stress(x).traction(normal); }
};

}  // namespace bemcontact::reference

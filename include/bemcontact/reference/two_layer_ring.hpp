#pragma once
// Two bonded layers a <= r <= c (inner material) and c <= r <= b (outer material) of a
// thick ring or tube under internal pressure p_i and external pressure p_o, in plane strain
// or plane stress (the compound cylinder; Timoshenko, Strength of Materials II, §2.7).
// In each layer u_r = A_k r + B_k / r and, with the plane-stress-equivalent moduli
// (E', nu') of reference::plane_stress_equivalent,
//   s_rr = E'/(1 - nu'^2) [ (1 + nu') A_k - (1 - nu') B_k / r^2 ],
//   s_tt = E'/(1 - nu'^2) [ (1 + nu') A_k + (1 - nu') B_k / r^2 ].
// The four constants follow from s_rr(a) = -p_i, s_rr(b) = -p_o and the continuity of u_r
// and s_rr at r = c. s_zz = nu (s_rr + s_tt) in plane strain, 0 in plane stress. The field
// is not piecewise linear, so a decomposed BEM model meets it only to discretisation error.
#include "bemcontact/core/types.hpp"
#include "bemcontact/reference/stress_state.hpp"

namespace bemcontact::reference {

struct TwoLayerRing {
  double inner_radius = 1.0;      // a
  double interface_radius = 1.5;  // c
  double outer_radius = 2.0;      // b
  double inner_pressure = 0.0;
  double outer_pressure = 0.0;
  Material inner, outer;
  AnalysisType type = AnalysisType::plane_strain;

  // (A, B) of the layer holding radius r.
  std::array<double, 2> constants(double r) const;
  double radial_displacement(double r) const;
  PolarStress polar_stress(double r) const;
  Vec2 displacement(const Vec2& x) const;  // Cartesian
  Stress stress(const Vec2& x) const;      // Cartesian, s33 = s_zz
};

}  // namespace bemcontact::reference

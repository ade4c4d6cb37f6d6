#pragma once
// Cantilever with a parabolic end shear (section II.7.2, Batoz' example [MEC 1]).
//
// Geometry and frame: the beam occupies 0 < x1 < L, -H/2 < x2 < H/2; O = (0, 0) is the
// middle of the end x1 = 0, A = (L, 0), B = (L, H/2), C = (0, H/2). The edges x2 = +-H/2 are
// free. With q the shear stress on the axis (the thesis takes q = 1):
//   s11 = 8 q x2 (x1 - L) / H^2,  s12 = q (1 - (2 x2 / H)^2),  s22 = 0
//   u1  = 4q/(E H^2) [ x2 (x1^2 - 2 L x1) + (2 + nu) x2 (H^2/4 - x2^2) / 3 ]
//   u2  = 4q/(E H^2) [ L x1^2 - x1^3 / 3 - nu x2^2 (x1 - L) + (4 + 5 nu) x1 H^2 / 12 ]
// (plane stress; plane strain replaces (E, nu) by (E/(1-nu^2), nu/(1-nu)), s33 = nu s11).
// Tractions p = sigma n: on x1 = L, p = (0, q (1 - (2x2/H)^2)); on x1 = 0,
// p = (8 q L x2 / H^2, -q (1 - (2x2/H)^2)), as printed in II.7.2.1.
// The field fixes u1 = u2 = 0 at O and u1 = 0 at C.
//
// Half model 0 < x2 < H/2: u1 is odd and u2 even in x2, so on the axis OA the symmetry
// condition is u1 = 0, p2 = 0 (the printed "u2 = 0, p1 = 0" contradicts the field).
// Thesis data: E = 100, nu = 0.3, L = H = 100: u1(B) = -2, u2(B) = 4.5, s11(C) = -4, and
// s12 = 1 on the axis (the column "sigma11 en O" of Table II.4).
#include "bemcontact/core/types.hpp"
#include "bemcontact/reference/stress_state.hpp"

namespace bemcontact::reference {

struct CantileverParabolicShear {
  double length = 100.0;      // L
  double height = 100.0;      // H (full height)
  double axis_shear = 1.0;    // q = s12 on x2 = 0
  Material material;
  AnalysisType type = AnalysisType::plane_stress;

  Vec2 displacement(const Vec2& x) const;
  Stress stress(const Vec2& x) const;
  // Resultant of the end shear, per unit thickness: 2 q H / 3.
  double end_shear_force() const { return 2.0 * axis_shear * height / 3.0; }
};

}  // namespace bemcontact::reference

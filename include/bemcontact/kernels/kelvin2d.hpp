#pragma once
// Kelvin fundamental solutions of plane strain (Annex A, 2D), as pure functions.
// Plane stress uses the same kernels with nu replaced by nu/(1+nu) (section II.3.1);
// see kernel_poisson_ratio().
//
// Conventions (x = source point, y = field point, r_i = y_i - x_i, r = |y - x|,
// n = outward normal at y):
//   U(x,y)(k,i): displacement u_i at y due to a unit force along k at x
//       U_ki = [ (3-4nu) ln(1/r) delta_ki + r_,k r_,i ] / (8 pi mu (1-nu))
//   T(x,y,n)(k,i): traction p_i = sigma_ij n_j at y of that displacement field
//       T_ki = -[ dr/dn ((1-2nu) delta_ki + 2 r_,k r_,i) - (1-2nu)(r_,k n_i - r_,i n_k) ]
//              / (4 pi (1-nu) r)
//   D(x,y)[k](i,j): stress sigma_ij at the interior point x due to the traction density
//       p_k on the boundary, so that sigma_ij(x) = int D_kij p_k - int S_kij u_k  (I.14)
//   S(x,y,n)[k](i,j): the same for the displacement density.
// Boundary integral equation: c u(x) + int T u dGamma = int U p dGamma.
#include <array>

#include "bemcontact/core/types.hpp"

namespace bemcontact::kernels {

struct KelvinPlane {
  double shear_modulus = 1.0;  // mu
  double poisson_ratio = 0.0;  // nu (already nu/(1+nu) for plane stress)
  static KelvinPlane from(AnalysisType type, const Material& material) {
    return {material.shear_modulus(), kernel_poisson_ratio(type, material)};
  }
};

using StressKernel = std::array<Mat2, 2>;  // [k](i, j)

Mat2 kelvin_displacement(const KelvinPlane& c, const Vec2& source, const Vec2& field);
Mat2 kelvin_traction(const KelvinPlane& c, const Vec2& source, const Vec2& field,
                     const Vec2& normal);
StressKernel kelvin_stress_from_traction(const KelvinPlane& c, const Vec2& source,
                                         const Vec2& field);  // D
StressKernel kelvin_stress_from_displacement(const KelvinPlane& c, const Vec2& source,
                                             const Vec2& field, const Vec2& normal);  // S

}  // namespace bemcontact::kernels

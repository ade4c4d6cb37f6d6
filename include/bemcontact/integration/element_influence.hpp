#pragma once
// Influence of one boundary element on one source point: the integrals over the element
// of the fundamental solutions times the element's shape functions. Shared by the plane
// (analytic, Annex C) and axisymmetric (Gauss, section II.4.4.1) integrators.
#include <array>

#include "bemcontact/core/types.hpp"
#include "bemcontact/kernels/kelvin2d.hpp"

namespace bemcontact::integration {

// For element node a (a < node_count):
//   G[a] = int_element U(x, y) N_a(y) dGamma(y)
//   H[a] = int_element T(x, y) N_a(y) dGamma(y)
// When the source x coincides with node a of the element (source_node = a), H[a] is not
// computed and is returned as zero: the caller builds the diagonal block from rigid-body
// motion (section I.4.2, remark). G[a] is then the weakly singular integral, exact.
inline constexpr int kMaxInfluenceNodes = 3;  // = geometry::kMaxElementNodes

struct ElementInfluence {
  std::array<Mat2, kMaxInfluenceNodes> G{Mat2::Zero(), Mat2::Zero(), Mat2::Zero()};
  std::array<Mat2, kMaxInfluenceNodes> H{Mat2::Zero(), Mat2::Zero(), Mat2::Zero()};
};

// For an interior point x (not on the element):
//   D[a] = int D(x, y) N_a dGamma,  S[a] = int S(x, y, n) N_a dGamma
// so sigma_ij(x) = sum_a D[a][k](i,j) p_k(node a) - S[a][k](i,j) u_k(node a).
struct ElementStressInfluence {
  std::array<kernels::StressKernel, kMaxInfluenceNodes> D{};
  std::array<kernels::StressKernel, kMaxInfluenceNodes> S{};
};

}  // namespace bemcontact::integration

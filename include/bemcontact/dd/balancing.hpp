#pragma once
// Balancing Neumann-Neumann preconditioner (Mandel 1993; Toselli and Widlund, ch. 6) for the
// conforming interface problem K u = F, K = sum_s R_s^T K_s R_s (K_s: subdomain s's
// Dirichlet-to-Neumann map on its interface nodes, formed explicitly).
//
//   M^-1 = Q + (I - Q K) [sum_s R_s^T D_s K_s^+ D_s R_s] (I - K Q),   Q = W (W^T K W)^-1 W^T
//
// D_s: partition of unity weighted by the diagonal stiffness of K_s at each interface dof
// (a soft subdomain takes little of a shared residual: the thin-layer joint). W: the
// rigid-body modes of every subdomain's interface (plane: two translations and the
// rotation; axisymmetric: the axial translation), weighted by D_s, with dependent columns
// dropped. The coarse correction makes the residual seen by the local solves orthogonal to
// every D_s Z_s, so the Neumann problem of a floating subdomain (K_s singular on its rigid
// modes) is consistent; K_s^+ solves it with the null modes fixed by Lagrange multipliers.
// The coarse problem carries information across all subdomains in one step, so the
// iteration count stays nearly flat as subdomains are added.
#include <vector>

#include "bemcontact/core/types.hpp"
#include "bemcontact/dd/interface.hpp"
#include "bemcontact/operators/dense_lu.hpp"
#include "bemcontact/operators/linear_operator.hpp"

namespace bemcontact::dd {

class InterfaceOperator;

class BalancingPreconditioner : public operators::LinearOperator {
 public:
  // K must hold explicit interface maps (conforming method).
  BalancingPreconditioner(const InterfaceOperator& K, const Connectivity& connectivity, AnalysisType analysis);

  Index rows() const override { return unknowns_; }
  Index cols() const override { return unknowns_; }
  void apply(const Vector& r, Vector& z) const override;

  Index coarse_dimension() const { return static_cast<Index>(coarse_basis_.cols()); }
  const Matrix& coarse_basis() const { return coarse_basis_; }
  // Per subdomain: how many rigid modes leave its interface map singular (0 when held).
  const std::vector<int>& floating_modes() const { return floating_modes_; }

 private:
  struct Local {
    std::vector<Index> dofs;              // global unknown of each local dof (R_s)
    Vector weights;                       // D_s
    Index null_modes = 0;                 // Lagrange multipliers after the k dofs
    operators::DenseLU neumann;           // [K_s Z; Z^T 0] or K_s
  };
  // The construction's phases, in order.
  Vector gather_locals(const Connectivity& connectivity, AnalysisType analysis, std::vector<Matrix>& local_operators,
                       std::vector<Matrix>& modes);
  void weight_partition_of_unity(const Vector& diagonal_sum);
  void build_coarse_space(const std::vector<Matrix>& modes);
  void factor_neumann_problems(const std::vector<Matrix>& local_operators, const std::vector<Matrix>& modes);
  void share_floating_modes();

  const InterfaceOperator& K_;
  Index unknowns_ = 0;
  std::vector<Local> locals_;
  std::vector<int> floating_modes_;
  Matrix coarse_basis_;  // W (orthonormal columns)
  Matrix coarse_image_;  // K W
  operators::DenseLU coarse_;
};

}  // namespace bemcontact::dd

#include "bemcontact/dd/balancing.hpp"

#include <cmath>

#include "bemcontact/core/error.hpp"
#include "bemcontact/dd/interface_operator.hpp"
#include "bemcontact/operators/dense_subspaces.hpp"

namespace bemcontact::dd {

namespace {

// A rigid mode is a null mode of K_s when K_s moves it by less than this fraction of K_s's
// RMS singular value. Free subdomains' rotations measure 1e-9..1e-7 (quadrature only: the
// linear elements carry rigid motions exactly); a held subdomain's weakest mode 1e-3 and
// more (its interface is at least one element of a body whose size is at most 10^3
// elements).
constexpr double kNullModeFraction = 1e-5;

// The rigid modes of the interface dofs of one subdomain, orthonormal columns.
Matrix interface_rigid_modes(const std::vector<Vec2>& positions, AnalysisType analysis) {
  const Index k = static_cast<Index>(positions.size());
  if (analysis == AnalysisType::axisymmetric) {  // only the axial translation is rigid
    Matrix z = Matrix::Zero(2 * k, 1);
    for (Index i = 0; i < k; ++i) z(2 * i + 1, 0) = 1.0;
    return z / std::sqrt(static_cast<double>(k));
  }
  Vec2 centre = Vec2::Zero();
  for (const auto& p : positions) centre += p;
  centre /= static_cast<double>(k);
  Matrix z = Matrix::Zero(2 * k, 3);
  for (Index i = 0; i < k; ++i) {
    const Vec2 d = positions[i] - centre;
    z(2 * i, 0) = 1.0;
    z(2 * i + 1, 1) = 1.0;
    z(2 * i, 2) = -d.y();
    z(2 * i + 1, 2) = d.x();
  }
  return operators::column_space(z, 1e-12);  // (on one point the rotation vanishes)
}

}  // namespace

BalancingPreconditioner::BalancingPreconditioner(const InterfaceOperator& K, const Connectivity& connectivity,
                                                 AnalysisType analysis)
    : K_(K), unknowns_(connectivity.unknowns) {
  // Each process builds the local parts of the subdomains it owns; the sums over processes
  // (diagonals, coarse basis, products with K) make the rest identical everywhere.
  const std::size_t count = K.subdomain_count();
  locals_.resize(count);
  floating_modes_.assign(count, 0);
  std::vector<Matrix> local_operators(count), modes(count);
  const Vector diagonal_sum = gather_locals(connectivity, analysis, local_operators, modes);
  weight_partition_of_unity(diagonal_sum);
  build_coarse_space(modes);
  factor_neumann_problems(local_operators, modes);
  share_floating_modes();
}

// R_s and Z_s of every subdomain, and K_s with |diag K_s| as the weights of those owned;
// returns the weights' sum at each dof (over all processes).
Vector BalancingPreconditioner::gather_locals(const Connectivity& connectivity, AnalysisType analysis,
                                              std::vector<Matrix>& local_operators, std::vector<Matrix>& modes) {
  const Distribution& distribution = K_.distribution();
  Vector diagonal_sum = Vector::Zero(unknowns_);
  for (std::size_t s = 0; s < locals_.size(); ++s) {
    auto& local = locals_[s];
    const auto& slots = connectivity.slots[s];
    std::vector<Vec2> positions;
    for (const auto& slot : slots) {
      const Index i = connectivity.unknown_of(slot);
      local.dofs.push_back(i);
      local.dofs.push_back(i + 1);
      positions.push_back(connectivity.interfaces[slot.interface].pairs[slot.pair].position);
      if (connectivity.interfaces[slot.interface].pairs[slot.pair].kind != bem::ConditionKind::displacement)
        throw Error("BalancingPreconditioner: the conforming method's unknowns are displacements");
    }
    if (slots.empty()) continue;
    modes[s] = interface_rigid_modes(positions, analysis);
    if (!distribution.owns(s)) continue;
    local_operators[s] = K_.local_operator(s);
    local.weights = local_operators[s].diagonal().cwiseAbs();  // divided by the sums below
    for (std::size_t a = 0; a < local.dofs.size(); ++a)
      diagonal_sum[local.dofs[a]] += local.weights[static_cast<Index>(a)];
  }
  distribution.sum(diagonal_sum);
  return diagonal_sum;
}

// D_s: stiffness-weighted partition of unity (every dof is shared by exactly two subdomains).
void BalancingPreconditioner::weight_partition_of_unity(const Vector& diagonal_sum) {
  const Distribution& distribution = K_.distribution();
  for (std::size_t s = 0; s < locals_.size(); ++s) {
    auto& local = locals_[s];
    const Index k = static_cast<Index>(local.dofs.size());
    if (k == 0 || !distribution.owns(s)) continue;
    for (Index a = 0; a < k; ++a) {
      const double total = diagonal_sum[local.dofs[static_cast<std::size_t>(a)]];
      local.weights[a] = total > 0.0 ? local.weights[a] / total : 0.5;
    }
  }
}

// Coarse space: D_s Z_s of every subdomain, an orthonormal basis of their span, its image
// under K and the coarse problem's factors.
void BalancingPreconditioner::build_coarse_space(const std::vector<Matrix>& modes) {
  const Distribution& distribution = K_.distribution();
  Index columns = 0;
  for (const auto& z : modes) columns += z.cols();
  Matrix W = Matrix::Zero(unknowns_, columns);
  Index column = 0;
  for (std::size_t s = 0; s < locals_.size(); ++s) {
    const auto& local = locals_[s];
    for (Index c = 0; c < modes[s].cols(); ++c, ++column)
      if (distribution.owns(s))
        for (std::size_t a = 0; a < local.dofs.size(); ++a)
          W(local.dofs[a], column) += local.weights[static_cast<Index>(a)] * modes[s](static_cast<Index>(a), c);
  }
  distribution.sum(W);
  distribution.broadcast_from_root(W);  // the same rank and basis on every process
  if (columns == 0) return;
  coarse_basis_ = operators::column_space(W, 1e-10);
  const Index rank = coarse_basis_.cols();
  coarse_image_.resize(unknowns_, rank);
  Vector image;
  for (Index c = 0; c < rank; ++c) {
    K_.apply(coarse_basis_.col(c), image);
    coarse_image_.col(c) = image;
  }
  if (rank > 0)
    coarse_ = operators::DenseLU(coarse_basis_.transpose() * coarse_image_,
                                 "the balancing preconditioner's coarse problem (the subdomains' rigid motions, " +
                                     std::to_string(rank) + " modes; a motion of the whole body held by nothing)",
                                 1e-14);
}

// Local Neumann problems, singular on a floating subdomain's rigid modes: the null modes
// fixed by Lagrange multipliers.
void BalancingPreconditioner::factor_neumann_problems(const std::vector<Matrix>& local_operators,
                                                      const std::vector<Matrix>& modes) {
  const Distribution& distribution = K_.distribution();
  for (std::size_t s = 0; s < locals_.size(); ++s) {
    auto& local = locals_[s];
    const Index k = static_cast<Index>(local.dofs.size());
    if (k == 0 || !distribution.owns(s)) continue;
    const Matrix& Ks = local_operators[s];
    const double rms = Ks.norm() / std::sqrt(static_cast<double>(k));
    const auto svd = operators::right_singular_vectors(Ks * modes[s]);
    std::vector<Index> null_columns;
    for (Index j = 0; j < svd.values.size(); ++j)
      if (svd.values[j] < kNullModeFraction * rms) null_columns.push_back(j);
    const Index m = static_cast<Index>(null_columns.size());
    floating_modes_[s] = static_cast<int>(m);
    local.null_modes = m;
    Matrix system = Matrix::Zero(k + m, k + m);
    system.topLeftCorner(k, k) = Ks;
    for (Index j = 0; j < m; ++j) {
      const Vector z = modes[s] * svd.V.col(null_columns[static_cast<std::size_t>(j)]);
      system.block(0, k + j, k, 1) = rms * z;
      system.block(k + j, 0, 1, k) = rms * z.transpose();
    }
    local.neumann = operators::DenseLU(std::move(system),
                                       "the balancing preconditioner's Neumann problem of subdomain " +
                                           std::to_string(s + 1) + " (singular beyond its rigid motions)",
                                       1e-14);
  }
}

// Every process's count of floating modes for the subdomains it owns, to all.
void BalancingPreconditioner::share_floating_modes() {
  const std::size_t count = floating_modes_.size();
  Vector floating(static_cast<Index>(count));
  for (std::size_t s = 0; s < count; ++s) floating[static_cast<Index>(s)] = floating_modes_[s];
  K_.distribution().sum(floating);
  for (std::size_t s = 0; s < count; ++s) floating_modes_[s] = static_cast<int>(floating[static_cast<Index>(s)]);
}

void BalancingPreconditioner::apply(const Vector& r, Vector& z) const {
  if (r.size() != unknowns_) throw Error("BalancingPreconditioner: wrong number of interface unknowns");
  // Coarse part Q r, and the residual it leaves, balanced: W^T (r - K Q r) = 0.
  Vector balanced = r;
  z = Vector::Zero(unknowns_);
  if (coarse_basis_.cols() > 0) {
    const Vector lambda = coarse_.solve(coarse_basis_.transpose() * r);
    z = coarse_basis_ * lambda;
    balanced -= coarse_image_ * lambda;
  }
  // Weighted local Neumann solves.
  Vector local_sum = Vector::Zero(unknowns_);
  for (const auto& local : locals_) {
    const Index k = static_cast<Index>(local.dofs.size());
    if (k == 0 || local.weights.size() == 0) continue;  // not owned here
    Vector rhs = Vector::Zero(k + local.null_modes);
    for (Index a = 0; a < k; ++a) rhs[a] = local.weights[a] * balanced[local.dofs[static_cast<std::size_t>(a)]];
    const Vector x = local.neumann.solve(rhs);
    for (Index a = 0; a < k; ++a) local_sum[local.dofs[static_cast<std::size_t>(a)]] += local.weights[a] * x[a];
  }
  K_.distribution().sum(local_sum);
  // (I - Q K) on the local part keeps the coarse component exact.
  if (coarse_basis_.cols() > 0) {
    Vector image;
    K_.apply(local_sum, image);
    local_sum -= coarse_basis_ * coarse_.solve(coarse_basis_.transpose() * image);
  }
  z += local_sum;
}

}  // namespace bemcontact::dd

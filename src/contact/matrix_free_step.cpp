// The Newton system of the matrix-free route (condensed.hpp, MatrixFreeCondensed): the
// frictionless pairs in contact A and the motions,
//   [M_AA  b_A    ] [lambda_A]   [d_A - w0_A]
//   [f_A   f_delta] [delta   ] = [target    ],
// solved without forming M: lambda_A = y - Y delta with M_AA y = d_A - w0_A and M_AA Y = b_A
// (K + 1 GMRES solves, each product one solve of every region's factors), then the K x K
// Schur complement for delta.
//
// Preconditioner: two-level additive Schwarz for a first-kind operator ([TranStephan1996]:
// hat functions on a coarse grid of the pairs plus a local scaling; its condition number
// grows with H / h, the coarse spacing over the pairs', not with their number):
//   z = P_A M_c^-1 P_A^T r + (s D_A)^-1 (r - (M P)_A M_c^-1 P_A^T r),
// M_c = P_A^T (M P)_A the coarse operator on the pairs in contact, (M P) formed once per model
// (one batched solve per coarse function), D the pairs' weights and s M's normal block on the
// highest frequency per unit weight: s w_i estimates M_ii (the local part of a first-kind
// operator of order -1 scales with the pair's size).
#include <algorithm>
#include <cmath>

#include "bemcontact/contact/step_solvers.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/gmres.hpp"

namespace bemcontact::contact {
namespace {

// Pairs per coarse hat function: the preconditioned condition number grows with it, the
// coarse image's memory (N x N / spacing) and its share of every iteration fall with it.
// Rigid cylinder, 8 001 pairs (model + contact iterations): 4: 18.3 + 4.8 s (61 products);
// 8: 10.8 + 4.0 s (94); 16: 10.6 + 13.3 s (275, 6 Newton iterations: a coarser start).
constexpr Index kCoarseSpacing = 8;

// The normal rows of a 2N-vector, and a pair vector spread on the normal dofs.
Vector normal_rows(const Vector& v) { return Eigen::Map<const Vector, 0, Eigen::InnerStride<2>>(v.data(), v.size() / 2); }
Vector on_normal_dofs(const Vector& v) {
  Vector out = Vector::Zero(2 * v.size());
  Eigen::Map<Vector, 0, Eigen::InnerStride<2>>(out.data(), v.size()) = v;
  return out;
}

// M_AA: the normal jumps at the pairs A for pressures at A.
class ActiveBlock : public operators::LinearOperator {
 public:
  ActiveBlock(const CondensedOperator& M, const std::vector<Index>& active, Index pairs)
      : M_(M), active_(active), pairs_(pairs) {}
  Index rows() const override { return static_cast<Index>(active_.size()); }
  Index cols() const override { return rows(); }
  void apply(const Vector& x, Vector& y) const override {
    Vector full = Vector::Zero(2 * pairs_);
    for (std::size_t a = 0; a < active_.size(); ++a) full[2 * active_[a]] = x[static_cast<Index>(a)];
    Vector w;
    M_.apply(full, w);
    y.resize(rows());
    for (std::size_t a = 0; a < active_.size(); ++a) y[static_cast<Index>(a)] = w[2 * active_[a]];
  }

 private:
  const CondensedOperator& M_;
  const std::vector<Index>& active_;
  Index pairs_;
};

// The two-level preconditioner of the header on the pairs A.
class TwoLevel : public operators::LinearOperator {
 public:
  TwoLevel(const MatrixFreeCondensed& data, const std::vector<Index>& active) : data_(data), active_(active) {
    const auto& P = data.coarse_basis;
    const Index nc = P.cols();
    // The coarse functions that keep at least half their mass on A (one cut to a sliver
    // at the zone's edge would make M_c nearly singular).
    std::vector<char> in_active(static_cast<std::size_t>(P.rows()), 0);
    for (const Index i : active) in_active[static_cast<std::size_t>(i)] = 1;
    std::vector<double> kept_mass(static_cast<std::size_t>(nc), 0.0), mass(static_cast<std::size_t>(nc), 0.0);
    for (Index k = 0; k < nc; ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(P, k); it; ++it) {
        mass[static_cast<std::size_t>(k)] += it.value();
        if (in_active[static_cast<std::size_t>(it.row())]) kept_mass[static_cast<std::size_t>(k)] += it.value();
      }
    position_.assign(static_cast<std::size_t>(P.rows()), -1);
    for (std::size_t a = 0; a < active.size(); ++a) position_[static_cast<std::size_t>(active[a])] = static_cast<Index>(a);
    for (Index k = 0; k < nc; ++k)
      if (kept_mass[static_cast<std::size_t>(k)] >= 0.5 * mass[static_cast<std::size_t>(k)]) columns_.push_back(k);
    const Index c = static_cast<Index>(columns_.size());
    if (c == 0) return;
    Matrix Mc = Matrix::Zero(c, c);
    for (Index l = 0; l < c; ++l)
      for (Eigen::SparseMatrix<double>::InnerIterator it(P, columns_[static_cast<std::size_t>(l)]); it; ++it) {
        if (!in_active[static_cast<std::size_t>(it.row())]) continue;
        for (Index k = 0; k < c; ++k) Mc(l, k) += it.value() * data.coarse_image(it.row(), columns_[static_cast<std::size_t>(k)]);
      }
    coarse_ = Eigen::PartialPivLU<Matrix>(Mc);
  }
  Index rows() const override { return static_cast<Index>(active_.size()); }
  Index cols() const override { return rows(); }
  void apply(const Vector& r, Vector& z) const override {
    const auto& P = data_.coarse_basis;
    const Index c = static_cast<Index>(columns_.size());
    Vector rc = Vector::Zero(c);
    for (Index l = 0; l < c; ++l)
      for (Eigen::SparseMatrix<double>::InnerIterator it(P, columns_[static_cast<std::size_t>(l)]); it; ++it)
        if (position_[static_cast<std::size_t>(it.row())] >= 0) rc[l] += it.value() * r[position_[static_cast<std::size_t>(it.row())]];
    const Vector e = c > 0 ? Vector(coarse_.solve(rc)) : Vector();
    Vector e_all = Vector::Zero(P.cols());
    for (Index l = 0; l < c; ++l) e_all[columns_[static_cast<std::size_t>(l)]] = e[l];
    const Vector image_e = data_.coarse_image * e_all;  // (M P) e at every pair: one matrix-vector product
    z.resize(rows());
    for (std::size_t a = 0; a < active_.size(); ++a) {
      const Index i = active_[a];
      const double local = data_.fine_scale * data_.weight[i];  // M_ii's estimate
      z[static_cast<Index>(a)] = local != 0.0 ? (r[static_cast<Index>(a)] - image_e[i]) / local : 0.0;
    }
    for (Index l = 0; l < c; ++l)
      for (Eigen::SparseMatrix<double>::InnerIterator it(P, columns_[static_cast<std::size_t>(l)]); it; ++it)
        if (position_[static_cast<std::size_t>(it.row())] >= 0) z[position_[static_cast<std::size_t>(it.row())]] += it.value() * e[l];
  }

 private:
  const MatrixFreeCondensed& data_;
  const std::vector<Index>& active_;
  std::vector<Index> position_;  // per pair: its place in A, or -1
  std::vector<Index> columns_;   // the coarse functions kept
  Eigen::PartialPivLU<Matrix> coarse_;
};

}  // namespace

MatrixFreeCondensed prepare_matrix_free(std::shared_ptr<const CondensedOperator> M, Vector weight,
                                        const std::vector<Index>& groups) {
  MatrixFreeCondensed data;
  const Index n = weight.size();
  // Hat functions over each contact's pairs, every kCoarseSpacing pairs (its ends included).
  std::vector<Eigen::Triplet<double>> hats, spread;
  Index column = 0;
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    const Index first = groups[g], count = groups[g + 1] - groups[g];
    if (count == 0) continue;
    const Index functions = count < 2 ? 1 : std::max<Index>(2, (count - 1 + kCoarseSpacing - 1) / kCoarseSpacing + 1);
    for (Index i = 0; i < count; ++i) {
      if (functions == 1) {
        hats.emplace_back(first + i, column, 1.0);
        continue;
      }
      const double t = static_cast<double>(i) * static_cast<double>(functions - 1) / static_cast<double>(count - 1);
      const Index k = std::min<Index>(static_cast<Index>(t), functions - 2);
      const double a = t - static_cast<double>(k);
      if (1.0 - a > 0.0) hats.emplace_back(first + i, column + k, 1.0 - a);
      if (a > 0.0) hats.emplace_back(first + i, column + k + 1, a);
    }
    column += functions;
  }
  data.coarse_basis.resize(n, column);
  data.coarse_basis.setFromTriplets(hats.begin(), hats.end());
  for (const auto& h : hats) spread.emplace_back(2 * h.row(), h.col(), h.value());
  Eigen::SparseMatrix<double> on_dofs(2 * n, column);
  on_dofs.setFromTriplets(spread.begin(), spread.end());
  const Matrix image = M->apply_columns(on_dofs);
  data.coarse_image.resize(n, column);
  for (Index i = 0; i < n; ++i) data.coarse_image.row(i) = image.row(2 * i);
  // M's normal block on the highest frequency (alternating signs along each contact) per
  // unit weight, sigma with M_ii ~ sigma w_i: the Rayleigh quotient of D^-1/2 M D^-1/2.
  Vector alternating = Vector::Zero(n);
  for (std::size_t g = 0; g + 1 < groups.size(); ++g)
    for (Index i = groups[g]; i < groups[g + 1]; ++i)
      if (weight[i] > 0.0) alternating[i] = ((i - groups[g]) % 2 == 0 ? 1.0 : -1.0) / std::sqrt(weight[i]);
  Vector w;
  M->apply(on_normal_dofs(alternating), w);
  const double scale = alternating.dot(normal_rows(w)) / std::max(static_cast<double>(n), 1.0);
  data.fine_scale = scale != 0.0 && std::isfinite(scale) ? scale : 1.0;
  data.weight = std::move(weight);
  data.M = std::move(M);
  return data;
}

bool solve_matrix_free_system(const CondensedProblem& p, const std::vector<Index>& free_dofs, const Vector& rhs,
                              double gap_goal, const Vector& delta_guess, NewtonSystemCache& cache, Vector& z,
                              std::string& failure) {
  const auto& data = *p.matrix_free;
  const Index n = p.pairs, K = p.motions;
  std::vector<Index> active;
  for (const Index dof : free_dofs) {
    if (dof % 2 != 0) throw std::logic_error("solve_matrix_free_system: a tangential unknown (the route is frictionless)");
    active.push_back(dof / 2);
  }
  const Index m = static_cast<Index>(active.size());
  if (cache.krylov_start.rows() != n || cache.krylov_start.cols() != K + 1) cache.krylov_start = Matrix::Zero(n, K + 1);
  // Right-hand sides: the gaps' rows, then b_A's columns.
  Matrix B(m, K + 1), Y(m, K + 1);
  for (Index a = 0; a < m; ++a) {
    B(a, 0) = rhs[a];
    for (Index k = 0; k < K; ++k) B(a, k + 1) = p.b(2 * active[static_cast<std::size_t>(a)], k);
  }
  if (m > 0) {
    const ActiveBlock block(*data.M, active, n);
    const TwoLevel preconditioner(data, active);
    operators::GmresOptions options;
    options.restart = 300;
    options.max_iterations = 3000;
    for (Index j = 0; j <= K; ++j) {
      const Vector b = B.col(j);
      Vector x0(m);
      for (Index a = 0; a < m; ++a) x0[a] = cache.krylov_start(active[static_cast<std::size_t>(a)], j);
      // The gaps' residual within gap_goal; b's columns within it over the motion they are
      // multiplied by (when it is not known yet, to the floor). GMRES's tolerance is relative
      // to its first residual, which a warm start makes small.
      Vector r0;
      block.apply(x0, r0);
      const double motion = j > 0 && delta_guess.size() == K ? std::abs(delta_guess[j - 1]) : 0.0;
      // (Not below 1e-15 of |b|: GMRES's round-off floor on this operator.)
      const double goal = std::max(j == 0 ? gap_goal : motion > 0.0 ? gap_goal / motion : 0.0, 1e-15 * b.norm());
      const double first = (b - r0).norm();
      ++cache.krylov_iterations;  // the product above
      if (first <= goal) {
        Y.col(j) = x0;
        continue;
      }
      options.tolerance = goal / first;
      const auto result = operators::gmres(block, b, options, x0, {}, &preconditioner);
      cache.krylov_iterations += result.iterations;
      // Stopped short of the goal at round-off (an invariant space, a stagnation) but within
      // 1e-12 of |b|: taken; the step's residual judges it.
      if (!result.converged() && result.relative_residual * first > 1e-12 * b.norm()) {
        failure = "GMRES on the " + std::to_string(m) + " pairs in contact: " + result.message;
        return false;
      }
      Y.col(j) = result.x;
    }
  }
  for (Index a = 0; a < m; ++a) cache.krylov_start.row(active[static_cast<std::size_t>(a)]) = Y.row(a);
  // delta from the Schur complement (f_delta - f_A Y_b) delta = target - f_A y.
  Vector delta;
  if (K > 0) {
    Matrix fA(K, m);
    for (Index a = 0; a < m; ++a) fA.col(a) = p.f.col(2 * active[static_cast<std::size_t>(a)]);
    const Matrix S = p.f_delta - fA * Y.rightCols(K);
    const Vector t = rhs.tail(K) - fA * Y.col(0);
    Eigen::FullPivLU<Matrix> lu(S);
    if (!lu.isInvertible()) {
      failure = "no pair in contact carries the force loads";
      return false;
    }
    delta = lu.solve(t);
  }
  z.resize(m + K);
  z.head(m) = Y.col(0);
  if (K > 0) {
    z.head(m) -= Y.rightCols(K) * delta;
    z.tail(K) = delta;
  }
  return z.allFinite();
}

void coarse_start(const StepInput& in, const SolverOptions& options, Vector& x, Vector& delta) {
  const auto& p = *in.problem;
  const auto& data = *p.matrix_free;
  const auto& P = data.coarse_basis;
  const Index nc = P.cols(), K = p.motions;
  // R = diag(1 / column sums) P^T: a coarse function's mean over its pairs.
  Vector mass = Vector::Zero(nc);
  for (Index k = 0; k < nc; ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(P, k); it; ++it) mass[k] += it.value();
  const auto mean = [&](const Vector& v) {  // R v for a pair vector v
    Vector out = P.transpose() * v;
    return Vector(out.cwiseQuotient(mass));
  };
  CondensedProblem coarse;
  coarse.pairs = nc;
  coarse.motions = K;
  coarse.M = Matrix::Zero(2 * nc, 2 * nc);
  const Matrix normal_block = mass.cwiseInverse().asDiagonal() * (P.transpose() * data.coarse_image);
  for (Index k = 0; k < nc; ++k) {
    for (Index l = 0; l < nc; ++l) coarse.M(2 * k, 2 * l) = normal_block(k, l);
    coarse.M(2 * k + 1, 2 * k + 1) = normal_block(k, k);  // (tau stays 0: frictionless)
  }
  coarse.b = Matrix::Zero(2 * nc, K);
  coarse.f = Matrix::Zero(K, 2 * nc);
  for (Index k = 0; k < K; ++k) {
    const Vector b_normal = normal_rows(p.b.col(k));
    const Vector f_normal = normal_rows(p.f.row(k).transpose());
    Eigen::Map<Vector, 0, Eigen::InnerStride<2>>(coarse.b.col(k).data(), nc) = mean(b_normal);
    const Vector f_coarse = P.transpose() * f_normal;
    for (Index l = 0; l < nc; ++l) coarse.f(k, 2 * l) = f_coarse[l];
  }
  coarse.f_delta = p.f_delta;
  coarse.gap = mean(in.gap);
  coarse.on_axis.assign(static_cast<std::size_t>(nc), false);
  coarse.length_scale = p.length_scale;
  coarse.groups = {0, nc};
  StepInput c = in;
  c.problem = &coarse;
  c.jump0 = on_normal_dofs(mean(normal_rows(in.jump0)));
  c.gap = coarse.gap;
  c.kind.assign(static_cast<std::size_t>(nc), ContactKind::unilateral);
  c.friction = Vector::Zero(nc);
  c.compliance.clear();
  c.mollifier = nullptr;
  c.previous_tangential_jump = Vector::Zero(nc);
  c.x_start.resize(0);
  c.state_start.clear();
  c.newton_cache = nullptr;
  SolverOptions coarse_options = options;
  coarse_options.tolerance = std::max(options.tolerance, 1e-8);
  const StepOutput out = solve_step_newton(c, coarse_options);
  if (!out.converged) return;  // the fine iteration starts from zero as it would have
  x = on_normal_dofs(P * normal_rows(out.x).cwiseMax(0.0));
  delta = out.delta;
}

}  // namespace bemcontact::contact

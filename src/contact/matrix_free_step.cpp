// The Newton system of the matrix-free route (condensed.hpp, MatrixFreeCondensed): the free
// unknowns of the pairs (lambda_n in contact, with a slipping tau folded into its column; tau
// sticking) F and the motions,
//   [J_FF  b_F    ] [z_F  ]   [rhs_F ]
//   [f_F   f_delta] [delta] = [target],   J_FF z = (M x(z))_F, x(z) the pair unknowns of z,
// solved without forming M: z_F = y - Y delta with J_FF y = rhs_F and J_FF Y = b_F (K + 1
// GMRES solves, each product one solve of every region's factors), then the K x K Schur
// complement for delta.
//
// Preconditioner: two-level additive Schwarz for a first-kind operator ([TranStephan1996]:
// hat functions on a coarse grid of the pairs plus a local scaling; its condition number
// grows with H / h, the coarse spacing over the pairs', not with their number):
//   z = Q J_c^-1 Q^T r + D^-1 (r - (J Q) J_c^-1 Q^T r),
// Q the hat functions on the free normal unknowns (and, with friction, on the free
// tangential ones), J Q from M's images of the hats on the normal and tangential dofs formed
// once per model (one batched solve per coarse function; a slipping column's tau enters as
// the hat's mean slip factor times the tangential image), J_c = Q^T (J Q), D J's diagonal
// from M's, sampled (sampled_diagonal).
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

// The normal (or tangential) rows of a 2N-vector, and a pair vector spread on those dofs.
Vector dof_rows(const Vector& v, int direction) {
  return Eigen::Map<const Vector, 0, Eigen::InnerStride<2>>(v.data() + direction, v.size() / 2);
}
Vector on_dofs(const Vector& v, int direction) {
  Vector out = Vector::Zero(2 * v.size());
  Eigen::Map<Vector, 0, Eigen::InnerStride<2>>(out.data() + direction, v.size()) = v;
  return out;
}

// J_FF: the free rows of M x(z) for the free unknowns z (the slipping tau folded in; a
// compliant pair's row less lambda / k).
class NewtonBlock : public operators::LinearOperator {
 public:
  NewtonBlock(const CondensedOperator& M, const NewtonSystem& system, Index pairs)
      : M_(M), system_(system), pairs_(pairs),
        offset_(system.pair_unknowns(Vector::Zero(static_cast<Index>(system.free_dofs.size())), pairs)) {}
  Index rows() const override { return static_cast<Index>(system_.free_dofs.size()); }
  Index cols() const override { return rows(); }
  void apply(const Vector& z, Vector& y) const override {
    const Vector x = system_.pair_unknowns(z, pairs_) - offset_;  // (the slip offsets are the right-hand side's)
    Vector w;
    M_.apply(x, w);
    y.resize(rows());
    for (Index a = 0; a < rows(); ++a) {
      const Index dof = system_.free_dofs[static_cast<std::size_t>(a)];
      y[a] = w[dof] - (dof % 2 == 0 ? system_.normal_shift[dof / 2] * z[a] : 0.0);
    }
  }

 private:
  const CondensedOperator& M_;
  const NewtonSystem& system_;
  Index pairs_;
  Vector offset_;
};

// The two-level preconditioner of the header on the free unknowns.
class TwoLevel : public operators::LinearOperator {
 public:
  TwoLevel(const MatrixFreeCondensed& data, const NewtonSystem& system) : data_(data), system_(system) {
    const auto& P = data.coarse_basis;
    const Index n = P.rows(), nc = P.cols();
    const auto& free = system.free_dofs;
    position_.assign(static_cast<std::size_t>(2 * n), -1);
    for (std::size_t a = 0; a < free.size(); ++a) position_[static_cast<std::size_t>(free[a])] = static_cast<Index>(a);
    // The coarse functions (hat k, direction) that keep at least half their mass on free
    // unknowns (one cut to a sliver at the zone's edge would make J_c nearly singular), and a
    // normal function's mean slip factor over its pairs.
    const int directions = data.tangential ? 2 : 1;
    for (int direction = 0; direction < directions; ++direction)
      for (Index k = 0; k < nc; ++k) {
        double mass = 0.0, kept = 0.0, slip = 0.0;
        for (Eigen::SparseMatrix<double>::InnerIterator it(P, k); it; ++it) {
          mass += it.value();
          if (position_[static_cast<std::size_t>(2 * it.row() + direction)] < 0) continue;
          kept += it.value();
          if (direction == 0) slip += it.value() * system.slip_factor[it.row()];
        }
        if (kept >= 0.5 * mass) functions_.push_back({k, direction, kept > 0.0 ? slip / kept : 0.0});
      }
    const Index c = static_cast<Index>(functions_.size());
    if (c == 0) return;
    // J Q's rows at the free unknowns, and J_c = Q^T (J Q).
    image_ = Matrix::Zero(static_cast<Index>(free.size()), c);
    for (Index l = 0; l < c; ++l) {
      const auto& fn = functions_[static_cast<std::size_t>(l)];
      for (std::size_t a = 0; a < free.size(); ++a) {
        const Index dof = free[a];
        double v = data.image(dof, fn.hat, fn.direction);
        if (fn.direction == 0 && fn.slip != 0.0) v += fn.slip * data.image(dof, fn.hat, 1);
        image_(static_cast<Index>(a), l) = v;
      }
      if (fn.direction == 0)  // a compliant pair's -lambda / k on the diagonal
        for (Eigen::SparseMatrix<double>::InnerIterator it(P, fn.hat); it; ++it) {
          const Index at = position_[static_cast<std::size_t>(2 * it.row())];
          if (at >= 0) image_(at, l) -= system.normal_shift[it.row()] * it.value();
        }
    }
    Matrix Jc = Matrix::Zero(c, c);
    for (Index l = 0; l < c; ++l) {
      const auto& fn = functions_[static_cast<std::size_t>(l)];
      for (Eigen::SparseMatrix<double>::InnerIterator it(P, fn.hat); it; ++it) {
        const Index at = position_[static_cast<std::size_t>(2 * it.row() + fn.direction)];
        if (at >= 0) Jc.row(l) += it.value() * image_.row(at);
      }
    }
    coarse_ = Eigen::PartialPivLU<Matrix>(Jc);
  }
  Index rows() const override { return static_cast<Index>(system_.free_dofs.size()); }
  Index cols() const override { return rows(); }
  void apply(const Vector& r, Vector& z) const override {
    const auto& P = data_.coarse_basis;
    const Index c = static_cast<Index>(functions_.size());
    Vector rc = Vector::Zero(c);  // Q^T r
    for (Index l = 0; l < c; ++l) {
      const auto& fn = functions_[static_cast<std::size_t>(l)];
      for (Eigen::SparseMatrix<double>::InnerIterator it(P, fn.hat); it; ++it) {
        const Index at = position_[static_cast<std::size_t>(2 * it.row() + fn.direction)];
        if (at >= 0) rc[l] += it.value() * r[at];
      }
    }
    const Vector e = c > 0 ? Vector(coarse_.solve(rc)) : Vector();
    const Vector image_e = c > 0 ? Vector(image_ * e) : Vector::Zero(rows());
    z.resize(rows());
    for (Index a = 0; a < rows(); ++a) {
      const Index dof = system_.free_dofs[static_cast<std::size_t>(a)], i = dof / 2;
      const double local = data_.diagonal[dof] - (dof % 2 == 0 ? system_.normal_shift[i] : 0.0);  // J_aa's estimate
      z[a] = local != 0.0 ? (r[a] - image_e[a]) / local : 0.0;
    }
    for (Index l = 0; l < c; ++l) {
      const auto& fn = functions_[static_cast<std::size_t>(l)];
      for (Eigen::SparseMatrix<double>::InnerIterator it(P, fn.hat); it; ++it) {
        const Index at = position_[static_cast<std::size_t>(2 * it.row() + fn.direction)];
        if (at >= 0) z[at] += it.value() * e[l];
      }
    }
  }

 private:
  struct CoarseFunction {
    Index hat;
    int direction;  // 0 normal, 1 tangential
    double slip;    // a normal function's mean slip factor
  };
  const MatrixFreeCondensed& data_;
  const NewtonSystem& system_;
  std::vector<Index> position_;  // per dof: its place among the free unknowns, or -1
  std::vector<CoarseFunction> functions_;
  Matrix image_;  // J Q at the free unknowns
  Eigen::PartialPivLU<Matrix> coarse_;
};

// Diagonal samples per contact: M's diagonal at this many pairs, the rest interpolated.
constexpr Index kDiagonalSamples = 16;

// M's diagonal estimated at every dof: exact at kDiagonalSamples pairs of each contact (M
// times their unit vectors, one batched solve), M_ii / w_i interpolated linearly between
// them (a first-kind operator of order -1: M_ii ~ w_i, with a log w_i factor that the
// interpolation follows along a graded zone). A pair of weight 0 (the axis node of a
// quadratic element) gets 0: its row is scaled by nothing.
Vector sampled_diagonal(const CondensedOperator& M, const Vector& weight, const std::vector<Index>& groups) {
  const Index n = weight.size();
  std::vector<Index> samples;
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    const Index first = groups[g], count = groups[g + 1] - groups[g];
    const Index wanted = std::min<Index>(kDiagonalSamples, count);
    for (Index k = 0; k < wanted; ++k) {
      Index i = first + (wanted == 1 ? 0 : k * (count - 1) / (wanted - 1));
      while (i + 1 < groups[g + 1] && weight[i] <= 0.0) ++i;  // (an axis node: its neighbour)
      if (weight[i] > 0.0 && (samples.empty() || samples.back() != i)) samples.push_back(i);
    }
  }
  std::vector<Eigen::Triplet<double>> units;
  for (std::size_t k = 0; k < samples.size(); ++k)
    for (int direction = 0; direction < 2; ++direction)
      units.emplace_back(2 * samples[k] + direction, 2 * static_cast<Index>(k) + direction, 1.0);
  Eigen::SparseMatrix<double> unit_columns(2 * n, 2 * static_cast<Index>(samples.size()));
  unit_columns.setFromTriplets(units.begin(), units.end());
  const Matrix columns = M.apply_columns(unit_columns);
  Vector diagonal = Vector::Zero(2 * n);
  std::size_t next = 0;  // the first sample of the current group
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    std::size_t end = next;
    while (end < samples.size() && samples[end] < groups[g + 1]) ++end;
    for (int direction = 0; direction < 2; ++direction) {
      const auto ratio = [&](std::size_t k) {
        const Index dof = 2 * samples[k] + direction;
        return columns(dof, 2 * static_cast<Index>(k) + direction) / weight[samples[k]];
      };
      for (Index i = groups[g]; i < groups[g + 1] && end > next; ++i) {
        std::size_t k = next;
        while (k + 1 < end && samples[k + 1] <= i) ++k;
        double r = ratio(k);
        if (k + 1 < end && i > samples[k]) {
          const double t = static_cast<double>(i - samples[k]) / static_cast<double>(samples[k + 1] - samples[k]);
          r = (1.0 - t) * r + t * ratio(k + 1);
        }
        diagonal[2 * i + direction] = r * weight[i];
      }
    }
    next = end;
  }
  return diagonal;
}

}  // namespace

double MatrixFreeCondensed::image(Index dof, Index hat, int direction) const {
  const Index nc = coarse_basis.cols();
  return tangential ? coarse_image(dof, direction * nc + hat) : coarse_image(dof / 2, hat);
}

MatrixFreeCondensed prepare_matrix_free(std::shared_ptr<const CondensedOperator> M, Vector weight,
                                        const std::vector<Index>& groups, bool tangential) {
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
  // The hats on the normal dofs (and on the tangential ones), M times them batched.
  const int directions = tangential ? 2 : 1;
  for (int direction = 0; direction < directions; ++direction)
    for (const auto& h : hats) spread.emplace_back(2 * h.row() + direction, direction * column + h.col(), h.value());
  Eigen::SparseMatrix<double> on_dofs_matrix(2 * n, directions * column);
  on_dofs_matrix.setFromTriplets(spread.begin(), spread.end());
  Matrix image = M->apply_columns(on_dofs_matrix);
  data.tangential = tangential;
  if (tangential) {
    data.coarse_image = std::move(image);
  } else {  // only the normal rows serve
    data.coarse_image.resize(n, column);
    for (Index i = 0; i < n; ++i) data.coarse_image.row(i) = image.row(2 * i);
  }
  data.diagonal = sampled_diagonal(*M, weight, groups);
  data.weight = std::move(weight);
  data.M = std::move(M);
  return data;
}

bool solve_matrix_free_system(const CondensedProblem& p, const NewtonSystem& system, double goal,
                              const Vector& delta_guess, NewtonSystemCache& cache, Vector& z, std::string& failure) {
  const auto& data = *p.matrix_free;
  const Index n = p.pairs, K = p.motions;
  const auto& free = system.free_dofs;
  const Index m = static_cast<Index>(free.size());
  for (const Index dof : free)
    if (dof % 2 != 0 && !data.tangential)
      throw std::logic_error("solve_matrix_free_system: a tangential unknown without the tangential coarse space");
  if (cache.krylov_start.rows() != 2 * n || cache.krylov_start.cols() != K + 1) cache.krylov_start = Matrix::Zero(2 * n, K + 1);
  // Right-hand sides: the free rows, then b's columns at them.
  Matrix B(m, K + 1), Y(m, K + 1);
  for (Index a = 0; a < m; ++a) {
    B(a, 0) = system.rhs[a];
    for (Index k = 0; k < K; ++k) B(a, k + 1) = p.b(free[static_cast<std::size_t>(a)], k);
  }
  cache.krylov_floor = false;
  if (m > 0) {
    const NewtonBlock block(*data.M, system, n);
    const TwoLevel preconditioner(data, system);
    operators::GmresOptions options;
    options.restart = 300;
    options.max_iterations = 1000;
    options.stagnation_cycles = 2;  // (at the products' accuracy the cycles end early and gain nothing)
    for (Index j = 0; j <= K; ++j) {
      const Vector b = B.col(j);
      if (b.isZero(0.0)) {  // (a motion that moves none of the free rows: a sliding body's tangential one)
        Y.col(j).setZero();
        continue;
      }
      Vector x0(m);
      for (Index a = 0; a < m; ++a) x0[a] = cache.krylov_start(free[static_cast<std::size_t>(a)], j);
      // The free rows' residual within goal; b's columns within it over the motion they are
      // multiplied by (when it is not known yet, to the floor), and within 1e-6 of |b| (the
      // Schur complement is formed from them, whatever the motion: a tangential motion is 0
      // until its force rises). GMRES's tolerance is relative to its first residual, which a
      // warm start makes small.
      Vector r0;
      block.apply(x0, r0);
      const double motion = j > 0 && delta_guess.size() == K ? std::abs(delta_guess[j - 1]) : 0.0;
      const double b_goal = std::min(motion > 0.0 ? goal / motion : 0.0, 1e-6 * b.norm());
      // (Not below 1e-15 of |b|: GMRES's round-off floor on this operator.)
      const double column_goal = std::max(j == 0 ? goal : b_goal, 1e-15 * b.norm());
      const double first = (b - r0).norm();
      ++cache.krylov_iterations;  // the product above
      if (first <= column_goal) {
        Y.col(j) = x0;
        continue;
      }
      options.tolerance = column_goal / first;
      const auto result = operators::gmres(block, b, options, x0, {}, &preconditioner);
      cache.krylov_iterations += result.iterations;
      // Stopped short of the goal at the products' accuracy (an invariant space, a
      // stagnation: the regions' compressed solves are accurate to about their compression
      // accuracy, not to round-off) but within 1e-6 of |b|: taken and flagged; the step's
      // residual judges it (solve_step_newton).
      if (!result.converged()) {
        if (result.relative_residual * first > 1e-6 * b.norm()) {
          failure = "GMRES on the " + std::to_string(m) + " free unknowns of the pairs in contact: " + result.message;
          return false;
        }
        cache.krylov_floor = true;
      }
      Y.col(j) = result.x;
    }
  }
  for (Index a = 0; a < m; ++a) cache.krylov_start.row(free[static_cast<std::size_t>(a)]) = Y.row(a);
  // delta from the Schur complement (f_delta - f_F Y_b) delta = target - f_F y, f_F with the
  // slipping tau folded in as in J.
  Vector delta;
  if (K > 0) {
    Matrix fF(K, m);
    for (Index k = 0; k < K; ++k)
      for (Index a = 0; a < m; ++a) fF(k, a) = jacobian_entry(p, system, 2 * n + k, free[static_cast<std::size_t>(a)]);
    const Matrix S = p.f_delta - fF * Y.rightCols(K);
    const Vector t = system.rhs.tail(K) - fF * Y.col(0);
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
  // M_c's block (row direction, column direction) = R (M's images of the hats)'s rows.
  const int directions = data.tangential ? 2 : 1;
  for (int row = 0; row < directions; ++row)
    for (int column = 0; column < directions; ++column) {
      Matrix rows(p.pairs, nc);
      for (Index i = 0; i < p.pairs; ++i)
        for (Index l = 0; l < nc; ++l) rows(i, l) = data.image(2 * i + row, l, column);
      const Matrix block = mass.cwiseInverse().asDiagonal() * (P.transpose() * rows);
      for (Index k = 0; k < nc; ++k)
        for (Index l = 0; l < nc; ++l) coarse.M(2 * k + row, 2 * l + column) = block(k, l);
    }
  if (!data.tangential)
    for (Index k = 0; k < nc; ++k) coarse.M(2 * k + 1, 2 * k + 1) = coarse.M(2 * k, 2 * k);  // (tau stays 0: frictionless)
  // b averaged, f summed over the hats (the coarse pressures are the hats' amplitudes).
  const auto coarse_dofs = [&](const Vector& fine, bool sum) {
    Vector out(2 * nc);
    for (int direction = 0; direction < 2; ++direction) {
      const Vector v = dof_rows(fine, direction);
      Eigen::Map<Vector, 0, Eigen::InnerStride<2>>(out.data() + direction, nc) =
          sum ? Vector(P.transpose() * v) : mean(v);
    }
    return out;
  };
  coarse.b = Matrix::Zero(2 * nc, K);
  coarse.f = Matrix::Zero(K, 2 * nc);
  for (Index k = 0; k < K; ++k) {
    coarse.b.col(k) = coarse_dofs(p.b.col(k), false);
    coarse.f.row(k) = coarse_dofs(p.f.row(k).transpose(), true).transpose();
  }
  coarse.f_delta = p.f_delta;
  coarse.gap = mean(in.gap);
  coarse.on_axis.assign(static_cast<std::size_t>(nc), false);
  coarse.length_scale = p.length_scale;
  coarse.groups = {0, nc};
  StepInput c = in;
  c.problem = &coarse;
  c.jump0 = coarse_dofs(in.jump0, false);
  c.gap = coarse.gap;
  c.kind.assign(static_cast<std::size_t>(nc), ContactKind::unilateral);
  c.friction = data.tangential ? mean(in.friction) : Vector::Zero(nc);
  c.compliance.clear();
  c.mollifier = nullptr;
  c.previous_tangential_jump = mean(in.previous_tangential_jump);
  c.x_start.resize(0);
  c.state_start.clear();
  c.newton_cache = nullptr;
  SolverOptions coarse_options = options;
  coarse_options.tolerance = std::max(options.tolerance, 1e-8);
  const StepOutput out = solve_step_newton(c, coarse_options);
  if (!out.converged) return;  // the fine iteration starts from zero as it would have
  x = on_dofs(P * dof_rows(out.x, 0).cwiseMax(0.0), 0) + on_dofs(P * dof_rows(out.x, 1), 1);
  delta = out.delta;
}

}  // namespace bemcontact::contact

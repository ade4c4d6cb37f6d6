// The Newton system of the matrix-free route (condensed.hpp, MatrixFreeCondensed): the free
// unknowns of the pairs (lambda_n in contact, with a slipping tau folded into its column; tau
// sticking) F and the motions,
//   [J_FF  b_F    ] [z_F  ]   [rhs_F ]
//   [f_F   f_delta] [delta] = [target],   J_FF z = (M x(z))_F, x(z) the pair unknowns of z,
// solved whole by one GMRES without forming M (each product one solve of every region's
// factors), the force rows scaled to their own goal.
//
// Preconditioner: two-level additive Schwarz for a first-kind operator ([TranStephan1996]:
// hat functions on a coarse grid of the pairs plus a local scaling; its condition number
// grows with H / h, the coarse spacing over the pairs', not with their number):
//   z = Q J_c^-1 Q^T r + D^-1 (r - (J Q) J_c^-1 Q^T r),
// Q the hat functions on the free normal unknowns (and, with friction, on the free
// tangential ones), J Q from M's images of the hats on the normal and tangential dofs,
// each formed when the contact set first reaches its hat (HatImages: one batched solve per
// coarse function; a slipping column's tau enters as the hat's mean slip factor times the
// tangential image), J_c = Q^T (J Q), D J's diagonal from M's, sampled (sampled_diagonal).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "bemcontact/contact/step_solvers.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/dense_lu.hpp"
#include "bemcontact/operators/gmres.hpp"

namespace bemcontact::contact {
namespace {

// Pairs per coarse hat function: the preconditioned condition number grows with it, the
// coarse image's memory (N x N / spacing) and its share of every iteration fall with it.
// Rigid cylinder, 8 001 pairs (model + contact iterations): 4: 18.3 + 4.8 s (61 products);
// 8: 10.8 + 4.0 s (94); 16: 10.6 + 13.3 s (275, 6 Newton iterations: a coarser start).
constexpr Index kCoarseSpacing = 8;
// The start's first stage (coarse_start): hats every 8 coarse ones, whose contact problem
// tells which of the coarse hats the second stage needs (their images are then formed, and
// the preconditioner's are those it keeps, not every hat of the declared zones).
constexpr Index kStartSpacing = 8 * kCoarseSpacing;
constexpr Index kStagedHats = 256;

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
    const auto& P = data.coarse.basis();
    const Index n = P.rows(), nc = P.cols();
    const auto& free = system.free_dofs;
    position_.assign(static_cast<std::size_t>(2 * n), -1);
    for (std::size_t a = 0; a < free.size(); ++a) position_[static_cast<std::size_t>(free[a])] = static_cast<Index>(a);
    // The coarse functions (hat k, direction) that keep at least half their mass on free
    // unknowns (one cut to a sliver at the zone's edge would make J_c nearly singular), and a
    // normal function's mean slip factor over its pairs.
    const int directions = data.coarse.tangential() ? 2 : 1;
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
    // The images of the functions kept (those the contact set reaches for the first time
    // formed now), J Q's rows at the free unknowns, and J_c = Q^T (J Q).
    std::vector<Index> needed;
    for (const auto& fn : functions_) {
      needed.push_back(fn.direction * nc + fn.hat);
      if (fn.direction == 0 && fn.slip != 0.0) needed.push_back(nc + fn.hat);
    }
    data.coarse.form(needed);
    image_ = Eigen::MatrixXf::Zero(static_cast<Index>(free.size()), c);
    for (Index l = 0; l < c; ++l) {
      const auto& fn = functions_[static_cast<std::size_t>(l)];
      for (std::size_t a = 0; a < free.size(); ++a) {
        const Index dof = free[a];
        double v = data.coarse.image(dof, fn.hat, fn.direction);
        if (fn.direction == 0 && fn.slip != 0.0) v += fn.slip * data.coarse.image(dof, fn.hat, 1);
        image_(static_cast<Index>(a), l) = static_cast<float>(v);
      }
      if (fn.direction == 0)  // a compliant pair's -lambda / k on the diagonal
        on_support(l, [&](Index at, double weight, Index pair) {
          image_(at, l) = static_cast<float>(image_(at, l) - system.normal_shift[pair] * weight);
        });
    }
    Matrix Jc = Matrix::Zero(c, c);
    for (Index l = 0; l < c; ++l)
      on_support(l, [&](Index at, double weight, Index) { Jc.row(l) += weight * image_.row(at).cast<double>(); });
    // LAPACK's blocked LU on the dense coarse operator (Eigen's PartialPivLU took most of an
    // iteration at 10^4 pairs with friction, c ~ 2 000). Singular to working precision (a
    // coarse space cut badly by the contact set): none, the fine level alone.
    try {
      coarse_ = operators::DenseLU(std::move(Jc), "the coarse operator of the matrix-free preconditioner");
    } catch (const SolverError&) {
      functions_.clear();
    }
  }
  Index rows() const override { return static_cast<Index>(system_.free_dofs.size()); }
  Index cols() const override { return rows(); }
  void apply(const Vector& r, Vector& z) const override {
    const Index c = static_cast<Index>(functions_.size());
    Vector rc = Vector::Zero(c);  // Q^T r
    for (Index l = 0; l < c; ++l) on_support(l, [&](Index at, double weight, Index) { rc[l] += weight * r[at]; });
    const Vector e = c > 0 ? Vector(coarse_.solve(rc)) : Vector();
    Vector image_e = Vector::Zero(rows());  // (J Q) e, in double
    for (Index l = 0; l < c; ++l) image_e += image_.col(l).cast<double>() * e[l];
    z.resize(rows());
    for (Index a = 0; a < rows(); ++a) {
      const Index dof = system_.free_dofs[static_cast<std::size_t>(a)], i = dof / 2;
      const double local = data_.diagonal[dof] - (dof % 2 == 0 ? system_.normal_shift[i] : 0.0);  // J_aa's estimate
      z[a] = local != 0.0 ? (r[a] - image_e[a]) / local : 0.0;
    }
    for (Index l = 0; l < c; ++l) on_support(l, [&](Index at, double weight, Index) { z[at] += weight * e[l]; });
  }

 private:
  struct CoarseFunction {
    Index hat;
    int direction;  // 0 normal, 1 tangential
    double slip;    // a normal function's mean slip factor
  };
  // f(at, weight, pair) over coarse function l's free unknowns: their place among the free
  // unknowns, the hat's weight there, the pair.
  template <class F>
  void on_support(Index l, F&& f) const {
    const auto& fn = functions_[static_cast<std::size_t>(l)];
    for (Eigen::SparseMatrix<double>::InnerIterator it(data_.coarse.basis(), fn.hat); it; ++it) {
      const Index at = position_[static_cast<std::size_t>(2 * it.row() + fn.direction)];
      if (at >= 0) f(at, it.value(), it.row());
    }
  }
  const MatrixFreeCondensed& data_;
  const NewtonSystem& system_;
  std::vector<Index> position_;  // per dof: its place among the free unknowns, or -1
  std::vector<CoarseFunction> functions_;
  Eigen::MatrixXf image_;  // J Q at the free unknowns (single precision: a fixed matrix, applied in double)
  operators::DenseLU coarse_;
};

// The Newton system with its motions, [J b_F; f_F f_delta], its force rows scaled by
// row_scale.
class BorderedSystem : public operators::LinearOperator {
 public:
  BorderedSystem(const NewtonBlock& J, const Matrix& bF, const Matrix& fF, const Matrix& f_delta, const Vector& row_scale)
      : J_(J), bF_(bF), fF_(fF), f_delta_(f_delta), row_scale_(row_scale) {}
  Index rows() const override { return J_.rows() + bF_.cols(); }
  Index cols() const override { return rows(); }
  void apply(const Vector& v, Vector& y) const override {
    const Index m = J_.rows(), K = bF_.cols();
    Vector Jz;
    if (m > 0) J_.apply(v.head(m), Jz);
    y.resize(m + K);
    if (m > 0) y.head(m) = Jz + bF_ * v.tail(K);
    if (K > 0) y.tail(K) = row_scale_.cwiseProduct(fF_ * v.head(m) + f_delta_ * v.tail(K));
  }

 private:
  const NewtonBlock& J_;
  const Matrix &bF_, &fF_, &f_delta_;
  const Vector& row_scale_;
};

// The bordered system's right preconditioner: the two-level one on the pairs' unknowns, the
// motions scaled to unit columns. With it the preconditioned operator differs from the
// pairs' alone (and the identity on the motions) by a rank of at most 2K: GMRES needs at
// most 2K more iterations than for the pairs' block, where K + 1 separate solves and a Schur
// complement took K + 1 times its iterations.
class BorderedPreconditioner : public operators::LinearOperator {
 public:
  BorderedPreconditioner(const TwoLevel& pairs, const Vector& column_scale) : pairs_(pairs), column_scale_(column_scale) {}
  Index rows() const override { return pairs_.rows() + column_scale_.size(); }
  Index cols() const override { return rows(); }
  void apply(const Vector& r, Vector& z) const override {
    const Index m = pairs_.rows(), K = column_scale_.size();
    z.resize(m + K);
    if (m > 0) {
      Vector zm;
      pairs_.apply(r.head(m), zm);
      z.head(m) = zm;
    }
    if (K > 0) z.tail(K) = column_scale_.cwiseProduct(r.tail(K));
  }

 private:
  const TwoLevel& pairs_;
  const Vector& column_scale_;
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

HatImages::HatImages(std::shared_ptr<const CondensedOperator> M, Eigen::SparseMatrix<double> basis, bool tangential)
    : M_(std::move(M)), basis_(std::move(basis)), tangential_(tangential),
      images_(static_cast<std::size_t>((tangential ? 2 : 1) * basis_.cols())) {}

void HatImages::form(const std::vector<Index>& functions) const {
  const Index n = basis_.rows(), hats = basis_.cols();
  std::vector<Index> missing;
  for (const Index f : functions)
    if (images_.at(static_cast<std::size_t>(f)).size() == 0) missing.push_back(f);
  std::sort(missing.begin(), missing.end());
  missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
  // In batches of columns, each rounded to single precision as it comes (the whole batch in
  // double is what the rounding saves).
  constexpr auto kImageBatch = static_cast<std::size_t>(HatImages::kBatch);
  for (std::size_t first = 0; first < missing.size(); first += kImageBatch) {
    const std::size_t count = std::min(kImageBatch, missing.size() - first);
    std::vector<Eigen::Triplet<double>> spread;
    for (std::size_t j = 0; j < count; ++j) {
      const Index f = missing[first + j], direction = f / hats, hat = f % hats;
      for (Eigen::SparseMatrix<double>::InnerIterator it(basis_, hat); it; ++it)
        spread.emplace_back(2 * it.row() + direction, static_cast<Index>(j), it.value());
    }
    Eigen::SparseMatrix<double> columns(2 * n, static_cast<Index>(count));
    columns.setFromTriplets(spread.begin(), spread.end());
    const Matrix image = M_->apply_columns(columns);
    for (std::size_t j = 0; j < count; ++j) {
      auto& out = images_[static_cast<std::size_t>(missing[first + j])];
      if (tangential_) {
        out = image.col(static_cast<Index>(j)).cast<float>();
      } else {  // only the normal rows serve
        out.resize(n);
        for (Index i = 0; i < n; ++i) out[i] = static_cast<float>(image(2 * i, static_cast<Index>(j)));
      }
    }
  }
}

const Eigen::VectorXf& HatImages::image_of(Index function) const {
  const auto& image = images_.at(static_cast<std::size_t>(function));
  if (image.size() == 0) throw std::logic_error("HatImages: an image asked for before it was formed");
  return image;
}

double HatImages::image(Index dof, Index hat, int direction) const {
  return tangential_ ? image_of(direction * hats() + hat)[dof] : image_of(hat)[dof / 2];  // (float to double)
}

Index HatImages::formed() const {
  return static_cast<Index>(std::count_if(images_.begin(), images_.end(), [](const auto& v) { return v.size() > 0; }));
}

namespace {

// Hat functions over each contact's pairs, every `spacing` pairs (its ends included): N x hats.
Eigen::SparseMatrix<double> hat_basis(Index n, const std::vector<Index>& groups, Index spacing) {
  std::vector<Eigen::Triplet<double>> hats;
  Index column = 0;
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    const Index first = groups[g], count = groups[g + 1] - groups[g];
    if (count == 0) continue;
    const Index functions = count < 2 ? 1 : std::max<Index>(2, (count - 1 + spacing - 1) / spacing + 1);
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
  Eigen::SparseMatrix<double> basis(n, column);
  basis.setFromTriplets(hats.begin(), hats.end());
  return basis;
}

}  // namespace

MatrixFreeCondensed prepare_matrix_free(std::shared_ptr<const CondensedOperator> M, Vector weight,
                                        const std::vector<Index>& groups, bool tangential) {
  MatrixFreeCondensed data;
  const Index n = weight.size();
  data.coarse = HatImages(M, hat_basis(n, groups, kCoarseSpacing), tangential);
  data.start = HatImages(M, hat_basis(n, groups, kStartSpacing), tangential);
  data.diagonal = sampled_diagonal(*M, weight, groups);
  data.weight = std::move(weight);
  data.M = std::move(M);
  return data;
}

bool solve_matrix_free_system(const CondensedProblem& p, const NewtonSystem& system, double goal,
                              const Vector& force_goal, const Vector& delta_guess, NewtonSystemCache& cache, Vector& z,
                              std::string& failure) {
  const auto& data = *p.matrix_free;
  const Index n = p.pairs, K = p.motions;
  const auto& free = system.free_dofs;
  const Index m = static_cast<Index>(free.size());
  for (const Index dof : free)
    if (dof % 2 != 0 && !data.coarse.tangential())
      throw std::logic_error("solve_matrix_free_system: a tangential unknown without the tangential coarse space");
  // The motions' columns b_F and rows f_F (the slipping tau folded in as in J).
  Matrix bF(m, K), fF(K, m);
  for (Index k = 0; k < K; ++k)
    for (Index a = 0; a < m; ++a) {
      bF(a, k) = p.b(free[static_cast<std::size_t>(a)], k);
      fF(k, a) = jacobian_entry(p, system, 2 * n + k, free[static_cast<std::size_t>(a)]);
    }
  for (Index k = 0; k < K; ++k)
    if (bF.col(k).isZero(0.0) && p.f_delta.col(k).isZero(0.0)) {  // the system is singular
      failure = "no pair in contact carries the force loads (no free row moves with motion " + std::to_string(k) + ")";
      return false;
    }
  // Each force row scaled so that meeting `goal` in the 2-norm meets its own force_goal.
  Vector row_scale(K), column_scale(K);
  for (Index k = 0; k < K; ++k) {
    row_scale[k] = force_goal[k] > 0.0 ? goal / force_goal[k] : 1.0;
    const double size = bF.col(k).norm() + row_scale[k] * p.f_delta.col(k).norm();
    column_scale[k] = size > 0.0 ? 1.0 / size : 1.0;  // (a unit column for the Krylov basis)
  }
  const NewtonBlock block(*data.M, system, n);
  const BorderedSystem bordered(block, bF, fF, p.f_delta, row_scale);
  const TwoLevel two_level(data, system);
  const BorderedPreconditioner preconditioner(two_level, column_scale);
  Vector rhs(m + K);
  rhs.head(m) = system.rhs.head(m);
  for (Index k = 0; k < K; ++k) rhs[m + k] = row_scale[k] * system.rhs[m + k];
  // From the last solution (per dof) and motions: a Newton iteration's unknowns differ from
  // the previous iteration's at the pairs whose state changed.
  if (cache.krylov_start.size() != 2 * n) cache.krylov_start = Vector::Zero(2 * n);
  Vector x0(m + K);
  for (Index a = 0; a < m; ++a) x0[a] = cache.krylov_start[free[static_cast<std::size_t>(a)]];
  for (Index k = 0; k < K; ++k) x0[m + k] = delta_guess.size() == K ? delta_guess[k] : 0.0;
  cache.krylov_floor = false;
  Vector r0;
  bordered.apply(x0, r0);
  ++cache.krylov_iterations;  // the product above
  const double first = (rhs - r0).norm();
  // Not below the products' accuracy: 100 times the largest residual a GMRES of this
  // history stagnated at, relative to its right-hand side (measured 4e-14 to 1e-13 at 5 001
  // frictional pairs; 1e-15 until one did). Within 10 times it GMRES still crawled (40
  // iterations for a factor 2 at 5 001 pairs); at 100 times, 334 -> 319 products.
  const double floor = 100.0 * cache.krylov_floor_level * rhs.norm();
  if (goal < floor) cache.krylov_floor = true;
  const double target = std::max(goal, floor);
  Vector solution = x0;
  if (first > target) {
    operators::GmresOptions options;
    options.restart = 300;
    options.max_iterations = 1000;
    options.stagnation_cycles = 1;  // (at the products' accuracy the cycles end early and gain nothing)
    options.tolerance = target / first;
    const auto result = operators::gmres(bordered, rhs, options, x0, {}, &preconditioner);
    cache.krylov_iterations += result.iterations;
    // Stopped short of the goal at the products' accuracy (an invariant space, a
    // stagnation: the regions' compressed solves are accurate to about their compression
    // accuracy, not to round-off) but within 1e-6 of the right-hand side: taken and flagged;
    // the step's residual judges it (solve_step_newton).
    if (!result.converged()) {
      const double reached = result.relative_residual * first / rhs.norm();
      if (reached > 1e-6) {
        failure = "GMRES on the " + std::to_string(m) + " free unknowns of the pairs in contact and " +
                  std::to_string(K) + " motions: " + result.message;
        return false;
      }
      cache.krylov_floor = true;
      // (A stagnation above 1e-11 is not the products' accuracy: it does not raise the floor.)
      cache.krylov_floor_level = std::max(cache.krylov_floor_level, std::min({reached, first / rhs.norm(), 1e-11}));
    }
    solution = result.x;
  }
  for (Index a = 0; a < m; ++a) cache.krylov_start[free[static_cast<std::size_t>(a)]] = solution[a];
  z = std::move(solution);
  return z.allFinite();
}

namespace {

// The contact problem on hats `selected` of `hats` (their images formed here): the hats as
// pressures and shears, the gaps averaged over them, M_c = R M P dense (R = diag(1 / column
// sums) P^T: a hat's mean over its pairs), solved by solve_step_newton with the contact's
// law and friction; its solution prolonged into x, delta. False when it has none.
bool solve_on_hats(const StepInput& in, const SolverOptions& options, const HatImages& hats,
                   const std::vector<Index>& selected, Vector& x, Vector& delta) {
  const auto& p = *in.problem;
  const Index nc = static_cast<Index>(selected.size()), K = p.motions, all = hats.hats();
  if (nc == 0) return false;
  const int directions = hats.tangential() ? 2 : 1;
  std::vector<Index> functions;
  for (int direction = 0; direction < directions; ++direction)
    for (const Index k : selected) functions.push_back(direction * all + k);
  hats.form(functions);
  std::vector<Eigen::Triplet<double>> entries;
  for (Index l = 0; l < nc; ++l)
    for (Eigen::SparseMatrix<double>::InnerIterator it(hats.basis(), selected[static_cast<std::size_t>(l)]); it; ++it)
      entries.emplace_back(it.row(), l, it.value());
  Eigen::SparseMatrix<double> P(p.pairs, nc);
  P.setFromTriplets(entries.begin(), entries.end());
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
  // M_c's block (row direction, column direction): R times the rows of direction `row` of
  // the images of the hats on the dofs of `column`, column by column in double.
  for (int row = 0; row < directions; ++row)
    for (int column = 0; column < directions; ++column)
      for (Index l = 0; l < nc; ++l) {
        const Eigen::VectorXf& image = hats.image_of(column * all + selected[static_cast<std::size_t>(l)]);
        const Eigen::Map<const Eigen::VectorXf, 0, Eigen::InnerStride<>> rows(
            image.data() + (hats.tangential() ? row : 0), p.pairs, Eigen::InnerStride<>(hats.tangential() ? 2 : 1));
        const Vector block = mean(rows.cast<double>());
        for (Index k = 0; k < nc; ++k) coarse.M(2 * k + row, 2 * l + column) = block[k];
      }
  if (!hats.tangential())
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
  // Each hat's law: that of the pair it weighs most (a hat lies within one contact).
  c.kind.assign(static_cast<std::size_t>(nc), ContactKind::unilateral);
  c.compliance.assign(static_cast<std::size_t>(nc), NormalCompliance{});
  for (Index k = 0; k < nc; ++k) {
    Index heaviest = -1;
    double most = 0.0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(P, k); it; ++it)
      if (it.value() > most) most = it.value(), heaviest = it.row();
    if (heaviest < 0) continue;
    c.kind[static_cast<std::size_t>(k)] = in.kind[static_cast<std::size_t>(heaviest)];
    if (static_cast<std::size_t>(heaviest) < in.compliance.size())
      c.compliance[static_cast<std::size_t>(k)] = in.compliance[static_cast<std::size_t>(heaviest)];
  }
  c.friction = hats.tangential() ? mean(in.friction) : Vector::Zero(nc);
  c.mollifier = nullptr;
  c.previous_tangential_jump = mean(in.previous_tangential_jump);
  c.x_start.resize(0);
  c.state_start.clear();
  c.newton_cache = nullptr;
  SolverOptions coarse_options = options;
  coarse_options.tolerance = std::max(options.tolerance, 1e-8);
  const StepOutput out = solve_step_newton(c, coarse_options);
  if (!out.converged) return false;
  x = on_dofs(P * dof_rows(out.x, 0).cwiseMax(0.0), 0) + on_dofs(P * dof_rows(out.x, 1), 1);
  delta = out.delta;
  return true;
}

std::vector<Index> every_hat(const HatImages& hats) {
  std::vector<Index> all(static_cast<std::size_t>(hats.hats()));
  for (Index k = 0; k < hats.hats(); ++k) all[static_cast<std::size_t>(k)] = k;
  return all;
}

}  // namespace

void coarse_start(const StepInput& in, const SolverOptions& options, Vector& x, Vector& delta) {
  const auto& p = *in.problem;
  const auto& data = *p.matrix_free;
  // First stage (from kStagedHats coarse hats: below, their images cost little and a start
  // hat spans much of a contact): every start hat. Its pairs in contact, widened by a
  // start hat's spacing each way within their contact, choose the coarse hats of the second
  // stage; without a solution there, every coarse hat.
  Vector x1, delta1;
  std::vector<Index> selected;
  if (data.coarse.hats() >= kStagedHats && solve_on_hats(in, options, data.start, every_hat(data.start), x1, delta1)) {
    std::vector<bool> near(static_cast<std::size_t>(p.pairs), false);
    const auto groups = pair_groups(p);
    for (std::size_t g = 0; g + 1 < groups.size(); ++g)
      for (Index i = groups[g]; i < groups[g + 1]; ++i) {
        if (!(x1[2 * i] > 0.0)) continue;
        for (Index j = std::max(groups[g], i - kStartSpacing); j < std::min(groups[g + 1], i + kStartSpacing + 1); ++j)
          near[static_cast<std::size_t>(j)] = true;
      }
    for (Index k = 0; k < data.coarse.hats(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(data.coarse.basis(), k); it; ++it)
        if (near[static_cast<std::size_t>(it.row())]) {
          selected.push_back(k);
          break;
        }
  } else {
    selected = every_hat(data.coarse);
  }
  if (solve_on_hats(in, options, data.coarse, selected, x, delta)) return;
  if (x1.size() == x.size()) x = x1, delta = delta1;  // (else from zero, as it would have)
}

}  // namespace bemcontact::contact

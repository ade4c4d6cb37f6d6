#include "bemcontact/operators/bordered_lu.hpp"

#include <stdexcept>
#include <utility>

namespace bemcontact::operators {

namespace {

void add_to(const BorderedLU::Border& border, double scale, Vector& v) {
  if (border.unit >= 0) v[border.unit] += scale;
  else v += scale * border.dense;
}

// The matrix with the rows and columns of `keep` only.
Matrix kept_block(const Matrix& m, const std::vector<bool>& keep, Index kept) {
  Matrix out(kept, kept);
  for (Index j = 0, jj = 0; j < m.cols(); ++j) {
    if (!keep[static_cast<std::size_t>(j)]) continue;
    for (Index i = 0, ii = 0; i < m.rows(); ++i)
      if (keep[static_cast<std::size_t>(i)]) out(ii++, jj) = m(i, j);
    ++jj;
  }
  return out;
}

}  // namespace

void BorderedLU::add(Border column, Vector solution, Border row, const Vector& corner_row,
                     const Vector& corner_column, double corner) {
  const Index k = elements(), n = base_size();
  if (solution.size() != n || (column.unit < 0 && column.dense.size() != n) || (row.unit < 0 && row.dense.size() != n) ||
      corner_row.size() != k || corner_column.size() != k)
    throw std::logic_error("BorderedLU::add: an element of the wrong size");
  K_.conservativeResize(k + 1, k + 1);
  S_.conservativeResize(k + 1, k + 1);
  for (Index j = 0; j < k; ++j) {
    K_(k, j) = corner_row[j];
    K_(j, k) = corner_column[j];
    S_(k, j) = corner_row[j] - row.dot(X_[static_cast<std::size_t>(j)]);
    S_(j, k) = corner_column[j] - H_[static_cast<std::size_t>(j)].dot(solution);
  }
  K_(k, k) = corner;
  S_(k, k) = corner - row.dot(solution);
  G_.push_back(std::move(column));
  H_.push_back(std::move(row));
  X_.push_back(std::move(solution));
}

void BorderedLU::keep_only(const std::vector<bool>& keep) {
  if (static_cast<Index>(keep.size()) != elements()) throw std::logic_error("BorderedLU::keep_only: wrong size");
  std::size_t kept = 0;
  for (std::size_t e = 0; e < keep.size(); ++e) {
    if (!keep[e]) continue;
    if (kept != e) {
      G_[kept] = std::move(G_[e]);
      H_[kept] = std::move(H_[e]);
      X_[kept] = std::move(X_[e]);
    }
    ++kept;
  }
  if (kept == keep.size()) return;
  K_ = kept_block(K_, keep, static_cast<Index>(kept));
  S_ = kept_block(S_, keep, static_cast<Index>(kept));
  G_.resize(kept);
  H_.resize(kept);
  X_.resize(kept);
}

// S's rows equilibrated before its factorisation: a dropped unknown's row is J0^-1's scale,
// a new unknown's J0's (DenseLU equilibrates the columns).
void BorderedLU::factor() {
  const Index k = elements();
  row_scale_.resize(k);
  for (Index e = 0; e < k; ++e) {
    const double largest = S_.row(e).cwiseAbs().maxCoeff();
    row_scale_[e] = largest > 0.0 ? 1.0 / largest : 1.0;
  }
  S_lu_ = k > 0 ? DenseLU(row_scale_.asDiagonal() * S_, "the Schur complement of an updated Newton system") : DenseLU();
}

void BorderedLU::solve(const Vector& r, const Vector& g, Vector& y, Vector& s) const {
  const Index k = elements();
  y = base_lu_->solve(r);
  if (k == 0) {
    s.resize(0);
    return;
  }
  Vector t(k);
  for (Index e = 0; e < k; ++e) t[e] = g[e] - H_[static_cast<std::size_t>(e)].dot(y);
  s = S_lu_.solve(row_scale_.cwiseProduct(t));
  for (Index e = 0; e < k; ++e) y -= s[e] * X_[static_cast<std::size_t>(e)];
}

void BorderedLU::apply(const Vector& y, const Vector& s, Vector& out_base, Vector& out_border) const {
  const Index k = elements();
  out_base = *base_ * y;
  for (Index e = 0; e < k; ++e) add_to(G_[static_cast<std::size_t>(e)], s[e], out_base);
  out_border = K_ * s;
  for (Index e = 0; e < k; ++e) out_border[e] += H_[static_cast<std::size_t>(e)].dot(y);
}

}  // namespace bemcontact::operators

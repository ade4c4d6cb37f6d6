#include "bemcontact/operators/bordered_lu.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace bemcontact::operators {

namespace {

std::vector<Index> not_kept(Index n, const std::vector<Index>& kept) {
  std::vector<bool> is_kept(static_cast<std::size_t>(n), false);
  for (const Index k : kept) is_kept[static_cast<std::size_t>(k)] = true;
  std::vector<Index> dropped;
  for (Index k = 0; k < n; ++k)
    if (!is_kept[static_cast<std::size_t>(k)]) dropped.push_back(k);
  return dropped;
}

}  // namespace

BorderedLU::BorderedLU(const Matrix& base, const DenseLU& base_lu, std::vector<Index> kept, Matrix Q, Matrix R,
                       Matrix T)
    : base_(&base), base_lu_(&base_lu), kept_(std::move(kept)), dropped_(not_kept(base.rows(), kept_)),
      Q_(std::move(Q)), R_(std::move(R)), T_(std::move(T)) {
  const Index n = base.rows(), d = static_cast<Index>(dropped_.size());
  W_ = Matrix::Zero(n, d);
  for (Index j = 0; j < d; ++j) W_(dropped_[static_cast<std::size_t>(j)], j) = 1.0;
  if (d > 0) base_lu.solve_in_place(W_);
  Matrix Z = Matrix::Zero(n, Q_.cols());
  for (std::size_t a = 0; a < kept_.size(); ++a) Z.row(kept_[a]) = Q_.row(static_cast<Index>(a));
  if (Z.cols() > 0) base_lu.solve_in_place(Z);
  factor_small_blocks(Z);
}

BorderedLU::BorderedLU(const Matrix& base, const DenseLU& base_lu, std::vector<Index> kept, Matrix W, Matrix Q,
                       Matrix R, Matrix T, Matrix Z)
    : base_(&base), base_lu_(&base_lu), kept_(std::move(kept)), dropped_(not_kept(base.rows(), kept_)),
      W_(std::move(W)), Q_(std::move(Q)), R_(std::move(R)), T_(std::move(T)) {
  if (W_.rows() != base.rows() || W_.cols() != static_cast<Index>(dropped_.size()) || Z.rows() != base.rows() ||
      Z.cols() != Q_.cols())
    throw std::logic_error("BorderedLU: solves of the wrong size");
  factor_small_blocks(Z);
}

void BorderedLU::factor_small_blocks(const Matrix& Z) {
  const Index d = static_cast<Index>(dropped_.size());
  if (d > 0) {
    Matrix WD(d, d);
    for (Index i = 0; i < d; ++i) WD.row(i) = W_.row(dropped_[static_cast<std::size_t>(i)]);
    dropped_lu_ = DenseLU(std::move(WD), "the dropped block of an updated Newton system");
  }
  const Index m = T_.rows();
  if (m > 0) {
    kept_inverse_Q_ = kept_part(Z);
    schur_lu_ = DenseLU(Matrix(T_ - R_ * kept_inverse_Q_), "the Schur complement of an updated Newton system");
  }
}

Matrix BorderedLU::solve_kept(const Matrix& r) const {
  Matrix full = Matrix::Zero(base_->rows(), r.cols());
  for (std::size_t a = 0; a < kept_.size(); ++a) full.row(kept_[a]) = r.row(static_cast<Index>(a));
  base_lu_->solve_in_place(full);
  return kept_part(std::move(full));
}

Matrix BorderedLU::kept_part(Matrix full) const {
  const Index columns = full.cols();
  if (!dropped_.empty()) {
    Matrix zd(static_cast<Index>(dropped_.size()), columns);
    for (std::size_t i = 0; i < dropped_.size(); ++i) zd.row(static_cast<Index>(i)) = full.row(dropped_[i]);
    dropped_lu_.solve_in_place(zd);
    full -= W_ * zd;
  }
  Matrix out(static_cast<Index>(kept_.size()), columns);
  for (std::size_t a = 0; a < kept_.size(); ++a) out.row(static_cast<Index>(a)) = full.row(kept_[a]);
  return out;
}

Vector BorderedLU::solve(const Vector& rhs) const {
  const Index c = static_cast<Index>(kept_.size()), m = T_.rows();
  const Vector y = solve_kept(Matrix(rhs.head(c))).col(0);
  if (m == 0) return y;
  Vector out(c + m);
  out.tail(m) = schur_lu_.solve(rhs.tail(m) - R_ * y);
  out.head(c) = y - kept_inverse_Q_ * out.tail(m);
  return out;
}

Vector BorderedLU::apply(const Vector& z) const {
  const Index c = static_cast<Index>(kept_.size()), m = T_.rows();
  Vector full = Vector::Zero(base_->rows());
  for (Index a = 0; a < c; ++a) full[kept_[static_cast<std::size_t>(a)]] = z[a];
  const Vector product = *base_ * full;
  Vector out(c + m);
  for (Index a = 0; a < c; ++a) out[a] = product[kept_[static_cast<std::size_t>(a)]];
  if (m > 0) {
    out.head(c) += Q_ * z.tail(m);
    out.tail(m) = R_ * z.head(c) + T_ * z.tail(m);
  }
  return out;
}

}  // namespace bemcontact::operators

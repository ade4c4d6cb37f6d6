#include "bemcontact/operators/dense_subspaces.hpp"

#include <algorithm>

namespace bemcontact::operators {

Vector singular_values(const Matrix& a) { return Eigen::JacobiSVD<Matrix>(a).singularValues(); }

RightSingularVectors right_singular_vectors(const Matrix& a) {
  const Eigen::JacobiSVD<Matrix> svd(a, Eigen::ComputeFullV);
  return {svd.singularValues(), svd.matrixV()};
}

Matrix null_space(const Matrix& a, double relative_tolerance, double minimum_scale) {
  if (a.rows() == 0) return Matrix::Identity(a.cols(), a.cols());
  const auto svd = right_singular_vectors(a);
  const double top = svd.values.size() > 0 ? svd.values[0] : 0.0;
  const double floor = relative_tolerance * std::max({top, minimum_scale, 1e-300});
  Index rank = 0;
  for (Index k = 0; k < svd.values.size(); ++k) rank += svd.values[k] > floor;
  return svd.V.rightCols(a.cols() - rank);
}

Matrix column_space(const Matrix& a, double threshold) {
  Eigen::ColPivHouseholderQR<Matrix> qr(a);
  qr.setThreshold(threshold);
  const Index rank = qr.rank();
  return qr.householderQ() * Matrix::Identity(a.rows(), rank);
}

}  // namespace bemcontact::operators

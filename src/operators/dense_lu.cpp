#include "bemcontact/operators/dense_lu.hpp"

#include <lapacke.h>

#include <cmath>
#include <sstream>

#include "bemcontact/core/error.hpp"

namespace bemcontact::operators {

DenseLU::DenseLU(Matrix matrix, const std::string& what, double singular_threshold)
    : factors_(std::move(matrix)) {
  const Index n = factors_.rows();
  if (n != factors_.cols() || n == 0)
    throw SolverError(what + ": the matrix is not square (" + std::to_string(n) + " x " +
                      std::to_string(factors_.cols()) + ")");
  if (!factors_.allFinite())
    throw SolverError(what + ": the matrix holds NaN or infinite entries (bad input data?)");
  column_scale_.resize(n);
  for (Index j = 0; j < n; ++j) {
    const double norm = factors_.col(j).cwiseAbs().maxCoeff();
    if (norm == 0.0) {
      std::ostringstream out;
      out << what << " is singular: unknown " << j << " appears in no equation";
      throw SolverError(out.str());
    }
    column_scale_[j] = 1.0 / norm;
    factors_.col(j) *= column_scale_[j];
  }
  const double anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, '1', n, n, factors_.data(), n);
  pivots_.resize(n);
  const lapack_int info = LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, factors_.data(), n, pivots_.data());
  if (info < 0) throw SolverError(what + ": LAPACK dgetrf rejected its arguments");
  if (info > 0) {
    rcond_ = 0.0;
  } else {
    double rcond = 0.0;
    LAPACKE_dgecon(LAPACK_COL_MAJOR, '1', n, factors_.data(), n, anorm, &rcond);
    rcond_ = rcond;
  }
  if (!(rcond_ >= singular_threshold)) {
    std::ostringstream out;
    out << what << " is singular (reciprocal condition number " << rcond_
        << "): the body can move as a rigid body, or conditions contradict each other. "
           "Prescribe displacements on a boundary or add [[constraint]] entries that fix "
           "both translations and the rotation.";
    throw SolverError(out.str());
  }
}

Vector DenseLU::solve(const Vector& rhs) const {
  Matrix x = rhs;
  solve_in_place(x);
  return x.col(0);
}

void DenseLU::solve_in_place(Matrix& rhs) const {
  const Index n = factors_.rows();
  if (rhs.rows() != n) throw SolverError("DenseLU::solve: right-hand side of wrong size");
  LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', n, rhs.cols(), factors_.data(), n, pivots_.data(),
                 rhs.data(), n);
  for (Index j = 0; j < rhs.cols(); ++j) rhs.col(j).array() *= column_scale_.array();
}

}  // namespace bemcontact::operators

namespace bemcontact::operators {

// A = A_s D^{-1} with D = diag(column_scale), so A^T x = b is A_s^T x = D b.
void DenseLU::solve_transposed_in_place(Matrix& rhs) const {
  const Index n = factors_.rows();
  if (rhs.rows() != n) throw SolverError("DenseLU::solve_transposed: right-hand side of wrong size");
  for (Index j = 0; j < rhs.cols(); ++j) rhs.col(j).array() *= column_scale_.array();
  LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'T', n, rhs.cols(), factors_.data(), n, pivots_.data(), rhs.data(), n);
}

}  // namespace bemcontact::operators

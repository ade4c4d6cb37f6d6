#include "bemcontact/operators/dense_lu.hpp"

#include <cblas.h>
#include <lapacke.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <sstream>

#include "bemcontact/core/error.hpp"

namespace bemcontact::operators {

void use_single_threaded_blas() {
  static std::once_flag once;
  std::call_once(once, [] { openblas_set_num_threads(1); });
}

namespace {

// Right-looking blocked LU with partial pivoting (LAPACK's dgetrf order of operations),
// whose trailing updates run over fixed tiles of columns in parallel. Each tile is
// computed by single-threaded BLAS in the same way whatever the thread count, so the
// factors are bit-identical for every --threads value (OpenBLAS's own threaded dgetrf
// changes its blocking with the thread count). Returns LAPACK's info.
lapack_int factor_in_tiles(Index n, double* a, lapack_int* pivots) {
  constexpr Index panel_width = 128, tile_width = 256;
  const auto at = [&](Index row, Index column) { return a + row + column * n; };
  lapack_int info = 0;
  for (Index k = 0; k < n; k += panel_width) {
    const Index kb = std::min(panel_width, n - k);
    const lapack_int panel_info = LAPACKE_dgetrf(LAPACK_COL_MAJOR, static_cast<lapack_int>(n - k),
                                                 static_cast<lapack_int>(kb), at(k, k), static_cast<lapack_int>(n),
                                                 pivots + k);
    if (panel_info < 0) return panel_info;
    if (panel_info > 0 && info == 0) info = static_cast<lapack_int>(k) + panel_info;
    for (Index i = k; i < k + kb; ++i) pivots[i] += static_cast<lapack_int>(k);
    // The row swaps of the panel on every other column, then U12 and the Schur complement.
    const Index tiles = (n + tile_width - 1) / tile_width;
#pragma omp parallel for schedule(dynamic, 1)
    for (Index t = 0; t < tiles; ++t) {
      Index first = t * tile_width, last = std::min(n, first + tile_width);
      // Skip the panel's own columns (already swapped by dgetrf).
      const auto apply = [&](Index c0, Index c1) {
        if (c1 <= c0) return;
        const auto cols = static_cast<lapack_int>(c1 - c0);
        LAPACKE_dlaswp(LAPACK_COL_MAJOR, cols, at(0, c0), static_cast<lapack_int>(n), static_cast<lapack_int>(k + 1),
                       static_cast<lapack_int>(k + kb), pivots, 1);
        if (c0 < k) return;  // left of the panel: swaps only
        cblas_dtrsm(CblasColMajor, CblasLeft, CblasLower, CblasNoTrans, CblasUnit, static_cast<int>(kb), cols, 1.0,
                    at(k, k), static_cast<int>(n), at(k, c0), static_cast<int>(n));
        if (k + kb < n)
          cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, static_cast<int>(n - k - kb), cols,
                      static_cast<int>(kb), -1.0, at(k + kb, k), static_cast<int>(n), at(k, c0), static_cast<int>(n),
                      1.0, at(k + kb, c0), static_cast<int>(n));
      };
      apply(first, std::min(last, k));
      apply(std::max(first, k + kb), last);
    }
  }
  return info;
}

}  // namespace

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
  use_single_threaded_blas();
  const lapack_int info = factor_in_tiles(n, factors_.data(), pivots_.data());
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
  solve_columns('N', rhs);
  for (Index j = 0; j < rhs.cols(); ++j) rhs.col(j).array() *= column_scale_.array();
}

}  // namespace bemcontact::operators

namespace bemcontact::operators {

// A = A_s D^{-1} with D = diag(column_scale), so A^T x = b is A_s^T x = D b.
void DenseLU::solve_transposed_in_place(Matrix& rhs) const {
  const Index n = factors_.rows();
  if (rhs.rows() != n) throw SolverError("DenseLU::solve_transposed: right-hand side of wrong size");
  for (Index j = 0; j < rhs.cols(); ++j) rhs.col(j).array() *= column_scale_.array();
  solve_columns('T', rhs);
}

// Fixed blocks of right-hand sides in parallel: each column is solved the same way
// whatever the thread count.
void DenseLU::solve_columns(char transpose, Matrix& rhs) const {
  use_single_threaded_blas();
  const Index n = factors_.rows(), columns = rhs.cols();
  constexpr Index block = 16;
  const Index blocks = (columns + block - 1) / block;
#pragma omp parallel for schedule(dynamic, 1) if (blocks > 1 && n >= 200)
  for (Index b = 0; b < blocks; ++b) {
    const Index first = b * block, count = std::min(block, columns - first);
    LAPACKE_dgetrs(LAPACK_COL_MAJOR, transpose, static_cast<lapack_int>(n), static_cast<lapack_int>(count),
                   factors_.data(), static_cast<lapack_int>(n), pivots_.data(), rhs.data() + first * n,
                   static_cast<lapack_int>(n));
  }
}

}  // namespace bemcontact::operators

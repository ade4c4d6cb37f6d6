#include "bemcontact/operators/dense_lu.hpp"

#include <cblas.h>
#include <omp.h>

#include <cstddef>
#include <string>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <sstream>
#include <vector>

#include "bemcontact/core/error.hpp"

// LAPACK's Fortran interface (LP64, gfortran's hidden string lengths last), called in
// OpenBLAS directly (it holds LAPACK): no LAPACKE layer and no liblapacke dependency.
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dlaswp_(const int* n, double* a, const int* lda, const int* k1, const int* k2, const int* ipiv,
             const int* incx);
double dlange_(const char* norm, const int* m, const int* n, const double* a, const int* lda, double* work,
               std::size_t norm_length);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm, double* rcond,
             double* work, int* iwork, int* info, std::size_t norm_length);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info, std::size_t trans_length);
}

namespace bemcontact::operators {

// OpenBLAS's kernel family (DYNAMIC_ARCH builds); weak, so that another BLAS links too.
extern "C" char* openblas_get_corename(void) __attribute__((weak));

// OpenBLAS's threaded build starts its worker threads when it loads, and an idle worker
// spins (sched_yield) for about 2^28 cycles, 0.1 s, before it sleeps: on 2 cores that
// took a core from 12 of 30 runs of the Hertz example (0.11 -> 0.22 s). With BLAS on one
// thread the workers are never used, so they are stopped; weak, for other BLAS builds.
extern "C" int blas_thread_shutdown_(void) __attribute__((weak));

void use_single_threaded_blas() {
  static std::once_flag once;
  std::call_once(once, [] {
    openblas_set_num_threads(1);
    if (blas_thread_shutdown_) blas_thread_shutdown_();
  });
}

std::string blas_core_name() { return openblas_get_corename ? std::string(openblas_get_corename()) : std::string(); }

namespace {

// Right-looking blocked LU with partial pivoting (LAPACK's dgetrf order of operations),
// whose trailing updates run over fixed tiles of columns in parallel. Each tile is
// computed by single-threaded BLAS in the same way whatever the thread count, so the
// factors are bit-identical for every --threads value (OpenBLAS's own threaded dgetrf
// changes its blocking with the thread count). Returns LAPACK's info.
int factor_in_tiles(Index n, double* a, int* pivots, const FractionCallback& progress) {
  constexpr Index panel_width = 128, tile_width = 256;
  const auto at = [&](Index row, Index column) { return a + row + column * n; };
  const int lda = static_cast<int>(n);
  int info = 0;
  for (Index k = 0; k < n; k += panel_width) {
    const Index kb = std::min(panel_width, n - k);
    const int rows = static_cast<int>(n - k), panel_columns = static_cast<int>(kb);
    int panel_info = 0;
    dgetrf_(&rows, &panel_columns, at(k, k), &lda, pivots + k, &panel_info);
    if (panel_info < 0) return panel_info;
    if (panel_info > 0 && info == 0) info = static_cast<int>(k) + panel_info;
    for (Index i = k; i < k + kb; ++i) pivots[i] += static_cast<int>(k);
    // The row swaps of the panel on every other column, then U12 and the Schur complement.
    const Index tiles = (n + tile_width - 1) / tile_width;
#pragma omp parallel for schedule(dynamic, 1)
    for (Index t = 0; t < tiles; ++t) {
      Index first = t * tile_width, last = std::min(n, first + tile_width);
      // Skip the panel's own columns (already swapped by dgetrf).
      const auto apply = [&](Index c0, Index c1) {
        if (c1 <= c0) return;
        const int cols = static_cast<int>(c1 - c0);
        const int k1 = static_cast<int>(k + 1), k2 = static_cast<int>(k + kb), increment = 1;
        dlaswp_(&cols, at(0, c0), &lda, &k1, &k2, pivots, &increment);
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
    if (progress) {  // the flops left are those of the trailing matrix's LU, m^3 of n^3
      const double left = static_cast<double>(n - k - kb) / static_cast<double>(n);
      progress(1.0 - left * left * left);
    }
  }
  return info;
}

}  // namespace

DenseLU::DenseLU(Matrix matrix, const std::string& what, double singular_threshold,
                 const FractionCallback& progress)
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
      throw SolverError(out.str(), {"factorisation"});
    }
    column_scale_[j] = 1.0 / norm;
    factors_.col(j) *= column_scale_[j];
  }
  const int size = static_cast<int>(n);
  const double anorm = dlange_("1", &size, &size, factors_.data(), &size, nullptr, 1);
  pivots_.resize(n);
  use_single_threaded_blas();
  if (progress) progress(0.0);
  const int info = factor_in_tiles(n, factors_.data(), pivots_.data(), progress);
  if (info < 0) throw SolverError(what + ": LAPACK dgetrf rejected its arguments");
  if (info > 0) {
    rcond_ = 0.0;
  } else {
    double rcond = 0.0;
    std::vector<double> work(4 * static_cast<std::size_t>(n));
    std::vector<int> iwork(static_cast<std::size_t>(n));
    int gecon_info = 0;
    dgecon_("1", &size, factors_.data(), &size, &anorm, &rcond, work.data(), iwork.data(), &gecon_info, 1);
    rcond_ = gecon_info == 0 ? rcond : 0.0;
  }
  if (!(rcond_ >= singular_threshold)) {
    std::ostringstream out;
    out << what << " is singular (reciprocal condition number " << rcond_
        << "): the body can move as a rigid body, or conditions contradict each other. "
           "Prescribe displacements on a boundary or add [[constraint]] entries that fix "
           "both translations and the rotation.";
    throw SolverError(out.str(), {"factorisation", -1, rcond_});
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
  if (columns == 0) return;
  // Equal blocks of at most kBlock columns, at least two blocks from two columns (a Newton
  // update's few right-hand sides share the threads): a function of the column count alone.
  // Below about 64 columns a block's triangular solves are bound by reading the factors
  // (n = 6 000, 410 columns, 2 threads: 0.65 s in blocks of 16, 0.31 s in blocks of 103).
  constexpr Index kBlock = 128;
  const Index blocks = std::max<Index>(std::min<Index>(columns, 2), (columns + kBlock - 1) / kBlock);
  const Index block = (columns + blocks - 1) / blocks;
#pragma omp parallel for schedule(dynamic, 1) if (blocks > 1 && n >= 200)
  for (Index b = 0; b < blocks; ++b) {
    const Index first = b * block, count = std::min(block, columns - first);
    const int size = static_cast<int>(n), columns_here = static_cast<int>(count);
    int info = 0;
    dgetrs_(&transpose, &size, &columns_here, factors_.data(), &size, pivots_.data(), rhs.data() + first * n, &size,
            &info, 1);
  }
}

}  // namespace bemcontact::operators

#pragma once
// Dense LU factorisation with partial pivoting (blocked, tiled over OpenMP threads, on
// LAPACK/BLAS kernels: dgetrf panels, dtrsm, dgemm; dgetrs, dgecon),
// with column equilibration so that displacement and traction unknowns, whose units
// differ, weigh alike in the condition estimate.
#include <string>

#include "bemcontact/operators/factorization.hpp"
#include "bemcontact/operators/linear_operator.hpp"
#include "bemcontact/operators/progress.hpp"

namespace bemcontact::operators {

// BLAS runs on one thread (OpenBLAS's threaded kernels change their rounding with the
// thread count); the parallel work is ours, in fixed tiles, so results are the same for
// every thread count. Called by every DenseLU; idempotent.
void use_single_threaded_blas();
// OpenBLAS's kernel family in use ("Haswell", "Cooperlake", ...; OPENBLAS_CORETYPE in the
// environment forces one), or "" for another BLAS; reported in summary.json.
std::string blas_core_name();

class DenseLU : public Factorization {
 public:
  static constexpr double default_singular_threshold = 1e-13;

  DenseLU() = default;
  // Factors a copy of `matrix` (square). Throws SolverError when it is singular to
  // working precision (reciprocal condition below `singular_threshold`); `what` names the
  // system in the message. `progress` hears the fraction of the factorisation's flops
  // done, after each panel of 128 columns (from the calling thread).
  explicit DenseLU(Matrix matrix, const std::string& what = "the boundary element system",
                   double singular_threshold = default_singular_threshold, const FractionCallback& progress = {});

  Index size() const override { return factors_.rows(); }
  Vector solve(const Vector& rhs) const;
  void solve_in_place(Matrix& rhs) const override;  // several right-hand sides
  void solve_transposed_in_place(Matrix& rhs) const override;  // A^T x = rhs
  double reciprocal_condition() const override { return rcond_; }

 private:
  void solve_columns(char transpose, Matrix& rhs) const;

  Matrix factors_;
  Eigen::VectorXi pivots_;
  Vector column_scale_;  // A = A_s D^{-1}: x = D x_s
  double rcond_ = 0.0;
};

}  // namespace bemcontact::operators

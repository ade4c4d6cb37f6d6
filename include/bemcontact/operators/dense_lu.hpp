#pragma once
// Dense LU factorisation with partial pivoting through LAPACK (dgetrf/dgetrs/dgecon),
// with column equilibration so that displacement and traction unknowns, whose units
// differ, weigh alike in the condition estimate.
#include "bemcontact/operators/linear_operator.hpp"

namespace bemcontact::operators {

class DenseLU {
 public:
  DenseLU() = default;
  // Factors a copy of `matrix` (square). Throws SolverError when it is singular to
  // working precision (reciprocal condition below `singular_threshold`); `what` names the
  // system in the message.
  explicit DenseLU(Matrix matrix, const std::string& what = "the boundary element system",
                   double singular_threshold = 1e-13);

  Index size() const { return factors_.rows(); }
  Vector solve(const Vector& rhs) const;
  void solve_in_place(Matrix& rhs) const;  // several right-hand sides
  void solve_transposed_in_place(Matrix& rhs) const;  // A^T x = rhs
  double reciprocal_condition() const { return rcond_; }

 private:
  Matrix factors_;
  Eigen::VectorXi pivots_;
  Vector column_scale_;  // A = A_s D^{-1}: x = D x_s
  double rcond_ = 0.0;
};

}  // namespace bemcontact::operators

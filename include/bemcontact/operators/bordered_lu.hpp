#pragma once
// Solves with a matrix that differs from a factored one in a few rows and columns, through
// the factors it has, at the cost of a few solves with them instead of a new factorisation
// (a semi-smooth Newton iteration whose active sets changed at a few pairs).
//
// With J0 factored and C the indices of J0 kept (in order), the new matrix is
//   J1 = [ J0(C, C)  Q ]
//        [ R         T ]      (the kept block first, then the new rows and columns).
// J0(C, C) is solved as the bordered system [J0 E_D; E_D^T 0] (D the dropped indices):
// z = J0^-1 r~ - W mu, W = J0^-1 E_D, mu = W(D, :)^-1 (J0^-1 r~)(D), r~ = r on C, 0 on D;
// then J1 by the Schur complement of that block, S = T - R J0(C, C)^-1 Q
// [Golub & Van Loan 2013, 3.2.11; Hager1989]. Cost: |D| + |N| solves with J0's factors
// to set up, two per solve; both small matrices are factored densely.
#include <vector>

#include "bemcontact/core/types.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::operators {

class BorderedLU {
 public:
  // `base` and its factors outlive this; `kept` are indices into base (increasing).
  // Throws SolverError when a small matrix (W(D, :) or S) is singular: J1 is then
  // singular, or too far from J0 for the update (the caller factors J1 itself).
  BorderedLU(const Matrix& base, const DenseLU& base_lu, std::vector<Index> kept, Matrix Q, Matrix R, Matrix T);
  // The same from the solves with the base factors, taken by the caller (successive updates
  // of one factorisation share most of them): W = J0^-1 E_D (D the indices not kept,
  // increasing) and Z = J0^-1 [Q on C; 0 on D].
  BorderedLU(const Matrix& base, const DenseLU& base_lu, std::vector<Index> kept, Matrix W, Matrix Q, Matrix R,
             Matrix T, Matrix Z);

  Index size() const { return static_cast<Index>(kept_.size()) + T_.rows(); }
  // J1^-1 rhs and J1 z, in J1's order (kept, then new).
  Vector solve(const Vector& rhs) const;
  Vector apply(const Vector& z) const;

 private:
  Matrix solve_kept(const Matrix& r) const;  // J0(C, C)^-1 r, column by column
  Matrix kept_part(Matrix full) const;       // the same from full = J0^-1 [r on C; 0 on D]
  void factor_small_blocks(const Matrix& Z);  // W(D, :) and S

  const Matrix* base_ = nullptr;
  const DenseLU* base_lu_ = nullptr;
  std::vector<Index> kept_, dropped_;
  Matrix W_;             // J0^-1 E_D
  DenseLU dropped_lu_;   // of W(D, :)
  Matrix Q_, R_, T_;
  Matrix kept_inverse_Q_;  // J0(C, C)^-1 Q
  DenseLU schur_lu_;       // of S
};

}  // namespace bemcontact::operators

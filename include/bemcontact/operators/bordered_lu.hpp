#pragma once
// Solves with a matrix that differs from a factored one in a few rows and columns, through
// the factors it has, at the cost of a few solves with them instead of a new factorisation
// (a semi-smooth Newton iteration whose active sets changed at a few pairs).
//
// The bordered matrix [J0 G; H^T K] with J0 factored and k border elements, element e a
// column g_e of G, a row h_e of H^T and its entries in the corner K, is solved through the
// Schur complement S = K - H^T X, X = J0^-1 G [Golub & Van Loan 2013, 3.2.11; Hager1989]:
//   S s = g - H^T J0^-1 r,   y = J0^-1 r - X s.
// A matrix J1 = J0 with the indices D dropped and new rows and columns added is the bordered
// matrix of D's unit columns and rows (their corner 0: y_D = 0) and of the new unknowns
// (column: its entries at J0's rows; row: its entries at J0's columns; corner: its entries
// at the new unknowns). S is kept from one set of elements to the next: an element added
// costs its row and column of S (O(n k)) and the caller's solve X_e = J0^-1 g_e, an element
// removed nothing; only S's factorisation (k^3 / 3) is redone.
#include <vector>

#include "bemcontact/core/types.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::operators {

class BorderedLU {
 public:
  // A border column or row: the unit vector e_unit (unit >= 0), or `dense` (J0's size).
  struct Border {
    Index unit = -1;
    Vector dense;
    double dot(const Vector& v) const { return unit >= 0 ? v[unit] : dense.dot(v); }
  };

  // `base` and its factors outlive this.
  BorderedLU(const Matrix& base, const DenseLU& base_lu) : base_(&base), base_lu_(&base_lu) {}

  Index base_size() const { return base_->rows(); }
  Index elements() const { return static_cast<Index>(X_.size()); }
  // Adds an element: its column, solution = J0^-1 column, its row, its corner entries
  // against the elements present (corner_row[j] = K(new, j), corner_column[j] = K(j, new))
  // and its own K(new, new).
  void add(Border column, Vector solution, Border row, const Vector& corner_row, const Vector& corner_column,
           double corner);
  // Keeps the elements whose `keep` is true (elements() entries), in their order.
  void keep_only(const std::vector<bool>& keep);
  // Factors S. Throws SolverError when it is singular: the bordered matrix is then
  // singular, or too far from J0 for the update (the caller factors it itself).
  void factor();
  // [y; s] solving [J0 G; H^T K] [y; s] = [r; g] (after factor()).
  void solve(const Vector& r, const Vector& g, Vector& y, Vector& s) const;
  // [J0 y + G s; H^T y + K s] as out_base, out_border.
  void apply(const Vector& y, const Vector& s, Vector& out_base, Vector& out_border) const;

 private:
  const Matrix* base_ = nullptr;
  const DenseLU* base_lu_ = nullptr;
  std::vector<Border> G_, H_;
  std::vector<Vector> X_;  // J0^-1 g_e
  Matrix K_, S_;
  Vector row_scale_;  // of S, for its factorisation
  DenseLU S_lu_;
};

}  // namespace bemcontact::operators

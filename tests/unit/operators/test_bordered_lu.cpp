// operators::BorderedLU: solving a matrix that differs from a factored one in a few rows
// and columns through the factors, against a direct solve of the new matrix assembled.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/bordered_lu.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::operators {
namespace {

Matrix random_matrix(Index rows, Index cols, std::mt19937_64& engine) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Matrix m(rows, cols);
  for (Index j = 0; j < cols; ++j)
    for (Index i = 0; i < rows; ++i) m(i, j) = uniform(engine);
  return m;
}

}  // namespace

TEST(BorderedLU, SolvesTheUpdatedMatrixAsADirectSolve) {
  std::mt19937_64 engine(7);
  const Index n = 40;
  Matrix base = random_matrix(n, n, engine) + 8.0 * Matrix::Identity(n, n);
  const DenseLU base_lu(base, "the test matrix");
  for (const int dropped : {0, 1, 5}) {
    for (const Index added : {Index(0), Index(1), Index(6)}) {
      std::vector<Index> kept;
      for (Index k = 0; k < n; ++k)
        if (k % 7 != 3 || k / 7 >= dropped) kept.push_back(k);  // drops `dropped` indices
      const Index c = static_cast<Index>(kept.size());
      ASSERT_EQ(c, n - dropped);
      const Matrix Q = random_matrix(c, added, engine), R = random_matrix(added, c, engine);
      const Matrix T = random_matrix(added, added, engine) + 8.0 * Matrix::Identity(added, added);
      Matrix J1(c + added, c + added);
      for (Index a = 0; a < c; ++a)
        for (Index b = 0; b < c; ++b) J1(a, b) = base(kept[static_cast<std::size_t>(a)], kept[static_cast<std::size_t>(b)]);
      J1.topRightCorner(c, added) = Q;
      J1.bottomLeftCorner(added, c) = R;
      J1.bottomRightCorner(added, added) = T;
      const BorderedLU updated(base, base_lu, kept, Q, R, T);
      ASSERT_EQ(updated.size(), c + added);
      const Vector rhs = random_matrix(c + added, 1, engine).col(0);
      const Vector direct = J1.partialPivLu().solve(rhs);
      const Vector z = updated.solve(rhs);
      EXPECT_LT((z - direct).norm(), 1e-11 * direct.norm()) << "dropped " << dropped << ", added " << added;
      EXPECT_LT((updated.apply(z) - J1 * z).norm(), 1e-12 * (J1 * z).norm());
      // The same from the caller's solves: W = J0^-1 E_D, and Z = J0^-1 U - W U(D, :) for the
      // new columns U at every row of J0 (their values at the dropped rows arbitrary).
      std::vector<Index> dropped_rows;
      for (Index k = 0; k < n; ++k)
        if (std::find(kept.begin(), kept.end(), k) == kept.end()) dropped_rows.push_back(k);
      const Index d = static_cast<Index>(dropped_rows.size());
      Matrix W = Matrix::Zero(n, d), U = random_matrix(n, added, engine), UD(d, added);
      for (Index j = 0; j < d; ++j) W(dropped_rows[static_cast<std::size_t>(j)], j) = 1.0;
      for (Index a = 0; a < c; ++a) U.row(kept[static_cast<std::size_t>(a)]) = Q.row(a);
      for (Index j = 0; j < d; ++j) UD.row(j) = U.row(dropped_rows[static_cast<std::size_t>(j)]);
      base_lu.solve_in_place(W);
      Matrix Z = U;
      base_lu.solve_in_place(Z);
      Z -= W * UD;
      const BorderedLU from_solves(base, base_lu, kept, W, Q, R, T, Z);
      EXPECT_LT((from_solves.solve(rhs) - direct).norm(), 1e-11 * direct.norm()) << "dropped " << dropped << ", added " << added;
    }
  }
}

// Dropping an index whose removal leaves the kept block singular is refused (the caller
// factors the new matrix itself).
TEST(BorderedLU, ASingularKeptBlockIsRefused) {
  Matrix base = Matrix::Identity(3, 3);
  base(0, 1) = base(1, 0) = 1.0;  // [[1, 1, 0], [1, 1, 0], [0, 0, 1]] + shift on (2, 2): regular
  base(0, 0) = 2.0;
  const DenseLU base_lu(base, "the test matrix");
  // Kept {1}, a new index whose row and column are 0 with T = 0: J1 = [[1, 0], [0, 0]].
  EXPECT_THROW(BorderedLU(base, base_lu, {1}, Matrix::Zero(1, 1), Matrix::Zero(1, 1), Matrix::Zero(1, 1)),
               SolverError);
}

}  // namespace bemcontact::operators

// operators::BorderedLU: solving a matrix that differs from a factored one in a few rows
// and columns through the factors, against a direct solve of the new matrix assembled;
// its elements kept, removed and added from one update to the next.
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

// J1: the base without the indices `dropped`, with `added` new unknowns (index into U's
// columns) whose columns at the base rows are U, rows at the base columns R, corner T.
struct Update {
  std::vector<Index> dropped, added;
};

Matrix assembled(const Matrix& base, const Matrix& U, const Matrix& R, const Matrix& T, const Update& u,
                 std::vector<Index>& kept) {
  kept.clear();
  for (Index k = 0; k < base.rows(); ++k)
    if (std::find(u.dropped.begin(), u.dropped.end(), k) == u.dropped.end()) kept.push_back(k);
  const Index c = static_cast<Index>(kept.size()), m = static_cast<Index>(u.added.size());
  Matrix J1(c + m, c + m);
  for (Index a = 0; a < c; ++a)
    for (Index b = 0; b < c; ++b) J1(a, b) = base(kept[a], kept[b]);
  for (Index j = 0; j < m; ++j) {
    for (Index a = 0; a < c; ++a) {
      J1(a, c + j) = U(kept[a], u.added[j]);
      J1(c + j, a) = R(u.added[j], kept[a]);
    }
    for (Index i = 0; i < m; ++i) J1(c + i, c + j) = T(u.added[i], u.added[j]);
  }
  return J1;
}

}  // namespace

TEST(BorderedLU, SolvesTheUpdatedMatrixAsADirectSolveAcrossUpdates) {
  std::mt19937_64 engine(7);
  const Index n = 40, candidates = 8;
  const Matrix base = random_matrix(n, n, engine) + 8.0 * Matrix::Identity(n, n);
  const DenseLU base_lu(base, "the test matrix");
  const Matrix U = random_matrix(n, candidates, engine), R = random_matrix(candidates, n, engine);
  const Matrix T = random_matrix(candidates, candidates, engine) + 8.0 * Matrix::Identity(candidates, candidates);
  // Successive sets: elements that stay, go and come back, and an empty update.
  const std::vector<Update> updates = {{{}, {}},        {{3}, {}},          {{}, {2}},         {{3, 10, 17}, {0, 5}},
                                       {{10, 17}, {5, 1, 6}}, {{3, 24, 31}, {0, 1, 2, 7}}, {{}, {}}};
  BorderedLU bordered(base, base_lu);
  // The bordered elements: dropped index (>= 0) or new unknown (-1 - its column).
  std::vector<Index> elements;
  for (const Update& u : updates) {
    std::vector<Index> wanted;
    for (const Index d : u.dropped) wanted.push_back(d);
    for (const Index a : u.added) wanted.push_back(-1 - a);
    std::vector<bool> keep(elements.size());
    std::vector<Index> order;
    for (std::size_t e = 0; e < elements.size(); ++e) {
      keep[e] = std::find(wanted.begin(), wanted.end(), elements[e]) != wanted.end();
      if (keep[e]) order.push_back(elements[e]);
    }
    bordered.keep_only(keep);
    for (const Index w : wanted) {
      if (std::find(order.begin(), order.end(), w) != order.end()) continue;
      const Index k = bordered.elements();
      Vector corner_row = Vector::Zero(k), corner_column = Vector::Zero(k);
      if (w >= 0) {
        Matrix unit = Matrix::Zero(n, 1);
        unit(w, 0) = 1.0;
        base_lu.solve_in_place(unit);
        bordered.add({w, {}}, unit.col(0), {w, {}}, corner_row, corner_column, 0.0);
      } else {
        const Index a = -1 - w;
        for (Index j = 0; j < k; ++j)
          if (order[j] < 0) corner_row[j] = T(a, -1 - order[j]), corner_column[j] = T(-1 - order[j], a);
        Matrix solution = U.col(a);
        base_lu.solve_in_place(solution);
        bordered.add({-1, U.col(a)}, solution.col(0), {-1, R.row(a).transpose()}, corner_row, corner_column, T(a, a));
      }
      order.push_back(w);
    }
    elements = order;
    ASSERT_EQ(bordered.elements(), static_cast<Index>(u.dropped.size() + u.added.size()));
    bordered.factor();
    std::vector<Index> kept;
    const Matrix J1 = assembled(base, U, R, T, u, kept);
    const Index c = static_cast<Index>(kept.size());
    const Vector rhs = random_matrix(J1.rows(), 1, engine).col(0);
    const Vector direct = J1.partialPivLu().solve(rhs);
    // The bordered right-hand side: rhs at the kept rows, 0 at the dropped; the new rows' at
    // their elements, 0 at the dropped elements'.
    Vector r = Vector::Zero(n), g = Vector::Zero(bordered.elements()), y, s;
    for (Index a = 0; a < c; ++a) r[kept[a]] = rhs[a];
    for (std::size_t e = 0; e < elements.size(); ++e)
      if (elements[e] < 0)
        g[static_cast<Index>(e)] =
            rhs[c + (std::find(u.added.begin(), u.added.end(), -1 - elements[e]) - u.added.begin())];
    bordered.solve(r, g, y, s);
    Vector z(J1.rows());
    for (Index a = 0; a < c; ++a) z[a] = y[kept[a]];
    for (std::size_t e = 0; e < elements.size(); ++e) {
      if (elements[e] >= 0) {
        EXPECT_LT(std::abs(y[elements[e]]), 1e-12 * direct.norm());  // a dropped unknown stays 0
        continue;
      }
      z[c + (std::find(u.added.begin(), u.added.end(), -1 - elements[e]) - u.added.begin())] = s[static_cast<Index>(e)];
    }
    EXPECT_LT((z - direct).norm(), 1e-11 * direct.norm()) << "dropped " << u.dropped.size() << ", added " << u.added.size();
    // The bordered product reproduces J1 z at the kept rows and the new rows.
    Vector out_base, out_border;
    bordered.apply(y, s, out_base, out_border);
    const Vector product = J1 * z;
    for (Index a = 0; a < c; ++a) EXPECT_NEAR(out_base[kept[a]], product[a], 1e-12 * product.norm());
    for (std::size_t e = 0; e < elements.size(); ++e)
      if (elements[e] < 0)
        EXPECT_NEAR(out_border[static_cast<Index>(e)],
                    product[c + (std::find(u.added.begin(), u.added.end(), -1 - elements[e]) - u.added.begin())],
                    1e-12 * product.norm());
  }
}

// Dropping an index whose removal leaves the kept block singular is refused (the caller
// factors the new matrix itself).
TEST(BorderedLU, ASingularKeptBlockIsRefused) {
  Matrix base = Matrix::Identity(3, 3);
  base(0, 1) = base(1, 0) = 1.0;
  base(0, 0) = 2.0;  // [[2, 1, 0], [1, 1, 0], [0, 0, 1]]: regular
  const DenseLU base_lu(base, "the test matrix");
  // Index 0 dropped, a new unknown whose row and column are 0 with corner 0: J1 = [[1, 0, 0], [0, 1, 0], [0, 0, 0]].
  BorderedLU bordered(base, base_lu);
  Matrix unit = Matrix::Zero(3, 1);
  unit(0, 0) = 1.0;
  base_lu.solve_in_place(unit);
  bordered.add({0, {}}, unit.col(0), {0, {}}, Vector::Zero(0), Vector::Zero(0), 0.0);
  bordered.add({-1, Vector::Zero(3)}, Vector::Zero(3), {-1, Vector::Zero(3)}, Vector::Zero(1), Vector::Zero(1), 0.0);
  EXPECT_THROW(bordered.factor(), SolverError);
}

}  // namespace bemcontact::operators

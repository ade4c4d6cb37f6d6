// The tiled dense LU: correct, and bit-identical whatever the thread count and however
// often it runs (its tiles call BLAS from several threads at once, which a BLAS build
// that is not thread-safe breaks: OpenBLAS's serial build did, CMakeLists.txt).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::operators {
namespace {

// A well-conditioned nonsymmetric matrix, large enough for several panels and tiles.
Matrix test_matrix(Index n) {
  Matrix a(n, n);
  for (Index j = 0; j < n; ++j)
    for (Index i = 0; i < n; ++i) a(i, j) = std::sin(0.37 * static_cast<double>(i) + 1.3 * static_cast<double>(j)) / static_cast<double>(1 + (i > j ? i - j : j - i));
  a.diagonal().array() += 4.0;
  return a;
}

TEST(OperatorsDenseLU, SolvesAndIsBitIdenticalAcrossThreadsAndRepeats) {
  const Index n = 1500;
  const Matrix a = test_matrix(n);
  const Vector x_true = Vector::LinSpaced(n, -1.0, 2.0);
  const Vector b = a * x_true;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Vector reference = DenseLU(a, "test").solve(b);
  omp_set_num_threads(std::max(2, threads));
  EXPECT_LT((reference - x_true).norm() / x_true.norm(), 1e-12);
  Matrix many(n, 64);  // several right-hand-side blocks, solved in parallel
  for (Index j = 0; j < many.cols(); ++j) many.col(j) = b * (1.0 + static_cast<double>(j));
  Matrix first_many;
  for (int repeat = 0; repeat < 4; ++repeat) {
    const DenseLU lu(a, "test");
    const Vector x = lu.solve(b);
    Matrix x_many = many;
    lu.solve_in_place(x_many);
    EXPECT_LT((x_many.col(63) - 64.0 * x).norm(), 1e-9 * x.norm());
    if (repeat == 0) first_many = x_many;
    EXPECT_EQ(0, std::memcmp(x_many.data(), first_many.data(), sizeof(double) * static_cast<std::size_t>(x_many.size())))
        << "repeat " << repeat;
    ASSERT_EQ(0, std::memcmp(x.data(), reference.data(), sizeof(double) * static_cast<std::size_t>(n)))
        << "repeat " << repeat << ": largest difference " << (x - reference).cwiseAbs().maxCoeff();
  }
  omp_set_num_threads(threads);
}

}  // namespace
}  // namespace bemcontact::operators

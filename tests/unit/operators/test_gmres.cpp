// GMRES(m) against dense LU on small matrices, with the failure modes it must report.
#include <gtest/gtest.h>

#include <random>

#include "bemcontact/operators/gmres.hpp"

namespace bemcontact::operators {
namespace {

Matrix random_matrix(Index n, unsigned seed, double diagonal) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Matrix A(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) A(i, j) = normal(generator) / std::sqrt(static_cast<double>(n));
  A.diagonal().array() += diagonal;
  return A;
}

TEST(OperatorsGmres, FullGmresSolvesANonsymmetricSystemToTheTolerance) {
  const Matrix A = random_matrix(40, 1, 2.0);
  const Vector x_exact = Vector::LinSpaced(40, -1.0, 1.0);
  const Vector b = A * x_exact;
  GmresOptions options;
  options.restart = 40;
  options.tolerance = 1e-12;
  const auto result = gmres(DenseOperator(A), b, options);
  ASSERT_TRUE(result.converged()) << result.message;
  // Backward-stable: error <= cond * tolerance; cond(A) here is about 3 (shifted random).
  EXPECT_LT((result.x - x_exact).norm() / x_exact.norm(), 1e-10);
  EXPECT_LT(result.relative_residual, 1e-12);
  EXPECT_LE(result.iterations, 40);
  // The history starts at 1 and never grows (GMRES minimises the residual).
  ASSERT_EQ(result.residual_history.front(), 1.0);
  for (std::size_t k = 1; k < result.residual_history.size(); ++k)
    EXPECT_LE(result.residual_history[k], result.residual_history[k - 1] * (1 + 1e-12));
}

TEST(OperatorsGmres, RestartedGmresConvergesOnAWellConditionedSystem) {
  const Matrix A = random_matrix(60, 2, 3.0);
  const Vector b = Vector::Ones(60);
  GmresOptions options;
  options.restart = 5;
  options.tolerance = 1e-10;
  const auto result = gmres(DenseOperator(A), b, options);
  ASSERT_TRUE(result.converged()) << result.message;
  EXPECT_GT(result.restarts, 0);
  EXPECT_LT((A * result.x - b).norm() / b.norm(), 1e-10);
}

TEST(OperatorsGmres, ExactInKSteps) {
  // A matrix with 3 distinct eigenvalues: full GMRES is exact after 3 steps.
  Matrix A = Matrix::Zero(30, 30);
  for (Index i = 0; i < 30; ++i) A(i, i) = 1.0 + (i % 3);
  const auto result = gmres(DenseOperator(A), Vector::Ones(30), GmresOptions{});
  ASSERT_TRUE(result.converged()) << result.message;
  EXPECT_EQ(result.iterations, 3);
}

TEST(OperatorsGmres, StagnationIsReportedNotLooped) {
  // The cyclic shift: GMRES(m) with m < n makes no progress at all from x0 = 0 on b = e1
  // (the classic stagnation example), so it must stop with status stagnated.
  const Index n = 20;
  Matrix A = Matrix::Zero(n, n);
  for (Index i = 0; i < n; ++i) A((i + 1) % n, i) = 1.0;
  Vector b = Vector::Zero(n);
  b[0] = 1.0;
  GmresOptions options;
  options.restart = 5;
  options.max_iterations = 10000;
  const auto result = gmres(DenseOperator(A), b, options);
  EXPECT_EQ(result.status, GmresStatus::stagnated);
  EXPECT_LT(result.iterations, 100);
  EXPECT_NE(result.message.find("stagnated"), std::string::npos);
  EXPECT_NEAR(result.relative_residual, 1.0, 1e-12);
}

TEST(OperatorsGmres, IterationBudgetIsReported) {
  const Matrix A = random_matrix(80, 3, 0.5);  // eigenvalues near 0: slow
  GmresOptions options;
  options.restart = 10;
  options.max_iterations = 7;
  const auto result = gmres(DenseOperator(A), Vector::Ones(80), options);
  EXPECT_EQ(result.status, GmresStatus::max_iterations);
  EXPECT_EQ(result.iterations, 7);
  EXPECT_GT(result.relative_residual, options.tolerance);
  EXPECT_NE(result.message.find("not converged"), std::string::npos);
}

TEST(OperatorsGmres, SingularOperatorBreaksDownWithAMessage) {
  // b outside the range of a singular A: the Krylov space becomes invariant while the
  // residual stays finite.
  Matrix A = Matrix::Zero(4, 4);
  A(0, 0) = 1.0;
  A(1, 1) = 2.0;
  Vector b = Vector::Ones(4);
  const auto result = gmres(DenseOperator(A), b, GmresOptions{});
  EXPECT_EQ(result.status, GmresStatus::breakdown) << result.message;
  EXPECT_NEAR(result.relative_residual, std::sqrt(2.0) / 2.0, 1e-12);
}

TEST(OperatorsGmres, ZeroRightHandSideGivesZero) {
  const auto result = gmres(DenseOperator(Matrix::Identity(3, 3)), Vector::Zero(3), GmresOptions{});
  EXPECT_TRUE(result.converged());
  EXPECT_EQ(result.x.norm(), 0.0);
  EXPECT_EQ(result.iterations, 0);
}

}  // namespace
}  // namespace bemcontact::operators

// Gauss-Legendre and log-weighted Gauss rules: exactness on monomials (the defining
// property), symmetry, known values, and thread safety of the cache.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::quadrature {
namespace {

// int_{-1}^{1} x^k dx, summed in long double to keep the check itself exact.
long double legendre_moment(int k) { return k % 2 ? 0.0L : 2.0L / (k + 1); }

TEST(QuadratureGaussLegendre, ExactForDegreeUpTo2nMinus1) {
  for (int n : {1, 2, 3, 4, 5, 8, 12, 16, 20, 24, 32, 48, 64}) {
    const Rule& rule = gauss_legendre(n);
    ASSERT_EQ(rule.size(), n);
    // Monomials up to degree 2n-1 on [0, 1] (x -> (1+x)/2) keep the integrals O(1/k), so
    // round-off stays ~1e-16 relative; the moments are 1/(k+1).
    for (int k = 0; k < 2 * n; ++k) {
      long double sum = 0.0L;
      for (int i = 0; i < n; ++i)
        sum += 0.5L * rule.weights[i] * std::pow(0.5L * (1.0L + rule.nodes[i]), k);
      EXPECT_NEAR(static_cast<double>(sum * (k + 1)), 1.0, 4e-15) << "n=" << n << " k=" << k;
    }
    // Degree 2n is not exact: the error on x^{2n} is the classical remainder
    // 2^{2n+1} (n!)^4 / ((2n+1) ((2n)!)^2), checked for the small orders where it is above
    // round-off (the rule is exactly as good as claimed, not better).
    if (n <= 8) {
      long double sum = 0.0L, remainder = std::pow(2.0L, 2 * n + 1) / (2 * n + 1);
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(static_cast<long double>(rule.nodes[i]), 2 * n);
      for (int k = 1; k <= n; ++k) remainder *= static_cast<long double>(k) * k / ((n + k) * (n + k));
      EXPECT_NEAR(static_cast<double>((legendre_moment(2 * n) - sum) / remainder), 1.0, 1e-8) << n;
    }
  }
}

TEST(QuadratureGaussLegendre, SymmetricIncreasingAndKnownValues) {
  for (int n : {1, 2, 7, 10, 33, 100, 200}) {
    const Rule& rule = gauss_legendre(n);
    double weight_sum = 0.0;
    for (int i = 0; i < n; ++i) {
      EXPECT_DOUBLE_EQ(rule.nodes[i], -rule.nodes[n - 1 - i]);
      EXPECT_DOUBLE_EQ(rule.weights[i], rule.weights[n - 1 - i]);
      if (i > 0) EXPECT_LT(rule.nodes[i - 1], rule.nodes[i]);
      weight_sum += rule.weights[i];
    }
    EXPECT_NEAR(weight_sum, 2.0, 1e-14);
  }
  // Closed forms: n = 2: +-1/sqrt3, weights 1; n = 3: 0, +-sqrt(3/5), weights 8/9, 5/9.
  EXPECT_NEAR(gauss_legendre(2).nodes[1], 1.0 / std::sqrt(3.0), 2e-16);
  EXPECT_NEAR(gauss_legendre(3).nodes[2], std::sqrt(0.6), 2e-16);
  EXPECT_NEAR(gauss_legendre(3).weights[1], 8.0 / 9.0, 2e-16);
  // A smooth integrand converges to round-off: int_{-1}^{1} cos(3x) dx = 2 sin(3)/3.
  const Rule& rule = gauss_legendre(200);
  double sum = 0.0;
  for (int i = 0; i < rule.size(); ++i) sum += rule.weights[i] * std::cos(3.0 * rule.nodes[i]);
  EXPECT_NEAR(sum, 2.0 * std::sin(3.0) / 3.0, 1e-14);
}

TEST(QuadratureGaussLog, ExactForDegreeUpTo2nMinus1) {
  // int_0^1 t^k ln(1/t) dt = 1/(k+1)^2.
  for (int n : {1, 2, 3, 4, 6, 8, 12, 16, 20, 24, 32, 40}) {
    const Rule& rule = gauss_log(n);
    ASSERT_EQ(rule.size(), n);
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(rule.nodes[i], 0.0);
      EXPECT_LT(rule.nodes[i], 1.0);
      EXPECT_GT(rule.weights[i], 0.0);
    }
    for (int k = 0; k < 2 * n; ++k) {
      long double sum = 0.0L;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(static_cast<long double>(rule.nodes[i]), k);
      EXPECT_NEAR(static_cast<double>(sum * (k + 1) * (k + 1)), 1.0, 1e-14) << "n=" << n << " k=" << k;
    }
  }
  // Known one-point rule: node 1/4, weight 1.
  EXPECT_NEAR(gauss_log(1).nodes[0], 0.25, 1e-16);
  EXPECT_NEAR(gauss_log(1).weights[0], 1.0, 1e-16);
}

TEST(QuadratureGaussLog, SmoothIntegrandToRoundOff) {
  // int_0^1 cos(t) ln(1/t) dt = Si(1) (integration by parts): Si(1) = 0.946083070367183...
  const Rule& rule = gauss_log(12);
  double sum = 0.0;
  for (int i = 0; i < rule.size(); ++i) sum += rule.weights[i] * std::cos(rule.nodes[i]);
  EXPECT_NEAR(sum, 0.94608307036718301494, 2e-16);
}

TEST(QuadratureRules, CacheIsThreadSafe) {
  // Several threads ask for the same fresh orders at once; all must see one rule.
  const std::vector<int> orders = {41, 57, 77, 129, 301};
  std::vector<std::vector<const Rule*>> seen(8);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int n : orders) {
        seen[t].push_back(&gauss_legendre(n));
        seen[t].push_back(&gauss_log(n > 100 ? 50 : n));
      }
    });
  for (auto& thread : threads) thread.join();
  for (int t = 1; t < 8; ++t) EXPECT_EQ(seen[t], seen[0]);
  for (const Rule* rule : seen[0]) {
    double sum = 0.0;
    for (double w : rule->weights) sum += w;
    EXPECT_TRUE(std::abs(sum - 2.0) < 1e-13 || std::abs(sum - 1.0) < 1e-13);
  }
}

}  // namespace
}  // namespace bemcontact::quadrature

// The ring integrals H(p, j) = int_0^{pi/2} cos^{2j} psi (1 - m sin^2 psi)^{-(p+1/2)} dpsi
// against a graded long-double Gauss-Legendre quadrature of the definition, over the whole
// range of m (trapezoid branch, K/E-recurrence branch, m -> 1), and their logarithmic parts
// against the K/E route.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "bemcontact/kernels/elliptic.hpp"
#include "bemcontact/kernels/ring_integrals.hpp"

namespace bemcontact::kernels {
namespace {

using Real = long double;
constexpr Real pi_long = std::numbers::pi_v<Real>;

struct LongGauss {
  std::vector<Real> x, w;  // on [0, 1]
  explicit LongGauss(int n) : x(n), w(n) {
    for (int i = 0; i < n; ++i) {
      Real z = std::cos(pi_long * (i + 0.75L) / (n + 0.5L)), dp = 1.0L;
      for (int it = 0; it < 100; ++it) {
        Real p0 = 1.0L, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const Real p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0L);
        const Real step = p1 / dp;
        z -= step;
        if (std::abs(step) < 1e-19L) break;
      }
      x[i] = 0.5L * (1.0L - z);
      w[i] = 1.0L / ((1.0L - z * z) * dp * dp);
    }
  }
};
const LongGauss kGauss(24);

// With phi = pi/2 - psi: H = int_0^{pi/2} sin^{2j} phi (m1 + m sin^2 phi)^{-q} dphi, whose
// peak at phi = 0 has width sqrt(m1): pieces doubling from 1e-3 sqrt(m1) up to pi/2.
Real reference_h(Real m, Real m1, int p, int j) {
  const Real q = p + 0.5L;
  auto integrand = [&](Real phi) {
    const Real s2 = std::sin(phi) * std::sin(phi);
    return std::pow(s2, j) * std::pow(m1 + m * s2, -q);
  };
  std::vector<Real> cuts = {0.0L};
  for (Real c = 1e-3L * std::sqrt(m1); c < pi_long / 2; c *= 2) cuts.push_back(c);
  cuts.push_back(pi_long / 2);
  Real sum = 0.0L;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const Real a = cuts[k], h = cuts[k + 1] - cuts[k];
    for (size_t i = 0; i < kGauss.x.size(); ++i) sum += h * kGauss.w[i] * integrand(a + h * kGauss.x[i]);
  }
  return sum;
}

TEST(KernelsRingIntegrals, MatchDefinitionOverWholeRange) {
  std::vector<double> m1_values;
  for (double m = 0.0; m < 0.95; m += 0.025) m1_values.push_back(1.0 - m);
  for (double m1 = 0.05; m1 > 1e-13; m1 /= 3.0) m1_values.push_back(m1);
  for (double m : {0.19999, 0.20001, 0.44999, 0.45001, 1e-3, 1e-6}) m1_values.push_back(1.0 - m);
  double worst = 0.0;
  for (double m1 : m1_values) {
    const double m = 1.0 - m1;  // both exact doubles here, consistent with each other
    for (int max_p : {2, 3}) {  // the branch switch depends on the highest p asked for
      RingIntegrals h;
      ring_integrals(m, m1, max_p, h);
      for (int p = 0; p <= max_p; ++p)
        for (int j = 0; j <= p + 1; ++j) {
          const Real ref = reference_h(m, m1, p, j);
          const double error = static_cast<double>(std::abs((h.h[p][j] - ref) / ref));
          worst = std::max(worst, error);
          // The K/E recurrences divide by m once per level of j: ~m^-(p+1) ulp, 8e-14 at the
          // switch (m = 0.2 for p <= 2, 0.45 for p = 3); the trapezoid branch stays near 1e-15.
          EXPECT_LT(error, 1e-13) << "m=" << m << " m1=" << m1 << " p=" << p << " j=" << j;
        }
    }
  }
  std::printf("  ring integrals H(p,j), p<=3: max relative error %.2e\n", worst);
}

// H(p, j) = alpha K + beta E, with (alpha, beta) from the same recurrences applied to the
// basis vectors; the log part is then alpha K_log + beta E_log (K_log, E_log checked in
// test_elliptic.cpp against the A&S series). Long double for the moderate m1 used, where
// the cancellation of the leading poles costs at most m1^-3.
TEST(KernelsRingIntegrals, LogPartsMatchEllipticDecomposition) {
  for (double m1 : {0.5, 0.3, 0.1, 0.03}) {
    const Real m = 1.0L - m1;
    using Pair = std::array<Real, 2>;  // coefficients of (K, E)
    Pair H[kRingMaxP + 1][kRingMaxP + 2];
    Pair previous = {0, 1}, current = {1, 0};
    for (int p = 0; p <= kRingMaxP; ++p) {
      H[p][0] = current;
      const Real q = p + 0.5L;
      Pair next;
      for (int c = 0; c < 2; ++c)
        next[c] = ((2 * q - 1) * (1 + m1) * current[c] - (2 * q - 2) * previous[c]) / (2 * q * m1);
      previous = current;
      current = next;
    }
    for (int c = 0; c < 2; ++c) H[0][1][c] = ((c == 1 ? 1.0L : 0.0L) - m1 * H[0][0][c]) / m;
    for (int p = 1; p <= kRingMaxP; ++p)
      for (int j = 1; j <= p + 1; ++j)
        for (int c = 0; c < 2; ++c) H[p][j][c] = (H[p - 1][j - 1][c] - m1 * H[p][j - 1][c]) / m;
    const EllipticLogSplit split = elliptic_log_split(static_cast<double>(m), m1);
    RingIntegrals log_parts;
    ring_integral_log_parts(m1, kRingMaxP, log_parts);
    for (int p = 0; p <= kRingMaxP; ++p)
      for (int j = 0; j <= p + 1; ++j) {
        const Real ref = H[p][j][0] * split.K_log + H[p][j][1] * split.E_log;
        // split.*_log carry 1e-16 relative; the pole cancellation multiplies by <= m1^-p.
        const double tolerance = 1e-15 * std::pow(1.0 / m1, p) * 4;
        EXPECT_NEAR(static_cast<double>(log_parts.h[p][j] / ref), 1.0, tolerance)
            << "m1=" << m1 << " p=" << p << " j=" << j;
      }
  }
  // H(0, 0) = K exactly, so its log part is K(m1)/pi at any m1.
  for (double m1 : {1e-10, 1e-3, 0.2, 0.5}) {
    RingIntegrals log_parts;
    ring_integral_log_parts(m1, 0, log_parts);
    EXPECT_NEAR(log_parts.h[0][0] / (complete_elliptic(m1, 1.0 - m1).K / std::numbers::pi), 1.0, 1e-15);
  }
}

TEST(KernelsRingIntegrals, RegularPartHasNoLogarithm) {
  // H - H_log ln(1/m1) is a Laurent polynomial (pole m1^{j-p}) plus an analytic function,
  // so r(m1) = m1^{p-j} (H - H_log ln(1/m1)) (p > j) or H - H_log ln(1/m1) (p <= j) is
  // analytic at 0: its values at m1 = h, 2h, 4h, 8h fit a cubic to O(h^4). A leftover
  // c m1^k ln m1 would break that fit by ~c h^k ln 2.
  for (int p = 0; p <= kRingMaxP; ++p)
    for (int j = 0; j <= p + 1; ++j) {
      const double h = 1e-4;
      double r[4];
      for (int k = 0; k < 4; ++k) {
        const double m1 = h * (1 << k);
        RingIntegrals value, log_parts;
        ring_integrals(1.0 - m1, m1, p, value);
        ring_integral_log_parts(m1, p, log_parts);
        const double regular = value.h[p][j] - log_parts.h[p][j] * std::log(1.0 / m1);
        r[k] = regular * std::pow(m1, std::max(p - j, 0));
      }
      // Third differences on the geometric grid: for a cubic a + b x + c x^2 + d x^3 the
      // combination below vanishes; for x ln x it is ~h.
      const double d1 = r[1] - r[0], d2 = r[2] - r[1], d3 = r[3] - r[2];
      const double combination = (d3 - 6 * d2 + 8 * d1);  // kills b x and c x^2 terms
      const double scale = std::abs(r[0]) + 1.0;
      EXPECT_LT(std::abs(combination) / scale, 1e-9) << "p=" << p << " j=" << j;
    }
}

}  // namespace
}  // namespace bemcontact::kernels

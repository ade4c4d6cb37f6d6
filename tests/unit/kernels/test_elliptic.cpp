// Complete elliptic integrals by the AGM against independent long-double references:
// the Maclaurin series in m for m <= 1/2, the logarithmic series in m1 = 1 - m
// ([AbramowitzStegun1972, 17.3.34, 17.3.36]) for m >= 1/2, and closed-form values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/kernels/elliptic.hpp"

namespace bemcontact::kernels {
namespace {

using Real = long double;
constexpr Real pi_l = std::numbers::pi_v<Real>;

// K = pi/2 sum [(1/2)_n / n!]^2 m^n,  E = pi/2 sum [(1/2)_n / n!]^2 m^n / (1 - 2n).
void maclaurin(Real m, Real& K, Real& E) {
  Real c = 1.0L;
  K = E = 0.0L;
  for (int n = 0; n < 200; ++n) {
    K += c;
    E += c / (1 - 2 * n);
    c *= m * (n + 0.5L) * (n + 0.5L) / ((n + 1.0L) * (n + 1.0L));
  }
  K *= pi_l / 2;
  E *= pi_l / 2;
}

// Near m = 1, with L = ln(4 / sqrt(m1)) and h_n = sum_{j<=n} 1/((2j-1) 2j):
//   K = sum_n [(1/2)_n/n!]^2 m1^n (L - 2 h_n)                                (A&S 17.3.34)
//   E = 1 + sum_{n>=1} c_n m1^n (L - 2 h_{n-1} - 1/((2n-1) 2n)),
//       c_1 = 1/2, c_{n+1}/c_n = (2n-1)(2n+1)/(2n (2n+2))                    (A&S 17.3.36)
// The coefficients of L are the log parts: sum [(1/2)_n/n!]^2 m1^n = (2/pi) K(m1) and
// sum c_n m1^n = (2/pi)(K(m1) - E(m1)).
void log_series(Real m1, Real& K, Real& E, Real& K_log_part, Real& E_log_part) {
  const Real L = std::log(4.0L / std::sqrt(m1));
  Real cK = 1.0L, cE = 0.5L, h = 0.0L, power = 1.0L;
  K = 0.0L;
  E = 1.0L;
  K_log_part = E_log_part = 0.0L;
  for (int n = 0; n < 400; ++n) {
    K += cK * power * (L - 2 * h);
    K_log_part += cK * power;
    if (n >= 1) {
      E += cE * power * (L - 2 * (h - 1.0L / ((2.0L * n - 1) * 2 * n)) - 1.0L / ((2.0L * n - 1) * 2 * n));
      E_log_part += cE * power;
      cE *= (2.0L * n - 1) * (2.0L * n + 1) / ((2.0L * n) * (2.0L * n + 2));
    }
    cK *= (n + 0.5L) * (n + 0.5L) / ((n + 1.0L) * (n + 1.0L));
    h += 1.0L / ((2.0L * n + 1) * (2.0L * n + 2));
    power *= m1;
  }
}

double relative(double value, Real reference) {
  return static_cast<double>(std::abs((value - reference) / reference));
}

TEST(KernelsElliptic, MaclaurinRange) {
  double worst = 0.0;
  for (int i = 0; i <= 100; ++i) {
    const Real m = 0.5L * i / 100;
    Real K, E;
    maclaurin(m, K, E);
    const CompleteElliptic v = complete_elliptic(static_cast<double>(m), static_cast<double>(1.0L - m));
    worst = std::max({worst, relative(v.K, K), relative(v.E, E)});
  }
  EXPECT_LT(worst, 1e-15);  // a few ulp: the AGM does ~5 roundings
}

TEST(KernelsElliptic, LogarithmicRangeDownToTinyComplement) {
  double worst_K = 0.0, worst_E = 0.0;
  for (int i = 0; i <= 150; ++i) {
    // m1 = 0.5 ... 1e-15 geometrically, m formed from the double m1 as a caller would.
    const double m1 = 0.5 * std::pow(2e-15, i / 150.0);
    const double m = 1.0 - m1;
    Real K, E, K_log, E_log;
    log_series(m1, K, E, K_log, E_log);
    const CompleteElliptic v = complete_elliptic(m, m1);
    worst_K = std::max(worst_K, relative(v.K, K));
    worst_E = std::max(worst_E, relative(v.E, E));
  }
  EXPECT_LT(worst_K, 1e-15);
  EXPECT_LT(worst_E, 1e-15);
  std::printf("  elliptic, m1 in [1e-15, 0.5]: max relative error K %.2e  E %.2e\n", worst_K, worst_E);
}

TEST(KernelsElliptic, ClosedFormValues) {
  // K(0) = E(0) = pi/2, E(1) = 1, K(1/2) = Gamma(1/4)^2 / (4 sqrt(pi)) and the Legendre
  // relation at m = 1/2: 2 E K - K^2 = pi/2.
  const double pi = std::numbers::pi;
  EXPECT_NEAR(complete_elliptic(0.0, 1.0).K, pi / 2, 2e-16);
  EXPECT_NEAR(complete_elliptic(0.0, 1.0).E, pi / 2, 2e-16);
  EXPECT_NEAR(complete_elliptic(1.0, 0.0).E, 1.0, 1e-15);
  const Real gamma_quarter = 3.62560990822190831193068515586767200L;
  const Real K_half = gamma_quarter * gamma_quarter / (4.0L * std::sqrt(pi_l));
  const CompleteElliptic half = complete_elliptic(0.5, 0.5);
  EXPECT_LT(relative(half.K, K_half), 5e-16);
  EXPECT_LT(relative(half.E, (pi_l / 2 + K_half * K_half) / (2 * K_half)), 5e-16);
  // Symmetric case m = m1 = 1/2 via the convenience wrappers.
  EXPECT_DOUBLE_EQ(elliptic_k(0.5), half.K);
  EXPECT_DOUBLE_EQ(elliptic_e(0.5), half.E);
}

TEST(KernelsElliptic, LogSplitMatchesSeriesCoefficients) {
  // K_log = K(m1)/pi must equal half the coefficient of L = ln(4/sqrt m1) = ln 4 + ln(1/m1)/2
  // in the series, and K_reg = K - K_log ln(1/m1) its remaining part; same for E.
  for (double m1 : {0.5, 0.2, 1e-2, 1e-4, 1e-8, 1e-12}) {
    Real K, E, K_log_part, E_log_part;
    log_series(m1, K, E, K_log_part, E_log_part);
    const EllipticLogSplit split = elliptic_log_split(1.0 - m1, m1);
    EXPECT_LT(relative(split.K_log, K_log_part / 2), 1e-15) << m1;
    EXPECT_LT(relative(split.E_log, E_log_part / 2), 2e-15) << m1;
    const Real K_reg = K - K_log_part / 2 * std::log(1.0L / m1);
    const Real E_reg = E - E_log_part / 2 * std::log(1.0L / m1);
    // Absolute: the regular parts are O(1) and the subtraction cancels up to ~K.
    EXPECT_NEAR(split.K_reg, static_cast<double>(K_reg), 1e-14) << m1;
    EXPECT_NEAR(split.E_reg, static_cast<double>(E_reg), 1e-14) << m1;
  }
  const EllipticLogSplit limit = elliptic_log_split(1.0 - 1e-14, 1e-14);
  EXPECT_NEAR(limit.K_reg, std::log(4.0), 1e-12);
  EXPECT_NEAR(limit.E_reg, 1.0, 1e-12);
}

}  // namespace
}  // namespace bemcontact::kernels

// Spence's stick ratio (Annex E): the bimaterial constant (E.2), the elliptic integral K1,
// and the root of (E.1), checked against an independent quadrature of K, the residual of
// (E.1) at the returned root, and the values of the thesis case (V.5.2.4).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "bemcontact/core/error.hpp"
#include "bemcontact/reference/spence.hpp"

namespace ref = bemcontact::reference;
using bemcontact::AnalysisType;
using bemcontact::Material;

namespace {

// K(k) = int_0^{pi/2} dtheta / sqrt(1 - k^2 sin^2 theta) by the trapezoidal rule, which
// converges geometrically for this smooth periodic integrand; 4000 panels reach round-off
// for k up to sqrt(1 - 0.05^2).
double elliptic_k_by_quadrature(double k) {
  const int n = 4000;
  const double h = 0.5 * std::numbers::pi / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double s = std::sin(i * h);
    const double f = 1.0 / std::sqrt(1.0 - k * k * s * s);
    sum += (i == 0 || i == n) ? 0.5 * f : f;
  }
  return h * sum;
}

const Material carbide_ball{432000.0, 0.32};
const Material aluminium{72000.0, 0.32};

}  // namespace

TEST(ReferenceSpence, BimaterialConstantOfTheThesisCase) {
  // (E.2) with the ball first: -0.18908 (V.5.2.4 prints 0.18908); odd under swapping.
  const double gamma = ref::spence_gamma(carbide_ball, aluminium);
  EXPECT_NEAR(gamma, -0.18908, 5e-6);
  EXPECT_DOUBLE_EQ(ref::spence_gamma(aluminium, carbide_ball), -gamma);
  // By hand, same nu in both bodies: gamma = (1 - 2nu)(c1 - c2) / (2 (1 - nu)(c1 + c2)),
  // c_i = 1/G_i.
  const double c1 = 1.0 / carbide_ball.shear_modulus(), c2 = 1.0 / aluminium.shear_modulus();
  EXPECT_NEAR(gamma, 0.36 * (c1 - c2) / (2 * 0.68 * (c1 + c2)), 1e-15);
  // Identical bodies: no coupling.
  EXPECT_EQ(ref::spence_gamma(aluminium, aluminium), 0.0);
  // Rigid indenter, (E.3): |gamma| = (1 - 2nu) / (2 (1 - nu)).
  const Material rigid{std::numeric_limits<double>::infinity(), 0.3};
  EXPECT_NEAR(ref::spence_gamma(rigid, aluminium), -(1 - 0.64) / (2 * 0.68), 1e-15);
  // Plane stress: nu -> nu/(1+nu) (rigid punch, nu = 0.48 -> 0.26).
  const double nubar = 0.48 / 1.48;
  EXPECT_NEAR(ref::spence_gamma(rigid, Material{6.89, 0.48}, AnalysisType::plane_stress),
              -(1 - 2 * nubar) / (2 * (1 - nubar)), 1e-15);
}

TEST(ReferenceSpence, ComplementaryEllipticIntegralMatchesQuadrature) {
  for (double c : {0.05, 0.2, 0.53, 0.9, 0.9999}) {
    const double k = std::sqrt(1.0 - c * c);
    EXPECT_NEAR(ref::complementary_elliptic_k(c), elliptic_k_by_quadrature(k), 1e-13) << c;
  }
  EXPECT_NEAR(ref::complementary_elliptic_k(1.0), std::numbers::pi / 2, 1e-15);
  // Near c = 0: K1 ~ ln(4 / c).
  EXPECT_NEAR(ref::complementary_elliptic_k(1e-20), std::log(4e20), 1e-12);
}

TEST(ReferenceSpence, StickRatioOfTheThesisCase) {
  const double gamma = 0.18908;
  const double c1 = ref::spence_stick_ratio(0.1, gamma);
  const double c6 = ref::spence_stick_ratio(0.6, gamma);
  // Printed precision: 0.530 and 0.9999.
  EXPECT_NEAR(c1, 0.530, 5e-4);
  EXPECT_NEAR(c6, 0.9999, 5e-5);
  // The roots satisfy (E.1) to round-off: |beta(c) - beta| <= 1e-12.
  EXPECT_LE(std::abs(ref::spence_friction_coefficient(c1, gamma) - 0.1), 1e-12);
  EXPECT_LE(std::abs(ref::spence_friction_coefficient(c6, gamma) - 0.6), 1e-12);
  // (E.1) evaluated directly, with K from the quadrature above.
  auto beta_direct = [&](double c) {
    return gamma / (2 * c * elliptic_k_by_quadrature(std::sqrt(1 - c * c))) * std::log((1 + c) / (1 - c));
  };
  EXPECT_NEAR(beta_direct(c1), 0.1, 1e-12);
  EXPECT_NEAR(beta_direct(c6), 0.6, 1e-9);  // log((1+c)/(1-c)) loses ~4 digits at 1 - c = 1e-4
  // The sign of gamma (the order of the bodies) does not change c.
  EXPECT_EQ(ref::spence_stick_ratio(0.1, -gamma), c1);
  // gamma from the materials gives the same to the 5 printed digits.
  EXPECT_NEAR(ref::spence_stick_ratio(0.1, ref::spence_gamma(carbide_ball, aluminium)), c1, 1e-4);
}

TEST(ReferenceSpence, RootIsUniqueAndAccurateOverTheWholeRange) {
  // (E.1) increases with c, so one root per beta.
  double previous = 0.0;
  for (int i = 1; i < 1000; ++i) {
    const double beta = ref::spence_friction_coefficient(i / 1000.0, 0.375);
    EXPECT_GT(beta, previous);
    previous = beta;
  }
  for (double gamma : {0.01, 0.18908, 0.375, 0.5}) {
    for (double beta : {1e-3, 0.02, 0.1, 0.3, 1.0, 2.0}) {
      const double c = ref::spence_stick_ratio(beta, gamma);
      ASSERT_GT(c, 0.0);
      ASSERT_LT(c, 1.0);
      auto residual = [&](double x) { return ref::spence_friction_coefficient(x, gamma) - beta; };
      const double below = std::nextafter(c, 0.0), above = std::nextafter(c, 1.0);
      if (above == 1.0) {
        // Root closer to 1 than one ulp (1 - c ~ 2 exp(-pi beta / gamma)): the largest c < 1.
        EXPECT_LE(residual(c), 0.0) << gamma << " " << beta;
        continue;
      }
      // c is the best double up to the evaluation noise of (E.1) (a few ulps of beta) ...
      EXPECT_LE(std::abs(residual(c)),
                std::min(std::abs(residual(below)), std::abs(residual(above))) + 1e-15 * beta)
          << gamma << " " << beta;
      // ... and the residual is below 1e-12 relative wherever one ulp of c allows it.
      const double ulp_step = std::abs(residual(above) - residual(below));
      EXPECT_LE(std::abs(residual(c)), std::max(1e-12 * beta, ulp_step)) << gamma << " " << beta;
    }
  }
  // Extreme roots: c ~ 4 exp(-gamma / beta) near 0, 1 - c ~ 2 exp(-pi beta / gamma) near 1.
  const double tiny = ref::spence_stick_ratio(0.01, 0.375);
  EXPECT_NEAR(tiny / (4 * std::exp(-37.5)), 1.0, 0.05);
  EXPECT_NEAR(ref::spence_friction_coefficient(tiny, 0.375), 0.01, 1e-14);
  const double close = ref::spence_stick_ratio(1.0, 0.375);
  // (leading order; the relative correction is ~ (pi beta / gamma)(1 - c) / 2 ~ 1e-3)
  EXPECT_NEAR((1 - close) / (2 * std::exp(-std::numbers::pi / 0.375)), 1.0, 5e-3);
  EXPECT_EQ(ref::spence_stick_ratio(100.0, 0.01), std::nextafter(1.0, 0.0));  // 1 - c < 1 ulp
}

TEST(ReferenceSpence, RejectsInvalidArguments) {
  EXPECT_THROW(ref::spence_stick_ratio(0.0, 0.2), bemcontact::Error);
  EXPECT_THROW(ref::spence_stick_ratio(-0.1, 0.2), bemcontact::Error);
  EXPECT_THROW(ref::spence_stick_ratio(0.1, 0.0), bemcontact::Error);
  EXPECT_THROW(ref::spence_stick_ratio(0.1, 0.7), bemcontact::Error);
  EXPECT_THROW(ref::spence_friction_coefficient(1.0, 0.2), bemcontact::Error);
  EXPECT_THROW(ref::complementary_elliptic_k(0.0), bemcontact::Error);
}

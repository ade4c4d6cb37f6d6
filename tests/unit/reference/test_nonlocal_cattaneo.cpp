// reference::NonlocalCattaneo: the local limit is Cattaneo's closed form, and the non-local
// solution meets its own equations (the slip law, the force, a bounded stick shear).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/reference/nonlocal_cattaneo.hpp"

namespace bemcontact::reference {

// rho = 0: q = mu p0 (sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)), c/a = sqrt(1 - Q/mu P).
TEST(NonlocalCattaneo, TheLocalLimitIsCattaneo) {
  const double a = 0.07, p0 = 1346.0, mu = 0.3;
  for (const double ratio : {0.3, 0.6, 0.9}) {
    const NonlocalCattaneo solution(a, p0, mu, 0.0, ratio);
    const double c = a * std::sqrt(1.0 - ratio);
    EXPECT_NEAR(solution.stick_half_width() / a, c / a, 1e-6) << ratio;
    for (const double x : {0.0, 0.3 * c, 0.9 * c, 0.5 * (a + c), 0.95 * a}) {
      const double exact = mu * p0 * (std::sqrt(1.0 - x * x / (a * a)) - (std::abs(x) < c ? (c / a) * std::sqrt(1.0 - x * x / (c * c)) : 0.0));
      EXPECT_NEAR(solution.shear(x), exact, 1e-5 * mu * p0) << ratio << " " << x;
    }
  }
}

// rho > 0: the slip zones carry mu (omega * p); the shear integrates to Q; it is continuous at
// the stick edges and below the threshold inside.
TEST(NonlocalCattaneo, TheNonlocalSolutionMeetsItsEquations) {
  const double a = 0.07, p0 = 1346.0, mu = 0.3, ratio = 0.6;
  const double P = std::numbers::pi * a * p0 / 2.0;
  for (const double rho : {0.05 * a, 0.2 * a}) {
    const NonlocalCattaneo solution(a, p0, mu, rho, ratio);
    const double c = solution.stick_half_width();
    EXPECT_GT(c, 0.3 * a);
    EXPECT_LT(c, 0.9 * a);
    double force = 0.0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
      const double x = -a + (k + 0.5) * 2.0 * a / n;
      force += solution.shear(x) * 2.0 * a / n;
      const double threshold = mu * solution.mollified_pressure(x);
      EXPECT_LE(solution.shear(x), threshold * (1.0 + 1e-6) + 1e-9 * mu * p0) << rho << " " << x;
      if (std::abs(x) > c) EXPECT_NEAR(solution.shear(x), threshold, 1e-12 * mu * p0);
    }
    EXPECT_NEAR(force / (ratio * mu * P), 1.0, 1e-4) << rho;
    const double eps = 1e-12 * a;  // the shear has a square-root cusp at c: continuous, not smooth
    EXPECT_NEAR(solution.shear(c - eps), solution.shear(c + eps), 1e-3 * mu * p0) << rho;
  }
}

}  // namespace bemcontact::reference

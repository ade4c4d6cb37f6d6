// Frictionless stiff punch on a large support against the rigid-punch closed form
// P / (pi sqrt(a^2 - x^2)) (reference/flat_punch.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/reference/flat_punch.hpp"
#include "contact_fixtures.hpp"

namespace bemcontact::contact {

TEST(ContactFlatPunch, FrictionlessPressureMatchesRigidPunchOnHalfPlane) {
  const double a = 1.0, P = 1.0e-2;
  auto problem = testing::flat_punch(a, 20.0, 24, P);
  const auto result = solve_contact(problem);
  const reference::FlatPunchPlane exact{P, a, 1.0};
  double worst = 0.0, total = 0.0;
  for (const auto& pair : result.pairs) {
    if (std::abs(pair.coordinate) < 0.8 * a) {
      const double error = std::abs(-pair.p_n - exact.pressure(pair.coordinate)) / exact.pressure(pair.coordinate);
      worst = std::max(worst, error);
    }
  }
  // The trapezoidal integral of the nodal pressures misses part of the edge singularity.
  EXPECT_NEAR(result.summary.normal_force, P, 1e-2 * P);
  EXPECT_LT(worst, 0.03) << "max relative pressure error for |x| < 0.8a";
  EXPECT_EQ(result.summary.pairs_in_contact, static_cast<int>(result.pairs.size()));
  std::printf("flat punch: worst pressure error %.4f, newton iterations %d\n", worst, result.summary.newton_iterations);
}

}  // namespace bemcontact::contact

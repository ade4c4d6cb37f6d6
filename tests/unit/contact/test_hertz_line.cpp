// Cylinder on a block (plane strain): unilateral frictionless contact against Hertz line
// contact, and the two algorithms (semi-smooth Newton, thesis Alg V.1-V.3) against each
// other with and without friction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/reference/hertz.hpp"
#include "contact_fixtures.hpp"

namespace bemcontact::contact {
namespace {

// a = 0.1 R for E* of the pair.
ContactProblem cylinder(const Material& m1, const Material& m2, int elements = 40) {
  const double R = 1.0, a = 0.1;
  const double e_star = reference::contact_modulus(m1, m2, AnalysisType::plane_strain);
  const double P = std::numbers::pi * e_star * a * a / (4.0 * R);
  return testing::cylinder_on_block(R, 0.25, elements, P, m1, m2);
}

double max_difference(const ContactResult& a, const ContactResult& b, double scale) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.pairs.size(); ++i)
    worst = std::max({worst, std::abs(a.pairs[i].p_n - b.pairs[i].p_n) / scale,
                      std::abs(a.pairs[i].p_t - b.pairs[i].p_t) / scale});
  return worst;
}

}  // namespace

TEST(ContactHertzLine, FrictionlessContactMatchesHertz) {
  const Material m{1.0, 0.3};
  auto problem = cylinder(m, m);
  const auto result = solve_contact(problem);
  const double P = -problem.forces.at(0).force;
  const reference::HertzLineContact hertz{P, 1.0, reference::contact_modulus(m, m, AnalysisType::plane_strain)};
  // Element size 0.0125 = a/8 near the edge: the edge extrapolation of p^2 keeps a within ~2 %.
  EXPECT_NEAR(result.summary.contact_radius, hertz.half_width(), 0.02 * hertz.half_width());
  EXPECT_NEAR(result.summary.peak_pressure, hertz.max_pressure(), 0.02 * hertz.max_pressure());
  double worst = 0.0;
  for (const auto& pair : result.pairs)
    if (std::abs(pair.coordinate) < 0.8 * hertz.half_width())
      worst = std::max(worst, std::abs(-pair.p_n - hertz.pressure(pair.coordinate)) / hertz.max_pressure());
  // Plane fields decay slowly, so the finite cylinder and block bend the half-plane profile
  // a little; 3 % of p0 inside 0.8a (measured 1.2 %).
  EXPECT_LT(worst, 0.03);
  std::printf("hertz line: a %.5f (%.5f), p0 %.5f (%.5f), profile %.4f, newton %d\n", result.summary.contact_radius,
              hertz.half_width(), result.summary.peak_pressure, hertz.max_pressure(), worst,
              result.summary.newton_iterations);
}

TEST(ContactAlgorithms, ThesisAndNewtonAgreeWithoutFriction) {
  auto problem = cylinder({10.0, 0.3}, {1.0, 0.3}, 24);
  const auto newton = solve_contact(problem);
  problem.solver.algorithm = Algorithm::thesis;
  problem.solver.gmres_restart = 3;
  const auto thesis = solve_contact(problem);
  ASSERT_EQ(newton.pairs.size(), thesis.pairs.size());
  // xi = 1e-8 on relative changes: agreement to ~1e-5 of the peak pressure.
  EXPECT_LT(max_difference(newton, thesis, newton.summary.peak_pressure), 1e-4);
  EXPECT_EQ(newton.summary.pairs_in_contact, thesis.summary.pairs_in_contact);
  std::printf("frictionless: newton %d its, thesis kalker %d, V.2 %d, gmres cycles %d\n",
              newton.summary.newton_iterations, thesis.summary.kalker_iterations, thesis.summary.threshold_iterations,
              thesis.summary.gmres_cycles);
}

TEST(ContactAlgorithms, ThesisAndNewtonAgreeWithFriction) {
  auto problem = cylinder({10.0, 0.3}, {1.0, 0.3}, 24);
  problem.set_friction(0.1);
  problem.increments = 4;
  const auto newton = solve_contact(problem);
  problem.solver.algorithm = Algorithm::thesis;
  problem.solver.gmres_restart = 3;
  const auto thesis = solve_contact(problem);
  EXPECT_LT(max_difference(newton, thesis, newton.summary.peak_pressure), 1e-4);
  int stick = 0;
  for (const auto& pair : newton.pairs) stick += pair.status == PairStatus::stick;
  EXPECT_GT(stick, 0);
  EXPECT_NEAR(newton.summary.stick_radius, thesis.summary.stick_radius, 1e-12);
  // Coulomb holds at every pair.
  for (const auto& pair : newton.pairs) EXPECT_LE(std::abs(pair.p_t), 0.1 * std::abs(pair.p_n) * (1 + 1e-9) + 1e-14);
  std::printf("friction: c/a %.3f, newton %d its, thesis kalker %d, V.2 %d, gmres cycles %d\n",
              newton.summary.stick_ratio(), newton.summary.newton_iterations,
              thesis.summary.kalker_iterations, thesis.summary.threshold_iterations, thesis.summary.gmres_cycles);
}

}  // namespace bemcontact::contact

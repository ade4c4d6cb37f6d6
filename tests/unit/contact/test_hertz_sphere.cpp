// Axisymmetric ball on a support at a coarse resolution (half the example's contact
// elements): Hertz within 3 %, both algorithms the same answer, friction and history.
#include <gtest/gtest.h>

#include <limits>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/output/contact_writer.hpp"
#include "bemcontact/reference/hertz.hpp"

namespace bemcontact::contact {
namespace {

// The example with `elements` on each contact zone.
ContactProblem sphere_with_zone_elements(int elements) {
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_hertz_sphere.toml");
  const auto& contact = file.problem.contacts.front();
  for (const auto* side : {&contact.side1, &contact.side2})
    for (const int piece : side->pieces) file.problem.region(*side).body.pieces[piece].elements = elements;
  return file.problem;
}
ContactProblem coarse_ball() { return sphere_with_zone_elements(15); }

}  // namespace

TEST(ContactHertzSphere, CoarseMeshMatchesHertz) {
  const auto problem = coarse_ball();
  const auto result = solve_contact(problem);
  const auto hertz = reference::hertz_point_contact(31.5, 1.0, problem.elastic(0).material,
                                                    std::numeric_limits<double>::infinity(), problem.elastic(1).material);
  // Contact elements of a/10: a and delta within 3 % (2 % at the example's resolution).
  EXPECT_NEAR(result.summary.contact_radius, hertz.contact_radius(), 0.03 * hertz.contact_radius());
  EXPECT_NEAR(-result.summary.approach, hertz.approach(), 0.03 * hertz.approach());
  EXPECT_NEAR(result.summary.normal_force, 31.5, 0.01 * 31.5);
  const std::string text = io::contact_report_text(problem, result);
  EXPECT_NE(text.find("Hertz (R = 1)"), std::string::npos) << text;
  EXPECT_NE(text.find("delta = 0.00490583"), std::string::npos) << text;
}

TEST(ContactHertzSphere, AlgorithmsAgreeWithFrictionAndIncrements) {
  auto problem = coarse_ball();
  problem.set_friction(0.1);
  problem.increments = 4;
  const auto newton = solve_contact(problem);
  problem.solver.algorithm = Algorithm::thesis;
  const auto thesis = solve_contact(problem);
  double worst = 0.0;
  for (std::size_t i = 0; i < newton.pairs.size(); ++i)
    worst = std::max({worst, std::abs(newton.pairs[i].p_n - thesis.pairs[i].p_n),
                      std::abs(newton.pairs[i].p_t - thesis.pairs[i].p_t)});
  EXPECT_LT(worst / newton.summary.peak_pressure, 1e-4);
  EXPECT_NEAR(newton.summary.stick_radius, thesis.summary.stick_radius, 1e-3 * newton.summary.contact_radius);
  // A stick zone exists, and one step (no history) gives a smaller one than four.
  EXPECT_GT(newton.summary.stick_radius, 0.3 * newton.summary.contact_radius);
  problem.solver.algorithm = Algorithm::newton;
  problem.increments = 1;
  const auto one_step = solve_contact(problem);
  EXPECT_LT(one_step.summary.stick_radius, newton.summary.stick_radius);
}

// A fine ball on the formed route (two dense bodies, 701 pairs): its Newton iteration
// reaches a set that repeats with the residual at the dense solves' round-off, 2.8e-10
// against the tolerance 1e-10, and stayed there to the 100th iteration (a solver error).
// Now the step is taken there, with a warning giving the residual, and the answer is
// Hertz's as at coarser meshes.
TEST(ContactHertzSphere, FineMeshStopsAtTheRoundOffWithAWarning) {
  const auto problem = sphere_with_zone_elements(700);
  const auto result = solve_contact(problem);
  const auto hertz = reference::hertz_point_contact(31.5, 1.0, problem.elastic(0).material,
                                                    std::numeric_limits<double>::infinity(), problem.elastic(1).material);
  EXPECT_FALSE(result.matrix_free);
  EXPECT_EQ(result.steps_at_round_off, 1);
  EXPECT_GT(result.round_off_residual, problem.solver.tolerance);
  EXPECT_LT(result.round_off_residual, 100.0 * problem.solver.tolerance);
  EXPECT_LT(result.summary.newton_iterations, 30);
  bool warned = false;
  for (const auto& warning : result.warnings) warned = warned || warning.find("round-off of the Newton solves") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_NEAR(result.summary.centre_pressure, hertz.max_pressure(), 1e-3 * hertz.max_pressure());
  EXPECT_NEAR(result.summary.contact_radius, hertz.contact_radius(), 3e-3 * hertz.contact_radius());
  // The coarse ball converges below the tolerance: no such step, no warning.
  const auto coarse = solve_contact(coarse_ball());
  EXPECT_EQ(coarse.steps_at_round_off, 0);
  for (const auto& warning : coarse.warnings) EXPECT_EQ(warning.find("round-off"), std::string::npos) << warning;
}

}  // namespace bemcontact::contact

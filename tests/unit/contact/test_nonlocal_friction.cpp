// The non-local Coulomb law (nonlocal_friction.hpp): the mollifier's rows, the law met pair
// by pair in slip, the two algorithms against each other, and the key's checks.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/nonlocal_friction.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "support/contact_input.hpp"
#include "support/example_text.hpp"

namespace bemcontact {
namespace {

using test_support::example_text;
using test_support::replaced;

std::string nonlocal_input_error(const std::string& text) { return test_support::contact_input_error(text, "punch.toml"); }

contact::ContactProblem nonlocal_punch(int elements, contact::Algorithm algorithm) {
  auto file = io::parse_contact_problem(example_text("contact_nonlocal_punch.toml"), "punch.toml", {{"n", elements}});
  file.problem.solver.algorithm = algorithm;
  file.problem.drop_interior_points();
  return file.problem;
}

}  // namespace

// Rows of unit sum, weights that vanish beyond rho, symmetric on a uniform row of pairs away
// from its ends, and a row covering one pair only where rho is below the spacing.
TEST(NonlocalFriction, MollifierRowsAreNormalisedBumps) {
  std::vector<contact::ContactPair> pairs(21);
  for (int k = 0; k < 21; ++k) {
    pairs[static_cast<std::size_t>(k)].position1 = Vec2(0.1 * k, 0.0);
    pairs[static_cast<std::size_t>(k)].weight = 0.1;
  }
  contact::MollifierRows rows;
  contact::add_mollifier_rows(pairs, 0, 21, 0.35, rows);
  for (const auto& row : rows) {
    double sum = 0.0;
    for (const auto& [j, w] : row) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-14);
  }
  const auto& middle = rows[10];
  ASSERT_EQ(middle.size(), 7u);  // |s_i - s_j| < 0.35: j = 7 ... 13
  EXPECT_NEAR(middle[0].second, middle[6].second, 1e-15);
  EXPECT_GT(middle[3].second, middle[2].second);
  EXPECT_EQ(contact::mollifier_bump(0.35, 0.35), 0.0);
  contact::add_mollifier_rows(pairs, 0, 21, 0.05, rows);
  EXPECT_EQ(rows[10].size(), 1u);
}

// Every slipping pair's shear is beta times its mollified pressure; none exceeds it.
TEST(NonlocalFriction, SlipFollowsTheMollifiedThreshold) {
  const auto problem = nonlocal_punch(40, contact::Algorithm::newton);
  const auto result = contact::solve_contact(problem);
  std::vector<contact::ContactPair> geometry(result.pairs.size());
  // The pairs' arc lengths and weights as the solver sees them: uniform zone, 40 elements.
  contact::MollifierRows rows;
  for (std::size_t k = 0; k < result.pairs.size(); ++k) geometry[k].position1 = result.pairs[k].position;
  const double h = 4.8 / 40;
  for (std::size_t k = 0; k < geometry.size(); ++k) geometry[k].weight = (k == 0 || k + 1 == geometry.size()) ? h / 2 : h;
  contact::add_mollifier_rows(geometry, 0, static_cast<Index>(geometry.size()), 0.48, rows);
  int slipping = 0;
  for (std::size_t i = 0; i < result.pairs.size(); ++i) {
    // Rows whose kernel reaches neither end pair (whose weights the solver takes from the
    // split corner node's shifted element): there the uniform weights above are the solver's.
    const double x = result.pairs[i].position.x();
    if (x < 0.48 + 2 * h || x > 4.8 - 0.48 - 2 * h) continue;
    double mollified = 0.0;
    for (const auto& [j, w] : rows[i]) mollified += w * std::abs(result.pairs[static_cast<std::size_t>(j)].p_n);
    const double g = 0.1 * mollified;
    EXPECT_LE(std::abs(result.pairs[i].p_t), g * (1.0 + 1e-9)) << i;
    // Slip as reported: within 1e-3 of the threshold (contact_solver's status rule).
    if (result.pairs[i].status == contact::PairStatus::slip) {
      ++slipping;
      EXPECT_NEAR(std::abs(result.pairs[i].p_t), g, 1e-3 * g) << i;
      if (result.pairs[i].slip_ratio > 1.0 - 1e-9) EXPECT_NEAR(std::abs(result.pairs[i].p_t), g, 1e-8 * g) << i;
    }
  }
  EXPECT_GT(slipping, 3);
}

// The thesis' algorithm (Alg V.2's fixed point on the mollified threshold) and the Newton
// method (the threshold's dependence on the neighbours' pressures in its Jacobian) agree to
// the thesis algorithm's tolerance (sqrt(xi) on g).
TEST(NonlocalFriction, BothAlgorithmsAgree) {
  const auto newton = contact::solve_contact(nonlocal_punch(40, contact::Algorithm::newton));
  const auto thesis = contact::solve_contact(nonlocal_punch(40, contact::Algorithm::thesis));
  double peak = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < newton.pairs.size(); ++i) {
    peak = std::max(peak, std::abs(newton.pairs[i].p_n));
    worst = std::max({worst, std::abs(newton.pairs[i].p_t - thesis.pairs[i].p_t),
                      std::abs(newton.pairs[i].p_n - thesis.pairs[i].p_n)});
  }
  EXPECT_LT(worst, 1e-3 * peak);
}

// Unilateral contact with a kernel five pair spacings wide (the fretting cycle, 60 elements):
// the first steps, where the contact holds a few pairs and the kernel reaches open ones,
// converge (a pair out of contact has no threshold, as the normal active set says), and the
// stick zone stays near the local law's.
TEST(NonlocalFriction, AWideKernelOnAGrowingContactConverges) {
  auto file = io::parse_contact_problem(example_text("fretting_cylinder.toml"), "fretting.toml");
  file.problem.drop_interior_points();
  const auto local = contact::solve_contact(file.problem);
  file.problem.contacts.front().law.nonlocal_radius = 0.014;  // 0.2 a
  const auto nonlocal = contact::solve_contact(file.problem);
  EXPECT_NEAR(nonlocal.summary.stick_ratio(), local.summary.stick_ratio(), 0.05);
  EXPECT_NEAR(nonlocal.summary.tangential_force, local.summary.tangential_force, 1e-6 * std::abs(local.summary.tangential_force));
}

TEST(NonlocalFriction, KeyIsCheckedWhereItIsRead) {
  const std::string text = example_text("contact_nonlocal_punch.toml");
  const auto frictionless = nonlocal_input_error(replaced(text, "friction = \"beta\"", "friction = 0.0"));
  EXPECT_TRUE(frictionless.find("with friction = 0 it has no effect") != std::string::npos) << frictionless;
  const auto negative = nonlocal_input_error(replaced(text, "\nrho = 0.48", "\nrho = -1.0"));
  EXPECT_TRUE(negative.find("nonlocal_radius") != std::string::npos) << negative;
  EXPECT_TRUE(negative.find("punch.toml:") != std::string::npos) << negative;
  const auto wide = nonlocal_input_error(replaced(text, "\nrho = 0.48", "\nrho = 50.0"));
  EXPECT_TRUE(wide.find("larger than side 1's contact zone boundary 'contact' of body 'punch'") != std::string::npos) << wide;
  const auto axisymmetric = nonlocal_input_error(replaced(example_text("contact_spence_sphere.toml"), "[contact]\n",
                                                          "[contact]\nnonlocal_radius = 0.01\n"));
  EXPECT_TRUE(axisymmetric.find("plane problems only") != std::string::npos) << axisymmetric;
}

}  // namespace bemcontact

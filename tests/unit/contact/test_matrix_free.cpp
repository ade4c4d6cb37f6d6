// The matrix-free route of the condensed operator (condensed.hpp, matrix_free_step.cpp)
// against the formed one: the same model solved both ways must give the same pairs, with a
// rigid cylinder pressed by a force (one motion, the Schur complement of b) and two elastic
// bodies under a prescribed displacement (no motion, both regions in every product).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/step_solvers.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "contact_fixtures.hpp"

namespace bemcontact::contact {
namespace {

// examples/contact_compliant_cylinder.toml made unilateral: a rigid cylinder on a block.
ContactProblem rigid_cylinder(int elements) {
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_compliant_cylinder.toml",
                                    {{"n", static_cast<double>(elements)}, {"rc", 0.1}, {"E_block", 70000.0},
                                     {"P", 148.0}});
  file.problem.contacts.front().law = ContactLaw{};
  file.problem.drop_interior_points();
  return file.problem;
}

// Two elastic cylinders' model of the Hertz line tests, the cylinder's top moved down.
ContactProblem pressed_cylinder(int elements) {
  auto problem = testing::cylinder_on_block(1.0, 0.25, elements, 0.0, {1.0, 0.3}, {2.0, 0.25});
  problem.forces.clear();
  problem.elastic(0).conditions[2] = testing::displacement(0.0, -0.004, "top");
  return problem;
}

// Both routes; the largest pressure difference over the pairs relative to the peak.
double routes_differ(ContactProblem problem, ContactResult& matrix_free) {
  problem.solver.contact_operator = CondensedOperatorKind::dense;
  const auto dense = solve_contact(problem);
  problem.solver.contact_operator = CondensedOperatorKind::matrix_free;
  matrix_free = solve_contact(problem);
  EXPECT_FALSE(dense.matrix_free);
  EXPECT_TRUE(matrix_free.matrix_free);
  EXPECT_EQ(dense.pairs.size(), matrix_free.pairs.size());
  EXPECT_EQ(dense.summary.pairs_in_contact, matrix_free.summary.pairs_in_contact);
  double worst = 0.0;
  for (std::size_t i = 0; i < dense.pairs.size(); ++i)
    worst = std::max(worst, std::abs(dense.pairs[i].p_n - matrix_free.pairs[i].p_n));
  EXPECT_GT(dense.summary.peak_pressure, 0.0);
  std::printf("matrix-free: %zu pairs, %d in contact, pressures differ by %.2e of the peak; newton %d / %d, %ld products\n",
              dense.pairs.size(), dense.summary.pairs_in_contact, worst / dense.summary.peak_pressure,
              dense.summary.newton_iterations, matrix_free.summary.newton_iterations,
              matrix_free.summary.matrix_free_products);
  return worst / dense.summary.peak_pressure;
}

}  // namespace

TEST(MatrixFree, ProductIsTheFormedOperator) {
  auto problem = rigid_cylinder(120);
  problem.solver.contact_operator = CondensedOperatorKind::dense;
  const ContactModel dense(problem);
  problem.solver.contact_operator = CondensedOperatorKind::matrix_free;
  const ContactModel applied(problem);
  const auto& formed = dense.condensed();
  const auto& product = applied.condensed();
  ASSERT_TRUE(product.matrix_free);
  EXPECT_EQ(product.M.size(), 0);
  Vector x(2 * formed.pairs);
  for (Index i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * static_cast<double>(i)) * (i % 2 == 0 ? 1.0 : 0.0);
  const Vector expected = formed.M * x;
  EXPECT_LT((product.apply_M(x) - expected).norm(), 1e-12 * expected.norm());
  // The motions' columns and rows are formed alike on both routes.
  EXPECT_LT((product.b - formed.b).norm(), 1e-12 * formed.b.norm());
  EXPECT_LT((product.f - formed.f).norm(), 1e-12 * formed.f.norm());
}

TEST(MatrixFree, RigidCylinderUnderForceMatchesTheFormedOperator) {
  ContactResult matrix_free;
  // The routes' steps both meet the complementarity functions to 1e-10 of the peak pressure.
  EXPECT_LT(routes_differ(rigid_cylinder(400), matrix_free), 1e-8);
  EXPECT_GT(matrix_free.summary.matrix_free_products, 0);
  // The coarse start finds the contact set to within a few pairs: a few Newton iterations.
  EXPECT_LE(matrix_free.summary.newton_iterations, 6);
}

TEST(MatrixFree, TwoElasticBodiesUnderDisplacementMatchTheFormedOperator) {
  ContactResult matrix_free;
  EXPECT_LT(routes_differ(pressed_cylinder(60), matrix_free), 1e-8);
}

TEST(MatrixFree, RefusedWhereItsStepSolverDoesNotServe) {
  auto problem = rigid_cylinder(40);
  problem.solver.contact_operator = CondensedOperatorKind::matrix_free;
  problem.set_friction(0.2);
  EXPECT_NE(matrix_free_obstacle(problem).find("friction"), std::string::npos);
  EXPECT_THROW(ContactModel{problem}, InputError);
  auto platen = pressed_cylinder(20);
  platen.forces = {testing::platen_force(0, 2, 1, -0.01)};
  EXPECT_NE(matrix_free_obstacle(platen).find("platen"), std::string::npos);
  // auto keeps the formed operator where something stands in the way, and below the threshold.
  problem.solver.contact_operator = CondensedOperatorKind::automatic;
  EXPECT_FALSE(ContactModel(problem).condensed().matrix_free);
  problem.set_friction(0.0);
  EXPECT_FALSE(ContactModel(problem).condensed().matrix_free);
}

TEST(MatrixFree, ProblemFileKeyIsReadAndChecked) {
  // The rigid cylinder's example made unilateral, with the key; then with friction too.
  std::ifstream in(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_compliant_cylinder.toml");
  std::string text, line;
  while (std::getline(in, line))
    if (line.rfind("kind = ", 0) != 0 && line.rfind("normal_", 0) != 0) text += line + "\n";
  const std::string key = "[solver]\ncontact_operator = \"matrix_free\"\n";
  const auto file = io::parse_contact_problem(text + key, "mf.toml");
  EXPECT_EQ(file.problem.solver.contact_operator, CondensedOperatorKind::matrix_free);
  const std::string with_friction = "normal = \"body1\"\nfriction = 0.3\n";
  const std::size_t at = text.find("normal = \"body1\"\n");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::string("normal = \"body1\"\n").size(), with_friction);
  try {
    io::parse_contact_problem(text + key, "mf.toml");
    FAIL() << "friction with contact_operator = matrix_free was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("mf.toml"), std::string::npos) << message;
    EXPECT_NE(message.find("contact_operator"), std::string::npos) << message;
    EXPECT_NE(message.find("friction"), std::string::npos) << message;
  }
}

}  // namespace bemcontact::contact

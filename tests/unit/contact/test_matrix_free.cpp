// The matrix-free route of the condensed operator (condensed.hpp, matrix_free_step.cpp)
// against the formed one: the same model solved both ways must give the same pairs, with a
// rigid cylinder pressed by a force (one motion, the Schur complement of b), then sheared
// with friction (sticking and slipping pairs, two motions), and two elastic bodies under a
// prescribed displacement (no motion, both regions in every product).
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

// The rigid cylinder with friction mu = 0.3 (the local law, or the non-local one over
// `radius`): P, then Q = 0.6 mu P (Cattaneo-Mindlin's partial slip), one step each.
ContactProblem sheared_cylinder(int elements, double radius = 0.0) {
  auto problem = rigid_cylinder(elements);
  problem.set_friction(0.3);
  problem.contacts.front().law.nonlocal_radius = radius;
  auto& P = problem.forces.front();
  P.amplitude.points = {{0.0, 0.0}, {1.0, 1.0}};
  ForceLoad Q = P;
  Q.name = "Q";
  Q.component = 0;
  Q.force = 0.6 * 0.3 * -P.force;
  Q.amplitude.points = {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}};
  problem.forces.push_back(Q);
  problem.end_time = 2.0;
  problem.increments = 2;
  problem.adaptive = false;
  return problem;
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
    worst = std::max({worst, std::abs(dense.pairs[i].p_n - matrix_free.pairs[i].p_n),
                      std::abs(dense.pairs[i].p_t - matrix_free.pairs[i].p_t)});
  // The same stick pairs; the stick zone's ends, extrapolated from the margins 1 - |p_t| /
  // (mu |p_n|) of the outermost stick pairs (contact_summary.cpp), within 10 times what the
  // tractions' difference moves them by: its share of the outermost margin's slope, a margin
  // changed by up to 2 |difference| / (mu |p_n|) (at least 1e-9 a).
  EXPECT_EQ(dense.summary.stick_outer_start, matrix_free.summary.stick_outer_start);
  EXPECT_EQ(dense.summary.stick_outer_end, matrix_free.summary.stick_outer_end);
  double edge_shift = 0.0;
  for (std::size_t i = 0; i + 1 < dense.pairs.size(); ++i) {
    const auto &a = dense.pairs[i], &b = dense.pairs[i + 1];
    if ((a.status == PairStatus::stick) == (b.status == PairStatus::stick) || a.status == PairStatus::open ||
        b.status == PairStatus::open)
      continue;  // not a stick edge
    const auto& inner = a.status == PairStatus::stick ? a : b;
    const std::size_t k = a.status == PairStatus::stick ? i : i + 1;
    const std::size_t next = a.status == PairStatus::stick ? (k > 0 ? k - 1 : k) : k + 1;  // the next stick pair inward
    if (next >= dense.pairs.size() || next == k || dense.pairs[next].status != PairStatus::stick) continue;
    const double slope = std::abs(dense.pairs[next].slip_ratio - inner.slip_ratio) /
                         std::abs(dense.pairs[next].coordinate - inner.coordinate);
    const double friction = inner.slip_ratio > 0.0 ? std::abs(inner.p_t) / (inner.slip_ratio * std::abs(inner.p_n)) : 0.0;
    if (slope > 0.0 && friction > 0.0) edge_shift = std::max(edge_shift, 2.0 * worst / (friction * std::abs(inner.p_n)) / slope);
  }
  const double edge_tolerance = std::max(1e-9 * dense.summary.contact_radius, 10.0 * edge_shift);
  EXPECT_NEAR(dense.summary.stick_start, matrix_free.summary.stick_start, edge_tolerance);
  EXPECT_NEAR(dense.summary.stick_end, matrix_free.summary.stick_end, edge_tolerance);
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
  // The diagonal estimate (sampled at 16 pairs, interpolated): within 4.5 % of M's (measured
  // at 121, 201, 401 and 1 001 pairs), enough for the penalty c and the fine level.
  const auto& data = *product.matrix_free;
  for (Index k = 0; k < formed.M.rows(); ++k)
    EXPECT_LT(std::abs(data.diagonal[k] - formed.M(k, k)), 0.06 * std::abs(formed.M(k, k))) << "dof " << k;
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

TEST(MatrixFree, FrictionalCylinderUnderTwoForcesMatchesTheFormedOperator) {
  ContactResult matrix_free;
  // Both meet the complementarity functions to 1e-10 of the peak pressure; the tangential
  // rows of the sticking pairs and the slipping tau folded into the normal columns.
  EXPECT_LT(routes_differ(sheared_cylinder(200), matrix_free), 1e-8);
  // Partial slip (c/a = 0.35: nu = 0.3 couples the pressure into the slip, which Cattaneo's
  // 0.63 leaves out).
  EXPECT_GT(matrix_free.summary.stick_radius, 0.1 * matrix_free.summary.contact_radius);
  EXPECT_LT(matrix_free.summary.stick_radius, 0.9 * matrix_free.summary.contact_radius);
  // The non-local law: tau of a slipping pair follows its neighbours' pressures.
  EXPECT_LT(routes_differ(sheared_cylinder(200, 0.005), matrix_free), 1e-8);
}

TEST(MatrixFree, CompliantAndBilateralContactsMatchTheFormedOperator) {
  ContactResult matrix_free;
  // examples/contact_compliant_cylinder.toml (m = 1) on a softer block: a compliant pair's
  // row less lambda / k.
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_compliant_cylinder.toml",
                                    {{"n", 200.0}, {"E_block", 70000.0}, {"cn", 1e6}});
  file.problem.drop_interior_points();
  EXPECT_LT(routes_differ(file.problem, matrix_free), 1e-8);
  // With friction (m_t = m_n) and Q = 0.1 P after P, adaptive steps (71 of them).
  file.problem.set_friction(0.3);
  file.problem.forces.front().amplitude.points = {{0.0, 0.0}, {1.0, 1.0}};
  ForceLoad Q = file.problem.forces.front();
  Q.name = std::string("Q");
  Q.component = 0;
  Q.force = 0.1 * -Q.force;
  Q.amplitude.points = {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}};
  file.problem.forces.push_back(Q);
  file.problem.end_time = 2.0;
  file.problem.increments = 2;
  file.problem.adaptive = true;
  EXPECT_LT(routes_differ(file.problem, matrix_free), 1e-8);
  // m_n = 2.2, m_t = 1.5 (test_normal_compliance.cpp's law): the slipping tau's offsets
  // enter the right-hand side through one product; 16 equal steps.
  auto& law = file.problem.contacts.front().law.compliance;
  law.stiffness = 5.8e6;
  law.exponent = 2.2;
  law.friction_stiffness = 1.515e5;
  law.friction_exponent = 1.5;
  file.problem.adaptive = false;
  file.problem.increments = 16;
  EXPECT_LT(routes_differ(file.problem, matrix_free), 1e-8);
  // Bilateral: every pair's row is a gap row.
  auto bonded = pressed_cylinder(60);
  bonded.contacts.front().law.kind = ContactKind::bilateral;
  EXPECT_LT(routes_differ(bonded, matrix_free), 1e-8);
}

TEST(MatrixFree, TwoElasticBodiesUnderDisplacementMatchTheFormedOperator) {
  ContactResult matrix_free;
  EXPECT_LT(routes_differ(pressed_cylinder(60), matrix_free), 1e-8);
}

TEST(MatrixFree, RefusedWhereItsStepSolverDoesNotServe) {
  auto problem = rigid_cylinder(40);
  problem.solver.contact_operator = CondensedOperatorKind::matrix_free;
  problem.solver.algorithm = Algorithm::thesis;
  EXPECT_NE(matrix_free_obstacle(problem).find("thesis"), std::string::npos);
  EXPECT_THROW(ContactModel{problem}, InputError);
  auto platen = pressed_cylinder(20);
  platen.forces = {testing::platen_force(0, 2, 1, -0.01)};
  EXPECT_NE(matrix_free_obstacle(platen).find("platen"), std::string::npos);
  // auto keeps the formed operator where something stands in the way, and below the threshold.
  problem.solver.contact_operator = CondensedOperatorKind::automatic;
  EXPECT_FALSE(ContactModel(problem).condensed().matrix_free);
  problem.solver.algorithm = Algorithm::newton;
  EXPECT_FALSE(ContactModel(problem).condensed().matrix_free);
}

TEST(MatrixFree, ProblemFileKeyIsReadAndChecked) {
  // The rigid cylinder's example made unilateral, with the key; then with the thesis algorithm.
  std::ifstream in(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_compliant_cylinder.toml");
  std::string text, line;
  while (std::getline(in, line))
    if (line.rfind("kind = ", 0) != 0 && line.rfind("normal_", 0) != 0) text += line + "\n";
  const std::string key = "[solver]\ncontact_operator = \"matrix_free\"\n";
  const auto file = io::parse_contact_problem(text + key, "mf.toml");
  EXPECT_EQ(file.problem.solver.contact_operator, CondensedOperatorKind::matrix_free);
  try {
    io::parse_contact_problem(text + key + "algorithm = \"thesis\"\n", "mf.toml");
    FAIL() << "the thesis algorithm with contact_operator = matrix_free was accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("mf.toml"), std::string::npos) << message;
    EXPECT_NE(message.find("contact_operator"), std::string::npos) << message;
    EXPECT_NE(message.find("thesis"), std::string::npos) << message;
  }
}

}  // namespace bemcontact::contact

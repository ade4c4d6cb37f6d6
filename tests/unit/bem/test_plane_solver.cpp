// Plane solver: exactness for linear fields under every kind of corner condition, the
// singular (free-body) diagnosis, and the factored body against the one-shot solve.
#include <gtest/gtest.h>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/factored_body.hpp"
#include "bemcontact/core/error.hpp"
#include "support/problems.hpp"

using namespace bemcontact;
using bemcontact::bem::ConditionKind;
using bemcontact::test_support::LinearField;

using bemcontact::test_support::T;
using bemcontact::test_support::U;

namespace {

// Unit square, sides bottom, right, top, left with the given kinds, data from `field`.
bem::ProblemDefinition square(const LinearField& field, std::array<std::array<ConditionKind, 2>, 4> kinds,
                              int per_side, Interpolation interpolation = Interpolation::linear) {
  bem::ProblemDefinition problem;
  problem.analysis = field.type;
  problem.mesh.interpolation = interpolation;
  problem.body.material = field.material;
  const Vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Vec2 normals[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  for (int k = 0; k < 4; ++k) {
    const Mat2 sigma = field.stress();
    const Vec2 p = sigma * normals[k];
    test_support::add_piece(problem, "side" + std::to_string(k), corners[k], corners[(k + 1) % 4], per_side, kinds[k],
                       [&field](const Vec2& x) { return field.displacement(x); }, [p](const Vec2&) { return p; });
  }
  return problem;
}

double max_error(const bem::BodyResult& r, const LinearField& field) {
  double e = 0.0;
  for (Index i = 0; i < r.mesh.node_count(); ++i) {
    const auto& node = r.mesh.nodes[i];
    e = std::max(e, (r.boundary.displacement[i] - field.displacement(node.position)).norm());
    e = std::max(e, (r.boundary.traction[i] - field.stress() * node.normal).norm() * 1e-3);
  }
  return e;
}

LinearField sample_field(AnalysisType type) {
  LinearField f;
  f.gradient << 1e-3, 2e-4, -5e-4, -3e-4;
  f.material = {1000.0, 0.3};
  f.type = type;
  return f;
}

}  // namespace

// Every combination of conditions on the two sides of a corner, including displacement
// on both (the clamped corner that breaks a naive double node, section II.4.4.2), must
// reproduce a linear field to round-off with linear elements and analytic integrals.
TEST(BemPlaneSolver, LinearFieldIsExactForEveryCornerCondition) {
  const std::array<std::array<ConditionKind, 2>, 4> cases[] = {
      {{{U, U}, {T, T}, {T, T}, {U, U}}},  // clamped corner at the origin
      {{{U, U}, {U, U}, {U, U}, {U, U}}},  // Dirichlet everywhere
      {{{T, U}, {U, T}, {T, T}, {U, T}}},  // mixed, symmetry-like
      {{{U, T}, {T, U}, {U, U}, {T, T}}},
  };
  for (const auto type : {AnalysisType::plane_strain, AnalysisType::plane_stress}) {
    const auto field = sample_field(type);
    for (const auto& kinds : cases) {
      const auto result = bem::solve_body(square(field, kinds, 3));
      EXPECT_LT(max_error(result, field), 1e-13) << to_string(type);
      EXPECT_GT(result.report.reciprocal_condition, 1e-8);
      EXPECT_LT(result.report.relative_residual, 1e-12);
    }
  }
}

// Discontinuous elements (every node inside its element, at the Gauss points) reproduce a
// linear field to round-off too, linear and quadratic, under every corner condition.
TEST(BemPlaneSolver, DiscontinuousElementsReproduceALinearField) {
  const std::array<std::array<ConditionKind, 2>, 4> cases[] = {
      {{{U, U}, {T, T}, {T, T}, {U, U}}}, {{{U, U}, {U, U}, {U, U}, {U, U}}}, {{{T, U}, {U, T}, {T, T}, {U, T}}}};
  const auto field = sample_field(AnalysisType::plane_strain);
  for (const auto interpolation : {Interpolation::linear, Interpolation::quadratic})
    for (const auto& kinds : cases) {
      auto problem = square(field, kinds, 3, interpolation);
      geometry::use_discontinuous_elements(problem.mesh);
      const auto result = bem::solve_body(problem);
      EXPECT_EQ(result.mesh.node_count(), 12 * (interpolation == Interpolation::quadratic ? 3 : 2));
      EXPECT_LT(max_error(result, field), 1e-12) << to_string(interpolation);
      EXPECT_LT(result.report.relative_residual, 1e-11);
    }
}

TEST(BemPlaneSolver, InteriorPointsOfALinearFieldAreExact) {
  const auto field = sample_field(AnalysisType::plane_strain);
  auto problem = square(field, {{{U, U}, {T, T}, {T, T}, {T, T}}}, 4);
  for (const Vec2 x : {Vec2(0.5, 0.5), Vec2(0.01, 0.3), Vec2(0.999, 0.999), Vec2(0.3, 1e-4)})
    problem.interior_points.push_back({x, false});
  const auto r = bem::solve_body(problem);
  ASSERT_EQ(r.interior.points.size(), 4u);
  for (std::size_t k = 0; k < r.interior.points.size(); ++k) {
    EXPECT_LT((r.interior.displacement[k] - field.displacement(r.interior.points[k])).norm(), 1e-14);
    const auto& s = r.interior.stress[k];
    const Mat2 sigma = field.stress();
    EXPECT_NEAR(s.s11, sigma(0, 0), 1e-10 * sigma.norm());
    EXPECT_NEAR(s.s22, sigma(1, 1), 1e-10 * sigma.norm());
    EXPECT_NEAR(s.s12, sigma(0, 1), 1e-10 * sigma.norm());
    EXPECT_NEAR(s.s33, field.material.poisson_ratio * (sigma(0, 0) + sigma(1, 1)), 1e-10 * sigma.norm());
  }
}

TEST(BemPlaneSolver, BoundaryStressOfALinearFieldIsExact) {
  const auto field = sample_field(AnalysisType::plane_stress);
  const auto r = bem::solve_body(square(field, {{{U, U}, {T, T}, {T, T}, {T, T}}}, 3));
  const Mat2 sigma = field.stress();
  for (const auto& s : r.boundary.stress) {
    EXPECT_NEAR(s.s11, sigma(0, 0), 1e-10 * sigma.norm());
    EXPECT_NEAR(s.s22, sigma(1, 1), 1e-10 * sigma.norm());
    EXPECT_NEAR(s.s12, sigma(0, 1), 1e-10 * sigma.norm());
    EXPECT_EQ(s.s33, 0.0);
  }
}

TEST(BemPlaneSolver, FreeBodyIsReportedNotSolved) {
  const auto field = sample_field(AnalysisType::plane_strain);
  try {
    bem::solve_body(square(field, {{{T, T}, {T, T}, {T, T}, {T, T}}}, 2));
    FAIL() << "a free body must be reported";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("rigid body"), std::string::npos) << e.what();
  }
}

TEST(BemPlaneSolver, PointConstraintsAtSplitCornersRemoveRigidMotion) {
  const auto field = sample_field(AnalysisType::plane_strain);
  auto problem = square(field, {{{T, T}, {T, T}, {T, T}, {T, T}}}, 3);
  // Fix the three rigid modes at two corners, with the exact field's values.
  bem::PointConstraint a, b;
  a.position = Vec2(0, 0);
  a.displacement = {field.displacement(a.position).x(), field.displacement(a.position).y()};
  b.position = Vec2(1, 0);
  b.displacement[1] = field.displacement(b.position).y();
  problem.body.constraints = {a, b};
  const auto r = bem::solve_body(problem);
  EXPECT_LT(max_error(r, field), 1e-12);
}

TEST(BemPlaneSolver, ConstantElementsConvergeAtFirstOrder) {
  const auto field = sample_field(AnalysisType::plane_strain);
  double previous = 0.0;
  for (int n : {4, 8, 16}) {
    const auto r = bem::solve_body(square(field, {{{U, U}, {T, T}, {T, T}, {T, T}}}, n, Interpolation::constant));
    double e = 0.0;
    for (Index i = 0; i < r.mesh.node_count(); ++i)
      e = std::max(e, (r.boundary.displacement[i] - field.displacement(r.mesh.nodes[i].position)).norm());
    if (previous > 0.0) EXPECT_GT(std::log2(previous / e), 0.8) << n;  // first order, O(h)
    previous = e;
  }
}

TEST(BemFactoredBody, MatchesTheOneShotSolveAndIsLinearInTheData) {
  const auto field = sample_field(AnalysisType::plane_strain);
  const auto problem = square(field, {{{U, U}, {T, T}, {T, T}, {T, T}}}, 3);
  const auto reference = bem::solve_body(problem);
  const auto& mesh = reference.mesh;
  // The top side's nodes become variable traction nodes carrying the same data.
  std::vector<bem::VariableNode> variable;
  for (Index node : mesh.piece_nodes[2]) variable.push_back({node, ConditionKind::traction});
  const bem::FactoredBody body(mesh, problem.body, problem.analysis, variable);
  Vector data(body.variable_dofs());
  for (std::size_t k = 0; k < variable.size(); ++k)
    data.segment<2>(2 * k) = reference.boundary.traction[variable[k].node];
  const auto full = body.solve(data);
  for (Index i = 0; i < mesh.node_count(); ++i) {
    EXPECT_LT((full.displacement[i] - reference.boundary.displacement[i]).norm(), 1e-14);
    EXPECT_LT((full.traction[i] - reference.boundary.traction[i]).norm(), 1e-9);
  }
  const Vector u_top = body.complementary(data);
  for (std::size_t k = 0; k < variable.size(); ++k)
    EXPECT_LT((u_top.segment<2>(2 * k) - reference.boundary.displacement[variable[k].node]).norm(), 1e-14);
  // Superposition: fixed data alone + variable data alone = both.
  const Vector split = body.complementary(data, false) + body.complementary(Vector::Zero(data.size()), true);
  EXPECT_LT((split - u_top).norm(), 1e-14);
}

// The compressed boundary element system against the dense one, entry for entry (as
// operators) and solution for solution, and its error against the accuracy parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/compressed_system.hpp"
#include "bemcontact/bem/factored_body.hpp"
#include "support/problems.hpp"

using namespace bemcontact;
using bemcontact::bem::ConditionKind;

using bemcontact::test_support::T;
using bemcontact::test_support::U;

namespace {

// A 4 x 1 strip: clamped at x = 0, sheared and stretched at x = 4, free sides; or, with
// `free_body`, loaded by balanced tractions only and held by point constraints.
bem::ProblemDefinition strip(int per_unit, bool free_body = false) {
  bem::ProblemDefinition problem;
  problem.analysis = AnalysisType::plane_strain;
  problem.body.material = {200e3, 0.3};
  const auto zero = [](const Vec2&) { return Vec2(0.0, 0.0); };
  // Clamped: tension and a parabolic shear at the end; free: a balanced parabolic tension.
  const auto end_load = [free_body](const Vec2& x) {
    const double parabola = 3.0 * (x.y() - 0.5) * (x.y() - 0.5);
    return free_body ? Vec2(10.0 + parabola, 0.0) : Vec2(10.0, parabola + 1.0);
  };
  const auto start_load = [end_load](const Vec2& x) { return Vec2(-end_load(x)); };
  test_support::add_piece(problem, "bottom", {0, 0}, {4, 0}, 4 * per_unit, {T, T}, zero, zero);
  test_support::add_piece(problem, "end", {4, 0}, {4, 1}, per_unit, {T, T}, zero, end_load);
  test_support::add_piece(problem, "top", {4, 1}, {0, 1}, 4 * per_unit, {T, T}, zero, zero);
  if (free_body) {
    test_support::add_piece(problem, "start", {0, 1}, {0, 0}, per_unit, {T, T}, zero, start_load);
    test_support::hold_rigid_motion(problem, {0, 0}, {4, 0});
  } else {
    test_support::add_piece(problem, "start", {0, 1}, {0, 0}, per_unit, {U, U}, zero, zero);
  }
  return problem;
}

double relative_difference(const bem::BoundarySolution& a, const bem::BoundarySolution& b, bool traction) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.displacement.size(); ++i) {
    const Vec2 x = traction ? a.traction[i] : a.displacement[i];
    const Vec2 y = traction ? b.traction[i] : b.displacement[i];
    diff = std::max(diff, (x - y).norm());
    scale = std::max(scale, y.norm());
  }
  return diff / scale;
}

}  // namespace

// The compressed [H' | G] and A act on vectors as the dense H, G and A do, to about the
// accuracy asked (ACA+ stops when its next cross is below it, relative to the block). 600
// nodes: [H' | G]'s 1 200 rows are assembled in row pieces (operators/row_partitioned_hmatrix.hpp).
TEST(CompressedSystem, OperatorsMatchTheDenseMatrices) {
  auto problem = strip(60);
  const auto mesh = bem::mesh_body(problem);
  const auto conditions = bem::resolve_node_conditions(mesh, problem.body, problem.analysis);
  const auto constraints = bem::resolve_point_constraints(mesh, problem.body, conditions);
  const bem::ElementIntegrator integrator(problem.analysis, problem.body.material);
  for (double accuracy : {1e-4, 1e-6, 1e-8, 1e-10}) {
    operators::HMatrixOptions options;
    options.accuracy = accuracy;
    bem::CompressedBoundarySystem compressed(mesh, integrator, conditions, constraints, options, "the strip");
    auto matrices = bem::assemble_influence_matrices(mesh, integrator);
    const auto dense = bem::build_boundary_system(matrices, conditions, constraints);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Vector x(dense.A.cols());
    for (Index k = 0; k < x.size(); ++k) x[k] = uniform(random);
    const Vector exact = dense.A * x;
    const double operator_error = (compressed.apply(x) - exact).norm() / exact.norm();
    const double rhs_error = (compressed.rhs() - dense.b).norm() / dense.b.norm();
    EXPECT_LT(operator_error, 10.0 * accuracy) << accuracy;
    EXPECT_LT(rhs_error, 10.0 * accuracy) << accuracy;
    EXPECT_LT(compressed.compression_ratio(), 1.0);
  }
}

// The zeros the compressed assembly takes on trust (compressed_system.cpp, node_lines):
// between a node and the elements of another on the same straight line parallel to an axis,
// H_xx = H_yy = 0 and G_xy = G_yx = 0, the neighbours' (near-singular) integrals included,
// for linear and quadratic elements; in axisymmetry on the lines z = const (a plane through
// the ring loads), not on r = const (a cylinder).
TEST(CompressedSystem, KernelsVanishWhereTheLinesSayTheyDo) {
  for (const auto analysis : {AnalysisType::plane_strain, AnalysisType::axisymmetric})
    for (const auto interpolation : {Interpolation::linear, Interpolation::quadratic}) {
      auto problem = strip(6);
      problem.analysis = analysis;
      problem.mesh.interpolation = interpolation;
      const bool axisymmetric = analysis == AnalysisType::axisymmetric;
      if (axisymmetric)  // off the axis: r in [1, 5]
        for (auto& piece : problem.body.pieces) piece.start.x() += 1.0, piece.end.x() += 1.0;
      const auto mesh = bem::mesh_body(problem);
      const bem::ElementIntegrator integrator(problem.analysis, problem.body.material);
      const auto matrices = bem::assemble_influence_matrices(mesh, integrator);
      const double h = matrices.H.cwiseAbs().maxCoeff(), g = matrices.G.cwiseAbs().maxCoeff();
      int pairs = 0, cylinder_pairs = 0;
      for (const auto& piece : mesh.piece_nodes) {
        const bool horizontal = mesh.nodes[piece.front()].position.y() == mesh.nodes[piece.back()].position.y();
        // The piece's nodes but its ends (a corner's node has elements on two lines).
        for (std::size_t a = 1; a + 1 < piece.size(); ++a)
          for (std::size_t b = 1; b + 1 < piece.size(); ++b) {
            const Index i = piece[a], j = piece[b];
            if (i == j) continue;
            if (axisymmetric && !horizontal) {  // r = const: the ring kernels do not vanish
              cylinder_pairs += std::abs(matrices.G(2 * i, 2 * j + 1)) > 1e-6 * g ? 1 : 0;
              continue;
            }
            ++pairs;
            for (int k = 0; k < 2; ++k) {
              EXPECT_LE(std::abs(matrices.H(2 * i + k, 2 * j + k)), 1e-13 * h) << i << ", " << j;
              EXPECT_LE(std::abs(matrices.G(2 * i + k, 2 * j + 1 - k)), 1e-13 * g) << i << ", " << j;
            }
            EXPECT_GT(std::abs(matrices.H(2 * i, 2 * j + 1)), 0.0);  // the pairs that stay
            EXPECT_GT(std::abs(matrices.G(2 * i, 2 * j)), 0.0);
          }
      }
      EXPECT_GT(pairs, 1000);
      if (axisymmetric) EXPECT_GT(cylinder_pairs, 10);
    }
}

// The whole solve on compressed operators against the dense solve: displacements and
// tractions within a small multiple of the accuracy asked, falling with it; also for a free
// body held by point constraints (the transposed H-LU of the rigid-mode treatment).
TEST(CompressedSystem, SolutionFollowsTheAccuracyAsked) {
  for (bool free_body : {false, true}) {
    auto problem = strip(40, free_body);
    problem.operator_choice.kind = bem::OperatorKind::dense;
    const auto dense = bem::solve_body(problem);
    double previous = 1.0;
    for (double accuracy : {1e-4, 1e-6, 1e-8}) {
      problem.operator_choice.kind = bem::OperatorKind::compressed;
      problem.operator_choice.accuracy = accuracy;
      const auto compressed = bem::solve_body(problem);
      EXPECT_EQ(compressed.report.operator_kind, "compressed");
      EXPECT_EQ(compressed.report.constraints_fix_rigid_modes_only, free_body);
      const double du = relative_difference(compressed.boundary, dense.boundary, false);
      const double dp = relative_difference(compressed.boundary, dense.boundary, true);
      std::printf("free_body %d accuracy %.0e: u %.2e, p %.2e, residual %.2e, stored %.1f %%\n", free_body, accuracy,
                  du, dp, compressed.report.relative_residual, 100.0 * compressed.report.compression_ratio);
      EXPECT_LT(du, 100.0 * accuracy) << accuracy;
      EXPECT_LT(dp, 100.0 * accuracy) << accuracy;
      EXPECT_LT(std::max(du, dp), previous);
      EXPECT_LT(compressed.report.relative_residual, 10.0 * accuracy);
      previous = std::max(du, dp);
    }
  }
}

// A factored body (the decomposition's and the contact model's building block) on
// compressed operators against the same body dense: its interface maps (unit responses),
// the response to its own loads, a load group's and the whole solution, within 100 x the
// accuracy asked. Variable nodes of both kinds: the bottom's displacements, the top's
// tractions; the loaded end and the clamped start keep their own data.
TEST(CompressedSystem, FactoredBodyMatchesTheDenseOne) {
  auto problem = strip(20);
  const auto reference = bem::solve_body(problem);  // for the mesh
  const auto& mesh = reference.mesh;
  std::vector<bem::VariableNode> variable;
  for (Index node : mesh.piece_nodes[0]) variable.push_back({node, U});
  for (Index node : mesh.piece_nodes[2]) variable.push_back({node, T});
  bem::OperatorChoice dense_choice, compressed_choice;
  dense_choice.kind = bem::OperatorKind::dense;
  compressed_choice.kind = bem::OperatorKind::compressed;
  compressed_choice.accuracy = 1e-8;
  const bem::FactoredBody dense(mesh, problem.body, problem.analysis, variable, {}, {}, dense_choice);
  const bem::FactoredBody compressed(mesh, problem.body, problem.analysis, variable, {}, {}, compressed_choice);
  EXPECT_FALSE(dense.compressed());
  EXPECT_TRUE(compressed.compressed());
  EXPECT_TRUE(std::isnan(compressed.reciprocal_condition()));
  const auto relative = [](const Matrix& a, const Matrix& b) { return (a - b).norm() / b.norm(); };
  EXPECT_LT(relative(compressed.unit_responses(), dense.unit_responses()), 100.0 * compressed_choice.accuracy);
  const Vector zero = Vector::Zero(dense.variable_dofs());
  EXPECT_LT(relative(compressed.complementary(zero, true), dense.complementary(zero, true)),
            100.0 * compressed_choice.accuracy);
  ASSERT_EQ(compressed.load_groups(), dense.load_groups());
  EXPECT_LT(relative(compressed.group_complementary(0), dense.group_complementary(0)), 100.0 * compressed_choice.accuracy);
  Vector data = Vector::Zero(dense.variable_dofs());
  for (Index i = 0; i < data.size(); ++i) data[i] = 1e-3 * std::sin(0.7 * static_cast<double>(i));
  EXPECT_LT(relative_difference(compressed.solve(data), dense.solve(data), false), 100.0 * compressed_choice.accuracy);
  EXPECT_LT(relative_difference(compressed.solve(data), dense.solve(data), true), 100.0 * compressed_choice.accuracy);
}

// "auto" compresses from the threshold only where hmat-oss is built in (an MIT-only build
// stays dense instead of refusing); "compressed" is always taken (and refused without it).
TEST(CompressedSystem, AutoCompressesOnlyWhereHMatricesAreBuilt) {
  bem::OperatorChoice choice;
  EXPECT_FALSE(bem::use_compressed_operator(choice, bem::OperatorChoice::automatic_threshold - 1));
  EXPECT_EQ(bem::use_compressed_operator(choice, bem::OperatorChoice::automatic_threshold),
            operators::hmatrix_available());
  choice.kind = bem::OperatorKind::compressed;
  EXPECT_TRUE(bem::use_compressed_operator(choice, 10));
  choice.kind = bem::OperatorKind::dense;
  EXPECT_FALSE(bem::use_compressed_operator(choice, 1000000));
}

// Axisymmetry: a solid cylinder (nodes on the axis) under an uneven pressure and an end
// load. The diagonal blocks come from the axial translation and the radial expansion, whose
// traction integral is a compressed matrix of its own: the operator A and the solution
// against the dense ones within a small multiple of the accuracy asked.
TEST(CompressedSystem, AxisymmetricBodyMatchesTheDenseOne) {
  bem::ProblemDefinition problem;
  problem.analysis = AnalysisType::axisymmetric;
  problem.body.material = {200e3, 0.3};
  const auto zero = [](const Vec2&) { return Vec2(0.0, 0.0); };
  const auto pressure = [](const Vec2& x) { return Vec2(-(5.0 + 3.0 * x.y() * x.y()), 0.0); };
  const auto end_load = [](const Vec2& x) { return Vec2(0.0, 10.0 + 2.0 * x.x()); };
  test_support::add_piece(problem, "bottom", {0, 0}, {1, 0}, 60, {T, U}, zero, zero);
  test_support::add_piece(problem, "outer", {1, 0}, {1, 2}, 120, {T, T}, zero, pressure);
  test_support::add_piece(problem, "top", {1, 2}, {0, 2}, 60, {T, T}, zero, end_load);
  test_support::add_piece(problem, "axis", {0, 2}, {0, 0}, 120, {U, T}, zero, zero);
  const auto mesh = bem::mesh_body(problem);
  const auto conditions = bem::resolve_node_conditions(mesh, problem.body, problem.analysis);
  const bem::ElementIntegrator integrator(problem.analysis, problem.body.material);
  auto matrices = bem::assemble_influence_matrices(mesh, integrator);
  const auto dense_system = bem::build_boundary_system(matrices, conditions, {});
  problem.operator_choice.kind = bem::OperatorKind::dense;
  const auto dense = bem::solve_body(problem);
  for (double accuracy : {1e-6, 1e-9}) {
    operators::HMatrixOptions options;
    options.accuracy = accuracy;
    const bem::CompressedBoundarySystem compressed(mesh, integrator, conditions, {}, options, "the cylinder");
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Vector x(dense_system.A.cols());
    for (Index k = 0; k < x.size(); ++k) x[k] = uniform(random);
    const Vector exact = dense_system.A * x;
    EXPECT_LT((compressed.apply(x) - exact).norm() / exact.norm(), 10.0 * accuracy) << accuracy;
    EXPECT_LT((compressed.rhs() - dense_system.b).norm() / dense_system.b.norm(), 10.0 * accuracy) << accuracy;
    EXPECT_LT(compressed.compression_ratio(), 1.0);

    problem.operator_choice.kind = bem::OperatorKind::compressed;
    problem.operator_choice.accuracy = accuracy;
    const auto solution = bem::solve_body(problem);
    EXPECT_EQ(solution.report.operator_kind, "compressed");
    const double du = relative_difference(solution.boundary, dense.boundary, false);
    const double dp = relative_difference(solution.boundary, dense.boundary, true);
    std::printf("axisymmetric accuracy %.0e: u %.2e, p %.2e, stored %.1f %%\n", accuracy, du, dp,
                100.0 * solution.report.compression_ratio);
    EXPECT_LT(du, 100.0 * accuracy) << accuracy;
    EXPECT_LT(dp, 100.0 * accuracy) << accuracy;
  }
}

namespace bemcontact::bem {

// Likewise for hmat-oss: found by the configuration, then in the build.
TEST(CompressedSystem, TheBuildHasHierarchicalMatricesWhenTheConfigurationFoundThem) {
  EXPECT_EQ(operators::hmatrix_available(), static_cast<bool>(BEMCONTACT_EXPECT_HMAT));
}

}  // namespace bemcontact::bem

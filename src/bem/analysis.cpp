#include "bemcontact/bem/analysis.hpp"

#include <omp.h>

#include <sstream>

#include <chrono>

#include <limits>
#include <optional>

#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/bem/compressed_system.hpp"
#include "bemcontact/bem/resultants.hpp"
#include "bemcontact/bem/rigid_modes.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::bem {
geometry::MeshOptions effective_mesh_options(const ProblemDefinition& problem) {
  geometry::MeshOptions options = problem.mesh;
  options.skip_axis_pieces = problem.analysis == AnalysisType::axisymmetric;
  return options;
}

geometry::BoundaryMesh mesh_body(const ProblemDefinition& problem) {
  const auto& body = problem.body;
  if (body.conditions.size() != body.pieces.size())
    throw Error("internal: one boundary condition per piece expected");
  if (problem.analysis == AnalysisType::axisymmetric) {
    const double tolerance = 1e-9 * geometry::geometry_scale(body.pieces);
    for (const auto& piece : body.pieces)
      for (int k = 0; k <= 4; ++k)
        if (geometry::point_on_piece(piece, k / 4.0).position.x() < -tolerance)
          throw InputError(piece.where, "boundary '" + piece.name +
                                            "' reaches r < 0; axisymmetric sections lie in r >= 0");
  }
  return geometry::mesh_boundary(body.pieces, effective_mesh_options(problem));
}

BodyResult solve_body(const ProblemDefinition& problem, const ProgressCallback& progress) {
  BodyResult result;
  PhaseClock clock(result.timings);
  const auto& body = problem.body;
  result.mesh = mesh_body(problem);
  const auto conditions = resolve_node_conditions(result.mesh, body, problem.analysis);
  const auto constraints = resolve_point_constraints(result.mesh, body, conditions);
  // Interior points are sorted before the solve, so that a listed point outside the body
  // is reported at once.
  auto selection = select_interior_points(result.mesh, problem.interior_points);
  if (!selection.listed_outside.empty()) {
    const auto& p = *selection.listed_outside.front();
    throw InputError(p.where.file.empty() ? SourceLocation{problem.source_file, 0, "interior.points"} : p.where,
                     "point " + point_text(p.position) + " is not inside the body");
  }
  clock.lap("mesh");

  const ElementIntegrator integrator(problem.analysis, body.material);
  const Index dofs = 2 * result.mesh.node_count();
  const bool rigid_only =
      constraints_fix_only_rigid_modes(free_rigid_modes(result.mesh, conditions, problem.analysis), constraints);
  result.report.threads = omp_get_max_threads();
  result.report.unknowns = dofs + static_cast<Index>(constraints.size());
  const std::string what = "the boundary element system of body '" + body.name + "'";
  Vector y;
  std::optional<InfluenceMatrices> matrices;  // dense path
  std::optional<CompressedBoundarySystem> compressed;
  if (use_compressed_operator(problem.operator_choice, result.report.unknowns,
                              geometry::symmetry_line_count(result.mesh.images))) {
    operators::HMatrixOptions options;
    options.accuracy = compression_accuracy(problem.operator_choice, result.mesh);
    result.report.compression_accuracy = options.accuracy;
    compressed.emplace(result.mesh, integrator, conditions, constraints, options, what, progress);
    clock.lap("assembly");
    compressed->factorize(rigid_only, progress);
    result.report.operator_kind = "compressed";
    result.report.compression_ratio = compressed->compression_ratio();
    result.report.reciprocal_condition = std::numeric_limits<double>::quiet_NaN();
    const auto& system = *compressed;
    Matrix rhs = system.rhs();
    system.solve_in_place(rhs);
    y = rhs.col(0);
    if (rigid_only) y = rigid_mode_consistent_solution(system, system.reaction_columns(), y);
  } else {
    matrices = assemble_influence_matrices(result.mesh, integrator, progress);
    clock.lap("assembly");
    auto system = build_boundary_system(*matrices, conditions, constraints);
    const Matrix reaction_columns = system.A.block(0, dofs, dofs, static_cast<Index>(constraints.size()));
    PhaseProgress phase(progress, "LU factorisation");
    const operators::DenseLU lu(std::move(system.A), what, operators::DenseLU::default_singular_threshold,
                                  phase.fractions());
    result.report.reciprocal_condition = lu.reciprocal_condition();
    y = lu.solve(system.b);
    if (rigid_only) y = rigid_mode_consistent_solution(lu, reaction_columns, y);
    phase.finish();
  }
  if (!y.allFinite()) throw SolverError("the solution of body '" + body.name + "' is not finite");
  clock.lap("solve");

  // Constraints that only fix rigid modes carry no reaction (see rigid_modes.hpp).
  result.report.constraints_fix_rigid_modes_only = rigid_only;
  result.boundary = recover_boundary_values(y, conditions, rigid_only ? std::vector<ConstraintEquation>{} : constraints);
  result.report.relative_residual = compressed ? compressed->residual(result.boundary)
                                               : boundary_equation_residual(*matrices, conditions, result.boundary);
  result.boundary.stress = boundary_stresses(result.mesh, problem.analysis, body.material, result.boundary);
  result.boundary.resultants = boundary_resultants(result.mesh, result.boundary, body, problem.analysis);
  clock.lap("boundary stress");

  if (!problem.interior_points.empty()) {
    result.interior = interior_values(result.mesh, integrator, result.boundary, std::move(selection), progress);
    clock.lap("interior points");
  }
  return result;
}

}  // namespace bemcontact::bem

#pragma once
// JSON pieces of summary.json (nlohmann::json); the command assembles the summary.
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "bemcontact/bem/solution.hpp"
#include "bemcontact/bem/problem.hpp"

namespace bemcontact::io {

// Indented text with a final newline; SolverError naming the key when a number is NaN or
// infinite (JSON cannot hold them).
std::string write_json_string(const nlohmann::json& value, int indent = 2);

// {"phases": {"assembly": 0.12, ...}, "total": 0.3} (phases in the order run).
nlohmann::json timings_json(const bem::PhaseTimings& timings);
// {"unknowns", "reciprocal_condition", "relative_residual", "threads"}.
nlohmann::json solve_report_json(const bem::SolveReport& report);

// A condition estimate, or null where there is none (NaN: a compressed operator's H-LU).
nlohmann::json condition_json(double reciprocal_condition);
// The options actually used, defaults included: analysis, interpolation, mesh,
// material, parameters, every boundary (elements, grading, condition), constraints,
// interior point count, outputs; `evaluated` the [parameters] as read, `vtk` the [output] key.
nlohmann::json problem_echo_json(const bem::ProblemDefinition& problem, const std::map<std::string, double>& evaluated,
                                 bool vtk);

// Boundaries the corner transition graded (geometry::MeshOptions): name, elements asked
// and made.
nlohmann::json mesh_transitions_json(const geometry::BoundaryMesh& mesh);

// The [mesh] options in effect (interpolation, continuity, corner shift, transition).
nlohmann::json mesh_options_json(const geometry::MeshOptions& mesh);

// Resultant force (and moment in plane problems) of the tractions on each boundary
// (BoundarySolution::resultants): [{"boundary", "prescribed_displacement", "force": [f1, f2], "moment"}].
nlohmann::json resultants_json(const std::vector<bem::BoundaryResultant>& resultants, AnalysisType type);

// Terminal lines for the boundaries with prescribed displacements: their reactions.
std::string reactions_text(const std::vector<bem::BoundaryResultant>& resultants, AnalysisType type,
                           const std::string& label);

}  // namespace bemcontact::io

#include "bemcontact/io/output/json_writer.hpp"

#include <cmath>
#include <cstdio>

#include "bemcontact/core/error.hpp"

namespace bemcontact::io {

namespace {

// JSON has no NaN or infinity (nlohmann would write null): a non-finite number is a
// broken result, reported with its path in the document.
void check_finite(const nlohmann::json& value, const std::string& path) {
  if (value.is_number_float() && !std::isfinite(value.get<double>()))
    throw SolverError("the results hold a non-finite value at '" + path +
                      "' of the summary: the solution broke down (check the data for extreme values)");
  if (value.is_object())
    for (const auto& [key, item] : value.items()) check_finite(item, path.empty() ? key : path + "." + key);
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i) check_finite(value[i], path + "[" + std::to_string(i) + "]");
}

}  // namespace

std::string write_json_string(const nlohmann::json& value, int indent) {
  check_finite(value, "");
  // Invalid UTF-8 in a title must not abort the summary: replace it.
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

nlohmann::json timings_json(const bem::PhaseTimings& timings) {
  nlohmann::json phases = nlohmann::json::array();
  for (const auto& [name, seconds] : timings.phases)
    phases.push_back({{"name", name}, {"seconds", seconds}});
  return {{"phases", phases}, {"total", timings.total()}};
}

nlohmann::json condition_json(double reciprocal_condition) {
  return std::isnan(reciprocal_condition) ? nlohmann::json(nullptr) : nlohmann::json(reciprocal_condition);
}

nlohmann::json solve_report_json(const bem::SolveReport& report) {
  return {{"unknowns", report.unknowns},
          {"reciprocal_condition", condition_json(report.reciprocal_condition)},
          {"relative_residual", report.relative_residual},
          {"threads", report.threads}};
}

nlohmann::json problem_echo_json(const bem::ProblemDefinition& problem, const std::map<std::string, double>& evaluated,
                                 bool vtk) {
  nlohmann::json boundaries = nlohmann::json::array();
  for (std::size_t i = 0; i < problem.body.pieces.size(); ++i) {
    const auto& piece = problem.body.pieces[i];
    nlohmann::json entry{
        {"name", piece.name},
        {"shape", piece.shape == geometry::PieceShape::arc ? "arc" : "line"},
        {"from", {piece.start.x(), piece.start.y()}},
        {"to", {piece.end.x(), piece.end.y()}},
        {"elements", piece.elements},
        {"grading", piece.grading},
        {"refine", piece.refine_toward == geometry::RefineToward::end ? "end" : "start"},
        {"condition", i < problem.body.conditions.size() ? problem.body.conditions[i].signature
                                                         : piece.condition_signature}};
    if (piece.shape == geometry::PieceShape::arc) {
      entry["center"] = {piece.center.x(), piece.center.y()};
      entry["direction"] = piece.counterclockwise ? "ccw" : "cw";
    }
    boundaries.push_back(entry);
  }
  nlohmann::json constraints = nlohmann::json::array();
  for (const auto& constraint : problem.body.constraints) {
    nlohmann::json entry{{"at", constraint.label},
                         {"position", {constraint.position.x(), constraint.position.y()}}};
    for (int c = 0; c < 2; ++c)
      if (constraint.displacement[c]) entry[c == 0 ? "u1" : "u2"] = *constraint.displacement[c];
    constraints.push_back(entry);
  }
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [name, value] : evaluated) parameters[name] = value;
  return {{"title", problem.title},
          {"source_file", problem.source_file},
          {"analysis", to_string(problem.analysis)},
          {"interpolation", to_string(problem.mesh.interpolation)},
          {"mesh", mesh_options_json(problem.mesh)},
          {"material",
           {{"E", problem.body.material.young_modulus}, {"nu", problem.body.material.poisson_ratio}}},
          {"parameters", parameters},
          {"boundaries", boundaries},
          {"constraints", constraints},
          {"interior_points", problem.interior_points.size()},
          {"output", {{"vtk", vtk}}}};
}

nlohmann::json mesh_options_json(const geometry::MeshOptions& mesh) {
  return {{"interpolation", to_string(mesh.interpolation)},
          {"continuity", mesh.discontinuous ? "discontinuous" : "continuous"},
          {"corner_shift", mesh.corner_shift},
          {"corner_transition", mesh.corner_transition},
          {"split_angle_radians", mesh.split_angle_radians}};
}

nlohmann::json mesh_transitions_json(const geometry::BoundaryMesh& mesh) {
  nlohmann::json graded = nlohmann::json::array();
  for (const auto& t : mesh.transitions)
    graded.push_back({{"boundary", t.name}, {"elements_asked", t.elements_asked}, {"elements", t.elements}});
  return graded;
}

nlohmann::json resultants_json(const std::vector<bem::BoundaryResultant>& resultants, AnalysisType type) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& r : resultants) {
    nlohmann::json entry = {{"boundary", r.boundary},
                            {"prescribed_displacement", r.prescribed_displacement},
                            {"force", {r.force.x(), r.force.y()}}};
    if (type != AnalysisType::axisymmetric) entry["moment"] = r.moment;
    list.push_back(entry);
  }
  return list;
}

std::string reactions_text(const std::vector<bem::BoundaryResultant>& resultants, AnalysisType type,
                           const std::string& label) {
  std::string text;
  char line[512];
  for (const auto& r : resultants) {
    if (!r.prescribed_displacement) continue;
    if (type == AnalysisType::axisymmetric)
      std::snprintf(line, sizeof line, "  %sreaction on '%s': F_z = %.6g (whole ring)\n", label.c_str(),
                    r.boundary.c_str(), r.force.y());
    else
      std::snprintf(line, sizeof line, "  %sreaction on '%s': F = (%.6g, %.6g), M = %.6g (about the origin)\n",
                    label.c_str(), r.boundary.c_str(), r.force.x(), r.force.y(), r.moment);
    text += line;
  }
  return text;
}

}  // namespace bemcontact::io

#include "bemcontact/driver/run.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/dd/solver.hpp"
#include "bemcontact/driver/resource_check.hpp"
#include "bemcontact/operators/dense_lu.hpp"
#include "bemcontact/geometry/boundary.hpp"
#include "bemcontact/io/file_names.hpp"
#include "bemcontact/io/input/problem_reader.hpp"
#include "bemcontact/io/output/contact_writer.hpp"
#include "bemcontact/io/output/decomposition_writer.hpp"
#include "bemcontact/io/output/json_writer.hpp"
#include "bemcontact/io/output/plasticity_writer.hpp"
#include "bemcontact/io/output/results_writer.hpp"
#include "bemcontact/io/output/run_summary.hpp"

namespace bemcontact::driver {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// printf into a string.
[[gnu::format(printf, 2, 3)]] void append(std::string& text, const char* format, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  text += buffer;
}

// Neighbouring elements of very different lengths (mesh_quality_warnings), named by body
// when there are several.
void add_mesh_warnings(std::vector<std::string>& warnings, const geometry::BoundaryMesh& mesh,
                       const std::string& label) {
  for (const auto& warning : geometry::mesh_quality_warnings(mesh))
    warnings.push_back(label.empty() ? warning : label + ": " + warning);
}

// Linear elasticity assumes small strains and rotations: displacements that vary over a body
// by more than 2 % of its size (its translation aside) are outside the model, and most often
// a unit mistake (E in GPa with loads in MPa). The same bound as a large interference.
void add_small_strain_warning(std::vector<std::string>& warnings, const geometry::BoundaryMesh& mesh,
                              const bem::BoundarySolution& solution, const std::string& label) {
  if (solution.displacement.empty()) return;
  Vec2 mean = Vec2::Zero();
  for (const auto& u : solution.displacement) mean += u / static_cast<double>(solution.displacement.size());
  double spread = 0.0;
  for (const auto& u : solution.displacement) spread = std::max(spread, (u - mean).norm());
  if (!(spread > 0.02 * mesh.scale)) return;
  char text[512];
  std::snprintf(text, sizeof text,
                "%sthe displacements vary by %.3g over the body, %.3g %% of its size %.3g: linear elasticity assumes "
                "small strains (a few per mille); check the units (E in MPa with lengths in mm and forces in N) and "
                "the loads",
                label.empty() ? "" : (label + ": ").c_str(), spread, 100.0 * spread / mesh.scale, mesh.scale);
  warnings.push_back(text);
}

// Likely mistakes in the geometry of each body (geometry_warnings), named by body when
// there are several.
void add_geometry_warnings(std::vector<std::string>& warnings, const bem::BodyDefinition& body,
                           const std::string& label) {
  for (const auto& warning : geometry::geometry_warnings(body.pieces))
    warnings.push_back(label.empty() ? warning : label + ": " + warning);
}

json mesh_json(const geometry::BoundaryMesh& mesh) {
  int split = 0;
  for (const auto& v : mesh.vertices) split += v.split;
  return {{"nodes", mesh.node_count()}, {"elements", mesh.element_count()},
          {"contours", mesh.contours.size()}, {"split_corners", split},
          {"graded_toward_vertices", io::mesh_transitions_json(mesh)}};
}

// The mesh block of summary.json: totals, and each region's own counts by name.
json meshes_json(const std::vector<std::pair<std::string, const geometry::BoundaryMesh*>>& meshes) {
  Index nodes = 0, elements = 0;
  json regions = json::object();
  for (const auto& [name, mesh] : meshes) {
    nodes += mesh->node_count();
    elements += mesh->element_count();
    regions[name] = mesh_json(*mesh);
  }
  return {{"nodes", nodes}, {"elements", elements}, {"regions", regions}};
}

io::RunSummary summary_envelope(const char* kind, const char* command, std::string_view text,
                                const std::string& file_name, const std::string& title, AnalysisType analysis) {
  io::RunSummary s;
  s.kind = kind;
  s.command = command;
  s.title = title;
  s.analysis = to_string(analysis);
  s.input_file = file_name;
  s.input_text = text;
  s.options["threads"] = omp_get_max_threads();
  s.options["blas_kernels"] = operators::blas_core_name();
  return s;
}

// A file of the run; a CSV file's table is also kept when the caller asks (keep_tables).
void add_file(RunOutput& output, const RunOptions& options, io::OutputFile file) {
  if (auto* table = std::get_if<io::CsvTable>(&file.content)) {
    output.files.add(file.name, io::csv_text(*table));
    if (options.keep_tables) output.tables.emplace(std::move(file.name), std::move(*table));
  } else {
    output.files.add(std::move(file.name), std::move(std::get<std::string>(file.content)));
  }
}

// summary.json, last, listing the files added before it. A run also keeps its problem text
// (problem.toml, byte for byte: its SHA-256 is the summary's), from which `probe` meshes it again.
void add_summary(io::RunSummary& summary, RunOutput& output) {
  if (summary.command == "run") output.files.add("problem.toml", std::string(summary.input_text));
  summary.warnings = output.warnings;
  summary.estimate = output.estimate;
  summary.outputs = output.files.names();
  output.files.add("summary.json", io::write_json_string(io::summary_json(summary)));
}

// One line per boundary the corner transition graded (geometry::MeshOptions).
void append_transitions(std::string& report, const geometry::BoundaryMesh& mesh, const std::string& label) {
  for (const auto& t : mesh.transitions)
    append(report, "  %sboundary '%s' graded toward a finer neighbour: %d elements (%d asked)\n", label.c_str(),
           t.name.c_str(), t.elements, t.elements_asked);
}

// "  time T s (phase t, phase t, ...)": a run's total and its phases.
void append_times(std::string& report, double total, const bem::PhaseTimings& timings) {
  append(report, "  time %.3f s (", total);
  bool first = true;
  for (const auto& [phase, seconds] : timings.phases) {
    append(report, "%s%s %.3f", first ? "" : ", ", phase.c_str(), seconds);
    first = false;
  }
  report += ")\n";
}

// Checks the resource limits of the problem a solver takes before anything is solved, and
// starts the output with the reader's warnings.
template <class Problem>
void check_read(const Problem& problem, const io::ProblemInput& input, const RunOptions& options, RunOutput& output) {
  check_resources(problem, options.limits);
  const ResourceEstimate estimate = estimate_resources(problem);
  output.estimate = {{"unknowns", estimate.total_unknowns},
                     {"largest_body_unknowns", estimate.unknowns},
                     {"memory_bytes", estimate.bytes},
                     {"recorded_steps_bytes", estimate.recording_bytes},
                     {"contact_pairs", estimate.contact_pairs},
                     {"contact_operator_bytes", estimate.contact_bytes},
                     {"contact_operator", estimate.contact_pairs == 0 ? "none"
                                          : estimate.contact_matrix_free ? "matrix_free" : "dense"},
                     {"seconds", estimate.seconds},
                     {"threads", estimate.threads},
                     {"elastoplastic_regions_not_included", estimate.elastoplastic_regions}};
  if (options.notice) options.notice(describe(estimate));
  output.warnings = input.warnings;
}

// A body the file named writes <name>_boundary.csv, ...; a one-body file boundary.csv.
std::string file_prefix(const contact::Body& body) { return io::body_file_prefix(body.name, body.named); }

// What to change when the interface GMRES does not converge.
std::string convergence_advice(const dd::DecompositionOptions& options, const dd::DecompositionResult& result) {
  const int m = dd::effective_restart(options, result.interface_unknowns);
  if (m < result.gmres.iterations)
    return "GMRES(" + std::to_string(m) + ") restarts lose the Krylov space: remove 'restart' from [decomposition] "
           "(full GMRES, the default) or raise it";
  if (options.preconditioner == dd::InterfacePreconditioner::none)
    return "raise max_iterations in [decomposition] (now " + std::to_string(options.max_iterations) +
           ") or use method = \"conforming\" with the balancing preconditioner (the default)";
  return "raise max_iterations in [decomposition] (now " + std::to_string(options.max_iterations) +
         ") or loosen tolerance; the balanced iteration stalling usually means the subdomains' rigid motions are "
         "held by a very soft part: check the materials and conditions";
}

// Several subdomains glued along interfaces (chapter IV).
RunOutput run_decomposition(const io::ProblemInput& input, const dd::DecompositionProblem& problem, std::string_view text,
                            const std::string& file_name, const RunOptions& options, Clock::time_point started) {
  RunOutput output;
  check_read(problem, input, options, output);
  // Its parts as the file calls them: subdomains ([[subdomain]]) or regions ([[body.region]]).
  const std::string& part = problem.part_word;
  for (const auto& subdomain : problem.subdomains)
    add_geometry_warnings(output.warnings, subdomain.body, part + " '" + subdomain.body.name + "'");
  const auto result = dd::solve_decomposition(problem, options.progress, options.parallel);
  for (const auto& subdomain : result.subdomains) {
    add_mesh_warnings(output.warnings, subdomain.mesh, part + " '" + subdomain.name + "'");
    if (result.converged())
      add_small_strain_warning(output.warnings, subdomain.mesh, subdomain.boundary, part + " '" + subdomain.name + "'");
  }
  auto summary = summary_envelope("decomposition", "run", text, file_name, problem.title, problem.analysis);
  summary.parameters = input.parameters;
  const auto& o = problem.options;
  summary.options.update({{"mesh", io::mesh_options_json(problem.mesh)},
                          {"method", dd::to_string(o.method)},
                          {"preconditioner", dd::to_string(o.preconditioner)},
                          {"restart", o.restart},
                          {"tolerance", o.tolerance},
                          {"max_iterations", o.max_iterations},
                          {"interface_tolerance", o.interface_tolerance},
                          {"displacement_nodes", o.displacement_nodes}});
  summary.problem = {{"subdomains", problem.subdomains.size()}};
  std::vector<std::pair<std::string, const geometry::BoundaryMesh*>> meshes;
  for (const auto& subdomain : result.subdomains) {
    meshes.emplace_back(subdomain.name, &subdomain.mesh);
    if (result.converged())
      summary.reactions[subdomain.name] = io::resultants_json(subdomain.boundary.resultants, problem.analysis);
  }
  summary.mesh = meshes_json(meshes);
  summary.results = {{"decomposition", io::decomposition_summary_json(problem, result)}};
  if (result.converged()) {
    for (auto& output_file : io::decomposition_files(result, problem.title, input.vtk))
      add_file(output, options, std::move(output_file));
  } else {
    // No answer from an unconverged iteration: only the diagnostics.
    add_file(output, options, {"gmres.csv", io::gmres_history_table(result.gmres)});
    output.solver_failure_details = {"interface GMRES", result.gmres.iterations, result.gmres.relative_residual};
    output.solver_failure = "the interface problem did not converge: " + result.gmres.message + "; " +
                            convergence_advice(problem.options, result);
  }
  summary.timings = {{"total", seconds_since(started)}};
  add_summary(summary, output);

  std::string& report = output.report;
  append(report, "%s\n  %zu %ss, method %s, %ld interface unknowns\n", problem.title.c_str(),
         result.subdomains.size(), part.c_str(), dd::to_string(result.method), static_cast<long>(result.interface_unknowns));
  if (result.processes > 1) append(report, "  %d processes (MPI), PETSc GMRES\n", result.processes);
  append(report, "  GMRES(%d), preconditioner %s: %d iterations, relative residual %.3g\n",
         dd::effective_restart(problem.options, result.interface_unknowns),
         dd::to_string(result.preconditioner), result.gmres.iterations, result.gmres.relative_residual);
  if (result.preconditioner == dd::InterfacePreconditioner::balancing)
    append(report, "  coarse space: %ld rigid modes\n", static_cast<long>(result.coarse_dimension));
  double jump_u = 0.0, jump_p = 0.0;
  for (const auto& j : result.jumps) jump_u = std::max(jump_u, j.jump_u), jump_p = std::max(jump_p, j.jump_p);
  append(report, "  max interface jumps: [u] = %.3g, [p] = %.3g\n", jump_u, jump_p);
  for (std::size_t s = 0; s < result.subdomains.size(); ++s) {
    const auto& subdomain = result.subdomains[s];
    append_transitions(report, subdomain.mesh, part + " '" + subdomain.name + "': ");
    if (result.converged())
      report += io::reactions_text(subdomain.boundary.resultants, problem.analysis,
                                   part + " '" + subdomain.name + "': ");
  }
  append(report, "  time %.3f s\n", seconds_since(started));
  return output;
}

// Bodies in contact (chapter V): elastic bodies of one or more regions, rigid indenters.
RunOutput run_contact(const io::ProblemInput& input, std::string_view text, const std::string& file_name,
                      const RunOptions& options, Clock::time_point started) {
  const contact::ContactProblem& problem = input.model;
  RunOutput output;
  check_read(problem, input, options, output);
  for (const auto& body : problem.bodies)
    for (const auto& region : body.regions)
      add_geometry_warnings(output.warnings, region.body,
                            body.regions.size() == 1 ? "body '" + body.name + "'"
                                                     : "region '" + region.body.name + "' of body '" + body.name + "'");
  contact::ContactProblem limited = problem;
  limited.memory_limit_bytes = options.limits.memory_limit_bytes();
  const auto result = contact::solve_contact(limited, options.progress);
  output.warnings.insert(output.warnings.end(), result.warnings.begin(), result.warnings.end());
  for (std::size_t r = 0; r < result.meshes.size(); ++r) {
    add_mesh_warnings(output.warnings, result.meshes[r], result.region_labels[r]);
    add_small_strain_warning(output.warnings, result.meshes[r], result.boundary[r], result.region_labels[r]);
  }
  // Moved, not copied: recorded steps make these files large.
  for (auto& output_file : io::contact_output_files(problem, result, input.vtk))
    add_file(output, options, std::move(output_file));
  auto summary = summary_envelope("contact", "run", text, file_name, problem.title, problem.analysis);
  summary.parameters = input.parameters;
  io::fill_contact_summary(summary, problem, result);
  add_summary(summary, output);
  output.report = io::contact_report_text(problem, result);
  for (std::size_t r = 0; r < result.meshes.size(); ++r) {
    const std::string label = result.region_labels[r] + ": ";
    append_transitions(output.report, result.meshes[r], label);
    output.report += io::reactions_text(result.boundary[r].resultants, problem.analysis, label);
  }
  append(output.report, "  time %.3f s\n", seconds_since(started));
  return output;
}

RunOutput run_body(const io::ProblemInput& input, const bem::ProblemDefinition& problem, std::string_view text,
                   const std::string& file_name, const RunOptions& options, Clock::time_point started) {
  RunOutput output;
  check_read(problem, input, options, output);
  const double read_seconds = seconds_since(started);
  add_geometry_warnings(output.warnings, problem.body, "");
  const auto result = bem::solve_body(problem, options.progress);
  add_mesh_warnings(output.warnings, result.mesh, "");
  add_small_strain_warning(output.warnings, result.mesh, result.boundary, "");

  const auto write_started = Clock::now();
  io::OutputDirectory& out = output.files;
  const std::string prefix = file_prefix(input.model.bodies[0]);
  add_file(output, options, {prefix + "boundary.csv", io::boundary_table(result.mesh, result.boundary)});
  if (!result.interior.points.empty())
    add_file(output, options, {prefix + "interior.csv", io::interior_table(result.interior)});
  if (input.vtk) {
    out.add(prefix + "boundary.vtk", io::boundary_vtk(result.mesh, result.boundary, problem.title));
    if (!result.interior.points.empty())
      out.add(prefix + "interior.vtk", io::interior_vtk(result.interior, problem.title));
  }
  double max_vm = 0.0, max_u = 0.0;
  Index max_vm_node = 0;
  for (Index i = 0; i < result.mesh.node_count(); ++i) {
    const double vm = result.boundary.stress[i].von_mises();
    if (vm > max_vm) max_vm = vm, max_vm_node = i;
    max_u = std::max(max_u, std::hypot(result.boundary.displacement[i].x(), result.boundary.displacement[i].y()));
  }
  double interior_max_vm = 0.0;
  for (const auto& s : result.interior.stress) interior_max_vm = std::max(interior_max_vm, s.von_mises());
  // Summary last, with the write time of the other files.
  json timings = {{"read", read_seconds}};
  for (const auto& [phase, seconds] : result.timings.phases) timings[phase] = seconds;
  timings["write"] = seconds_since(write_started);
  timings["total"] = seconds_since(started);
  const auto& peak = result.mesh.nodes[max_vm_node].position;
  auto summary = summary_envelope("body", "run", text, file_name, problem.title, problem.analysis);
  summary.parameters = input.parameters;
  summary.options.update({{"mesh", io::mesh_options_json(problem.mesh)}});
  summary.problem = io::problem_echo_json(problem, input.parameters, input.vtk);
  summary.mesh = meshes_json({{problem.body.name, &result.mesh}});
  summary.results = {{"solve", {{"unknowns", result.report.unknowns},
                                {"operator", result.report.operator_kind},
                                {"compression_ratio", result.report.compression_ratio},
                                {"compression_accuracy", result.report.compression_accuracy},
                                {"reciprocal_condition_estimate", io::condition_json(result.report.reciprocal_condition)},
                                {"relative_residual", result.report.relative_residual},
                                {"constraints_fix_rigid_modes_only", result.report.constraints_fix_rigid_modes_only}}},
                     {"max_boundary_displacement", max_u},
                     {"max_boundary_von_mises", max_vm},
                     {"max_boundary_von_mises_at", {peak.x(), peak.y()}},
                     {"interior_points", result.interior.points.size()},
                     {"interior_points_dropped_outside", result.interior.dropped_points.size()},
                     {"max_interior_von_mises", interior_max_vm}};
  summary.reactions[problem.body.name] = io::resultants_json(result.boundary.resultants, problem.analysis);
  summary.timings = timings;
  add_summary(summary, output);

  std::string& report = output.report;
  append(report, "%s\n", problem.title.c_str());
  append(report, "  %s, %s elements: %ld nodes, %ld elements, %ld unknowns\n", to_string(problem.analysis),
         to_string(problem.mesh.interpolation), static_cast<long>(result.mesh.node_count()),
         static_cast<long>(result.mesh.element_count()), static_cast<long>(result.report.unknowns));
  append_transitions(report, result.mesh, "");
  if (result.report.operator_kind == "compressed")
    append(report, "  compressed operator (accuracy %.3g): %.3g %% of the dense values stored, relative residual = %.3g\n",
           result.report.compression_accuracy, 100.0 * result.report.compression_ratio,
           result.report.relative_residual);
  else
    append(report, "  condition estimate 1/rcond = %.3g, relative residual = %.3g\n",
           1.0 / result.report.reciprocal_condition, result.report.relative_residual);
  append(report, "  max |u| on the boundary = %.6g, max von Mises = %.6g at (%.6g, %.6g)\n", max_u, max_vm,
         peak.x(), peak.y());
  report += io::reactions_text(result.boundary.resultants, problem.analysis, "");
  if (!result.interior.points.empty())
    append(report, "  %zu interior points (%zu outside dropped), max von Mises = %.6g\n",
           result.interior.points.size(), result.interior.dropped_points.size(), interior_max_vm);
  append_times(report, timings["total"].get<double>(), result.timings);
  return output;
}

// One elastoplastic region under the history's steps (docs/plasticity.md).
RunOutput run_elastoplastic(const io::ProblemInput& input, const contact::ElastoplasticHistory& history,
                            std::string_view text, const std::string& file_name, const RunOptions& options,
                            Clock::time_point started) {
  const bem::ProblemDefinition& problem = history.problem;
  RunOutput output;
  check_read(problem, input, options, output);
  const double read_seconds = seconds_since(started);
  add_geometry_warnings(output.warnings, problem.body, "");
  const auto result = bem::solve_elastoplastic_body(problem, history.times, history.amplitudes, options.progress,
                                                    options.limits.memory_limit_bytes());
  output.warnings.insert(output.warnings.end(), result.warnings.begin(), result.warnings.end());
  add_mesh_warnings(output.warnings, result.mesh, "");
  add_small_strain_warning(output.warnings, result.mesh, result.boundary, "");

  const auto write_started = Clock::now();
  const std::string prefix = file_prefix(input.model.bodies[0]);
  add_file(output, options, {prefix + "boundary.csv", io::boundary_table(result.mesh, result.boundary)});
  add_file(output, options, {prefix + "cells.csv", io::cells_table(result)});
  add_file(output, options, {prefix + "steps.csv", io::elastoplastic_steps_table(result)});
  if (!result.interior.points.empty())
    add_file(output, options, {prefix + "interior.csv", io::interior_table(result.interior)});
  if (input.vtk) {
    output.files.add(prefix + "boundary.vtk", io::boundary_vtk(result.mesh, result.boundary, problem.title));
    output.files.add(prefix + "cells.vtk", io::cells_vtk(result, problem.title));
    if (!result.interior.points.empty())
      output.files.add(prefix + "interior.vtk", io::interior_vtk(result.interior, problem.title));
  }
  json timings = {{"read", read_seconds}};
  for (const auto& [phase, seconds] : result.timings.phases) timings[phase] = seconds;
  timings["write"] = seconds_since(write_started);
  timings["total"] = seconds_since(started);
  auto summary = summary_envelope("elastoplastic", "run", text, file_name, problem.title, problem.analysis);
  summary.parameters = input.parameters;
  summary.options.update({{"mesh", io::mesh_options_json(problem.mesh)}});
  summary.problem = io::problem_echo_json(problem, input.parameters, input.vtk);
  summary.mesh = meshes_json({{problem.body.name, &result.mesh}});
  const json plastic = io::elastoplastic_summary_json(result);
  summary.results = {{"elastoplastic", plastic}};
  summary.reactions[problem.body.name] = io::resultants_json(result.boundary.resultants, problem.analysis);
  summary.timings = timings;
  add_summary(summary, output);

  std::string& report = output.report;
  const auto& zone = plastic["plastic_zone"];
  append(report, "%s\n", problem.title.c_str());
  append(report, "  %s, %ld nodes, %zu cells (%.3g to %.3g)\n", to_string(problem.analysis),
         static_cast<long>(result.mesh.node_count()), result.cells.size(), plastic["smallest_cell"].get<double>(),
         plastic["largest_cell"].get<double>());
  append(report, "  %zu steps: %d Newton iterations (at most %d in a step), %d cuts\n", result.steps.size(),
         plastic["newton_iterations"].get<int>(), plastic["most_newton_iterations_in_a_step"].get<int>(),
         plastic["cuts"].get<int>());
  append(report, "  plastic zone: %d cells, area %.6g, largest equivalent plastic strain %.6g\n",
         zone["yielded_cells"].get<int>(), zone["area"].get<double>(), zone["max_equivalent_plastic_strain"].get<double>());
  report += io::reactions_text(result.boundary.resultants, problem.analysis, "");
  append_times(report, timings["total"].get<double>(), result.timings);
  return output;
}

}  // namespace

RunOutput run_problem(std::string_view text, const std::string& file_name, const RunOptions& options) {
  const auto started = Clock::now();
  // The text parsed once into the model; what it holds picks the solver (docs/model.md).
  const io::ProblemInput input = io::read_problem(text, file_name, options.overrides, options.limits);
  const contact::SolverRoute route = contact::route_of(input.model);
  if (options.parallel.distribution.size > 1 && route != contact::SolverRoute::decomposition)
    throw InputError(SourceLocation{file_name, 0, ""},
                     "runs on several processes (mpirun -n " + std::to_string(options.parallel.distribution.size) +
                         ") serve one body of several regions without contact (the decomposition); this problem "
                         "takes the " + contact::to_string(route) + " solver: run it on one process");
  RunOutput output;
  switch (route) {
    case contact::SolverRoute::direct:
      output = run_body(input, contact::single_region_problem(input.model), text, file_name, options, started);
      break;
    case contact::SolverRoute::decomposition:
      output = run_decomposition(input, contact::decomposition_problem(input.model, input.decomposition, input.region_word),
                                 text, file_name, options, started);
      break;
    case contact::SolverRoute::condensed: output = run_contact(input, text, file_name, options, started); break;
    case contact::SolverRoute::elastoplastic:
      output = run_elastoplastic(input, contact::elastoplastic_history(input.model), text, file_name, options, started);
      break;
  }
  check_output_finite(output.files);
  return output;
}

namespace {

// `mesh` of a model of bodies, regions and contacts: every region's mesh and every
// contact's pairs, as the solver would use them.
RunOutput mesh_model(const contact::ContactProblem& problem, RunOutput output, io::RunSummary summary,
                     const RunOptions& options) {
  const auto prepared = contact::prepare_contact(problem);
  std::vector<std::pair<std::string, const geometry::BoundaryMesh*>> meshes;
  output.warnings.insert(output.warnings.end(), prepared.warnings.begin(), prepared.warnings.end());
  for (const auto& region : prepared.regions) {
    add_mesh_warnings(output.warnings, region.mesh, region.label);
    meshes.emplace_back(region.label, &region.mesh);
    append(output.report, "%s: %ld nodes, %ld elements\n", region.label.c_str(),
           static_cast<long>(region.mesh.node_count()), static_cast<long>(region.mesh.element_count()));
    append_transitions(output.report, region.mesh, region.label + ": ");
  }
  for (std::size_t c = 0; c < prepared.contacts.size(); ++c) {
    append(output.report, "contact '%s': %zu pairs, %d nodes of side 1 facing nothing\n",
           problem.contacts[c].name.c_str(), prepared.contacts[c].pairs.size(), prepared.contacts[c].unpaired_nodes1);
    if (problem.contacts[c].adaptivity.on())
      append(output.report, "  its zone is found by the solver (contact_resolution %g): this is the first pass's mesh; "
                            "`run` refines it where the candidates touch\n", problem.contacts[c].adaptivity.resolution);
  }
  for (auto& output_file : io::contact_mesh_files(problem, prepared)) add_file(output, options, std::move(output_file));
  summary.mesh = meshes_json(meshes);
  json pairs = json::object();
  for (std::size_t c = 0; c < prepared.contacts.size(); ++c)
    pairs[problem.contacts[c].name] = {{"pairs", prepared.contacts[c].pairs.size()},
                                       {"unpaired_nodes_side1", prepared.contacts[c].unpaired_nodes1}};
  summary.results = {{"contacts", pairs}};
  summary.problem = {{"bodies", problem.bodies.size()}, {"regions", prepared.regions.size()},
                     {"contacts", problem.contacts.size()}};
  add_summary(summary, output);
  check_output_finite(output.files);
  return output;
}

}  // namespace

RunOutput mesh_problem(std::string_view text, const std::string& file_name, const RunOptions& options) {
  io::ProblemInput input = io::read_problem(text, file_name, options.overrides, options.limits);
  // Meshing records no load steps: their memory is not asked for.
  input.model.record_steps = false;
  const contact::SolverRoute route = contact::route_of(input.model);
  RunOutput output;
  if (route != contact::SolverRoute::direct) {
    const auto& model = input.model;
    if (route == contact::SolverRoute::decomposition)
      check_read(contact::decomposition_problem(model, input.decomposition, input.region_word), input, options, output);
    else
      check_read(model, input, options, output);
    const char* kind = route == contact::SolverRoute::decomposition ? "decomposition"
                       : model.contacts.empty()                    ? "bodies"
                                                                   : "contact";
    auto summary = summary_envelope(kind, "mesh", text, file_name, model.title, model.analysis);
    summary.parameters = input.parameters;
    return mesh_model(model, std::move(output), std::move(summary), options);
  }
  const auto problem = contact::single_region_problem(input.model);
  output.warnings = input.warnings;
  add_geometry_warnings(output.warnings, problem.body, "");
  const auto mesh = bem::mesh_body(problem);
  const std::string prefix = file_prefix(input.model.bodies[0]);
  add_file(output, options, {prefix + "mesh_nodes.csv", io::mesh_nodes_table(mesh)});
  add_file(output, options, {prefix + "mesh_elements.csv", io::mesh_elements_table(mesh)});
  output.files.add(prefix + "mesh.vtk", io::mesh_vtk(mesh, problem.title));
  append(output.report, "%s: %ld nodes, %ld elements\n", problem.title.c_str(),
         static_cast<long>(mesh.node_count()), static_cast<long>(mesh.element_count()));
  auto summary = summary_envelope("body", "mesh", text, file_name, problem.title, problem.analysis);
  summary.parameters = input.parameters;
  summary.options.update({{"mesh", io::mesh_options_json(problem.mesh)}});
  summary.problem = io::problem_echo_json(problem, input.parameters, input.vtk);
  summary.mesh = meshes_json({{problem.body.name, &mesh}});
  add_summary(summary, output);
  check_output_finite(output.files);
  return output;
}

}  // namespace bemcontact::driver

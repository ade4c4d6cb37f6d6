// bemcontact: command line. Arguments -> problem file -> solve -> writers.
#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/dd/solver.hpp"
#include "bemcontact/io/contact_file.hpp"
#include "bemcontact/io/contact_writer.hpp"
#include "bemcontact/io/decomposition_file.hpp"
#include "bemcontact/io/decomposition_writer.hpp"
#include "bemcontact/io/json_writer.hpp"
#include "bemcontact/io/output_directory.hpp"
#include "bemcontact/io/problem_file.hpp"
#include "bemcontact/io/results_writer.hpp"
#include "bemcontact/validation/validation.hpp"

#ifndef BEMCONTACT_EXAMPLES_DIR
#define BEMCONTACT_EXAMPLES_DIR "examples"
#endif

namespace {

using namespace bemcontact;
using nlohmann::json;

enum ExitCode { ok = 0, validation_failed = 1, bad_input = 2, solver_failed = 3, internal = 4 };

// Progress on stderr, only when it is a terminal and not silenced.
bem::ProgressCallback make_progress(bool quiet) {
  if (quiet || !isatty(STDERR_FILENO)) return {};
  return [last = std::string(), last_percent = -1](const std::string& phase, double fraction) mutable {
    const int percent = static_cast<int>(fraction * 100.0);
    if (phase == last && percent == last_percent) return;
    last = phase;
    last_percent = percent;
    std::fprintf(stderr, "\r%-20s %3d %%%s", phase.c_str(), percent, percent >= 100 ? "\n" : "");
    std::fflush(stderr);
  };
}

json options_json(const bem::ProblemDefinition& problem) {
  return {{"analysis", to_string(problem.analysis)},
          {"interpolation", to_string(problem.mesh.interpolation)},
          {"corner_shift", problem.mesh.corner_shift},
          {"split_angle_radians", problem.mesh.split_angle_radians},
          {"material", {{"E", problem.body.material.young_modulus}, {"nu", problem.body.material.poisson_ratio}}},
          {"threads", omp_get_max_threads()}};
}

json mesh_json(const geometry::BoundaryMesh& mesh) {
  int split = 0;
  for (const auto& v : mesh.vertices) split += v.split;
  return {{"nodes", mesh.node_count()}, {"elements", mesh.element_count()},
          {"contours", mesh.contours.size()}, {"split_corners", split}};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void print_written(const std::string& output_dir, const io::OutputDirectory& out) {
  std::printf("  wrote %s/{", output_dir.c_str());
  bool first = true;
  for (const auto& name : out.names()) {
    std::printf("%s%s", first ? "" : ",", name.c_str());
    first = false;
  }
  std::printf("}\n");
}

// Several subdomains glued along interfaces (chapter IV).
int command_run_decomposition(const std::string& input, const std::string& output_dir, bool quiet,
                              const io::ParameterOverrides& overrides) {
  const auto started = std::chrono::steady_clock::now();
  const auto file = io::read_decomposition_file(input, overrides);
  const auto result = dd::solve_decomposition(file.problem, make_progress(quiet));
  json summary = {{"bemcontact_version", BEMCONTACT_VERSION},
                  {"input", input},
                  {"title", file.problem.title},
                  {"parameters", file.parameters},
                  {"decomposition", io::decomposition_summary_json(file.problem, result)}};
  io::OutputDirectory out;
  if (result.converged()) {
    for (const auto& [name, content] : io::decomposition_files(result, file.problem.title, file.output.vtk))
      out.add(name, content);
  } else {
    // No answer from an unconverged iteration: only the diagnostics.
    out.add("gmres.csv", io::gmres_history_csv(result.gmres));
  }
  summary["timings_seconds"] = {{"total", seconds_since(started)}};
  summary["outputs"] = out.names();
  out.add("summary.json", io::write_json_string(summary));
  out.commit(output_dir);
  if (!result.converged()) {
    std::fprintf(stderr, "bemcontact: solver error: the interface problem did not converge: %s\n",
                 result.gmres.message.c_str());
    return solver_failed;
  }
  if (!quiet) {
    std::printf("%s\n  %zu subdomains, method %s, %ld interface unknowns\n", file.problem.title.c_str(),
                result.subdomains.size(), dd::to_string(result.method), static_cast<long>(result.interface_unknowns));
    std::printf("  GMRES(%d): %d iterations, relative residual %.3g\n", file.problem.options.restart,
                result.gmres.iterations, result.gmres.relative_residual);
    double jump_u = 0.0, jump_p = 0.0;
    for (const auto& j : result.jumps) jump_u = std::max(jump_u, j.jump_u), jump_p = std::max(jump_p, j.jump_p);
    std::printf("  max interface jumps: [u] = %.3g, [p] = %.3g\n", jump_u, jump_p);
    std::printf("  time %.3f s\n", seconds_since(started));
    print_written(output_dir, out);
  }
  return ok;
}

// Two elastic bodies in contact (chapter V).
int command_run_contact(const std::string& input, const std::string& output_dir, bool quiet,
                        const io::ParameterOverrides& overrides) {
  const auto started = std::chrono::steady_clock::now();
  const auto file = io::read_contact_file(input, overrides);
  const auto result = contact::solve_contact(file.problem, make_progress(quiet));
  io::OutputDirectory out;
  for (const auto& [name, content] : io::contact_output_files(file.problem, result, file.vtk, file.parameters)) out.add(name, content);
  out.commit(output_dir);
  if (!quiet) {
    std::printf("%s", io::contact_report_text(file.problem, result).c_str());
    std::printf("  time %.3f s\n", seconds_since(started));
    print_written(output_dir, out);
  }
  return ok;
}

int command_run(const std::string& input, const std::string& output_dir, bool quiet,
                const io::ParameterOverrides& overrides) {
  if (io::is_decomposition_file(input)) return command_run_decomposition(input, output_dir, quiet, overrides);
  if (io::is_contact_file(input)) return command_run_contact(input, output_dir, quiet, overrides);
  const auto started = std::chrono::steady_clock::now();
  const auto file = io::read_problem_file(input, overrides);
  const auto read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  auto result = bem::solve_body(file.problem, make_progress(quiet));

  const auto write_started = std::chrono::steady_clock::now();
  io::OutputDirectory out;
  out.add("boundary.csv", io::boundary_csv(result.mesh, result.boundary));
  if (!result.interior.points.empty()) out.add("interior.csv", io::interior_csv(result.interior));
  if (file.output.vtk) {
    out.add("boundary.vtk", io::boundary_vtk(result.mesh, result.boundary, file.problem.title));
    if (!result.interior.points.empty())
      out.add("interior.vtk", io::interior_vtk(result.interior, file.problem.title));
  }
  // Summary last, with the write time of the other files.
  double max_vm = 0.0, max_u = 0.0;
  Index max_vm_node = 0;
  for (Index i = 0; i < result.mesh.node_count(); ++i) {
    const double vm = result.boundary.stress[i].von_mises();
    if (vm > max_vm) max_vm = vm, max_vm_node = i;
    max_u = std::max(max_u, result.boundary.displacement[i].norm());
  }
  double interior_max_vm = 0.0;
  for (const auto& s : result.interior.stress) interior_max_vm = std::max(interior_max_vm, s.von_mises());
  json timings = {{"read", read_seconds}};
  for (const auto& [phase, seconds] : result.timings.phases) timings[phase] = seconds;
  timings["write"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - write_started).count();
  timings["total"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const auto& peak = result.mesh.nodes[max_vm_node].position;
  json summary = {
      {"bemcontact_version", BEMCONTACT_VERSION},
      {"input", input},
      {"title", file.problem.title},
      {"parameters", file.parameters},
      {"options", options_json(file.problem)},
      {"problem", io::problem_echo_json(file)},
      {"mesh", mesh_json(result.mesh)},
      {"solve", {{"unknowns", result.report.unknowns},
                 {"reciprocal_condition_estimate", result.report.reciprocal_condition},
                 {"relative_residual", result.report.relative_residual},
                 {"constraints_fix_rigid_modes_only", result.report.constraints_fix_rigid_modes_only}}},
      {"results", {{"max_boundary_displacement", max_u},
                   {"max_boundary_von_mises", max_vm},
                   {"max_boundary_von_mises_at", {peak.x(), peak.y()}},
                   {"interior_points", result.interior.points.size()},
                   {"interior_points_dropped_outside", result.interior.dropped_points.size()},
                   {"max_interior_von_mises", interior_max_vm}}},
      {"timings_seconds", timings},
      {"outputs", out.names()}};
  out.add("summary.json", io::write_json_string(summary));
  out.commit(output_dir);

  if (!quiet) {
    std::printf("%s\n", file.problem.title.c_str());
    std::printf("  %s, %s elements: %ld nodes, %ld elements, %ld unknowns\n", to_string(file.problem.analysis),
                to_string(file.problem.mesh.interpolation), static_cast<long>(result.mesh.node_count()),
                static_cast<long>(result.mesh.element_count()), static_cast<long>(result.report.unknowns));
    std::printf("  condition estimate 1/rcond = %.3g, relative residual = %.3g\n",
                1.0 / result.report.reciprocal_condition, result.report.relative_residual);
    std::printf("  max |u| on the boundary = %.6g, max von Mises = %.6g at (%.6g, %.6g)\n", max_u, max_vm,
                peak.x(), peak.y());
    if (!result.interior.points.empty())
      std::printf("  %zu interior points (%zu outside dropped), max von Mises = %.6g\n",
                  result.interior.points.size(), result.interior.dropped_points.size(), interior_max_vm);
    std::printf("  time %.3f s (", timings["total"].get<double>());
    bool first = true;
    for (const auto& [phase, seconds] : result.timings.phases) {
      std::printf("%s%s %.3f", first ? "" : ", ", phase.c_str(), seconds);
      first = false;
    }
    std::printf(")\n  wrote %s/{", output_dir.c_str());
    first = true;
    for (const auto& name : out.names()) {
      std::printf("%s%s", first ? "" : ",", name.c_str());
      first = false;
    }
    std::printf("}\n");
  }
  return ok;
}

int command_mesh(const std::string& input, const std::string& output_dir, bool quiet,
                 const io::ParameterOverrides& overrides) {
  const auto file = io::read_problem_file(input, overrides);
  const auto mesh = bem::mesh_body(file.problem);
  io::OutputDirectory out;
  out.add("mesh_nodes.csv", io::mesh_nodes_csv(mesh));
  out.add("mesh_elements.csv", io::mesh_elements_csv(mesh));
  out.add("mesh.vtk", io::mesh_vtk(mesh, file.problem.title));
  out.commit(output_dir);
  if (!quiet)
    std::printf("%s: %ld nodes, %ld elements; wrote %s/{mesh_nodes.csv,mesh_elements.csv,mesh.vtk}\n",
                file.problem.title.c_str(), static_cast<long>(mesh.node_count()),
                static_cast<long>(mesh.element_count()), output_dir.c_str());
  return ok;
}

std::string params_text(const validation::Record& r) {
  std::string text;
  for (const auto& [key, value] : r.params) text += (text.empty() ? "" : " ") + key + "=" + value;
  return text;
}

int command_validate(std::vector<std::string> names, const std::vector<std::string>& skip, const std::string& json_path,
                     const std::string& examples, bool quiet, bool list) {
  const auto& all = validation::cases();
  if (list) {
    for (const auto& c : all) std::printf("%-26s %-8s %s\n", c.name.c_str(), c.section.c_str(), c.description.c_str());
    return ok;
  }
  if (names.empty())
    for (const auto& c : all)
      if (std::find(skip.begin(), skip.end(), c.name) == skip.end()) names.push_back(c.name);
  std::vector<const validation::Case*> selected;
  for (const auto& name : names) {
    const validation::Case* found = nullptr;
    for (const auto& c : all)
      if (c.name == name) found = &c;
    if (!found) {
      std::string valid;
      for (const auto& c : all) valid += (valid.empty() ? "" : ", ") + c.name;
      std::fprintf(stderr, "bemcontact validate: unknown case '%s'; valid cases: %s\n", name.c_str(), valid.c_str());
      return bad_input;
    }
    selected.push_back(found);
  }
  validation::Context context{examples, make_progress(quiet)};
  json records = json::array();
  int failed = 0, total = 0;
  std::printf("%-24s %-34s %-22s %14s %14s %10s %10s  %s\n", "case", "params", "quantity", "computed", "reference",
              "error", "tolerance", "pass");
  for (const auto* c : selected) {
    std::vector<validation::Record> results;
    try {
      results = c->run(context);
    } catch (const std::exception& e) {
      std::printf("%-24s failed to run: %s\n", c->name.c_str(), e.what());
      ++failed;
      ++total;
      records.push_back({{"case", c->name}, {"params", json::object()}, {"quantity", "run"},
                         {"computed", nullptr}, {"reference", nullptr}, {"tolerance", nullptr},
                         {"passed", false}, {"message", e.what()}});
      continue;
    }
    for (const auto& r : results) {
      const bool counted = r.comparison != validation::Comparison::report;
      total += counted;
      failed += counted && !r.passed;
      std::printf("%-24s %-34s %-22s %14.6g %14.6g %10.3g %10.3g  %s\n", r.case_name.c_str(), params_text(r).c_str(),
                  r.quantity.c_str(), r.computed, r.reference, r.error, r.tolerance,
                  !counted ? "info" : r.passed ? "yes" : "NO");
      json params = json::object();
      for (const auto& [key, value] : r.params) params[key] = value;
      const char* comparison = r.comparison == validation::Comparison::relative ? "relative"
                               : r.comparison == validation::Comparison::scaled ? "scaled"
                               : r.comparison == validation::Comparison::at_least ? "at_least"
                                                                                  : "report";
      records.push_back({{"case", r.case_name}, {"params", params}, {"quantity", r.quantity},
                         {"computed", r.computed}, {"reference", r.reference}, {"error", r.error},
                         {"comparison", comparison}, {"tolerance", counted ? json(r.tolerance) : json(nullptr)},
                         {"passed", counted ? json(r.passed) : json(nullptr)}});
    }
  }
  std::printf("validate: %d passed, %d failed\n", total - failed, failed);
  if (!json_path.empty()) {
    io::OutputDirectory out;
    const std::filesystem::path path(json_path);
    out.add(path.filename().string(), records.dump(2) + "\n");
    out.commit(path.has_parent_path() ? path.parent_path().string() : ".");
  }
  return failed == 0 ? ok : validation_failed;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bemcontact: boundary elements for 2D and axisymmetric elasticity and frictional contact"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("bemcontact ") + BEMCONTACT_VERSION);
  int threads = 0;
  app.add_option("--threads", threads, "number of threads (default: OMP_NUM_THREADS or all cores)")
      ->check(CLI::PositiveNumber);

  std::string input, output_dir = "out";
  bool quiet = false;
  auto* run = app.add_subcommand("run", "solve a problem file and write boundary.csv, interior.csv, VTK, summary.json");
  run->add_option("FILE", input, "problem file (TOML)")->required();
  run->add_option("-o,--output", output_dir, "output directory (default: out)");
  run->add_flag("-q,--quiet", quiet, "no progress and no summary on the terminal");
  std::vector<std::string> assignments;
  run->add_option("--set", assignments, "NAME=VALUE: replace a [parameters] value of the file (repeatable)");

  auto* mesh = app.add_subcommand("mesh", "write the boundary mesh only (nodes, elements, normals)");
  mesh->add_option("FILE", input, "problem file (TOML)")->required();
  mesh->add_option("-o,--output", output_dir, "output directory (default: out)");
  mesh->add_flag("-q,--quiet", quiet, "print nothing");
  mesh->add_option("--set", assignments, "NAME=VALUE: replace a [parameters] value of the file (repeatable)");

  std::vector<std::string> cases, skip;
  std::string json_path, examples = BEMCONTACT_EXAMPLES_DIR;
  bool list = false;
  auto* validate = app.add_subcommand("validate", "run the built-in reference cases against closed-form solutions");
  validate->add_option("CASE", cases, "cases to run (default: all; --list shows them)");
  validate->add_option("--json", json_path, "write the records as JSON to this file");
  validate->add_option("--examples", examples, "folder of the bundled example problems");
  validate->add_flag("--list", list, "list the cases");
  validate->add_option("--skip", skip, "cases to leave out of a full run");
  validate->add_flag("-q,--quiet", quiet, "no progress");

  CLI11_PARSE(app, argc, argv);
  if (threads > 0) omp_set_num_threads(threads);
  try {
    io::ParameterOverrides overrides;
    for (const auto& assignment : assignments) io::add_parameter_override(overrides, assignment);
    if (*run) return command_run(input, output_dir, quiet, overrides);
    if (*mesh) return command_mesh(input, output_dir, quiet, overrides);
    if (*validate) return command_validate(cases, skip, json_path, examples, quiet, list);
  } catch (const InputError& e) {
    std::fprintf(stderr, "bemcontact: error: %s\n", e.what());
    return bad_input;
  } catch (const GeometryError& e) {
    std::fprintf(stderr, "bemcontact: geometry error in %s: %s\n", input.c_str(), e.what());
    return bad_input;
  } catch (const SolverError& e) {
    std::fprintf(stderr, "bemcontact: solver error: %s\n", e.what());
    return solver_failed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bemcontact: error: %s\n", e.what());
    return internal;
  }
  return ok;
}

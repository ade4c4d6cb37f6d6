#include "bemcontact/driver/probe.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/bem/elastoplastic_region.hpp"
#include "bemcontact/bem/probe.hpp"
#include "bemcontact/contact/pairing.hpp"
#include "bemcontact/contact/zone_refinement.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/dd/interface.hpp"
#include "bemcontact/driver/resource_check.hpp"
#include "bemcontact/driver/run.hpp"
#include "bemcontact/io/output/contact_writer.hpp"
#include "bemcontact/io/output/decomposition_writer.hpp"
#include "bemcontact/io/input/expression.hpp"
#include "bemcontact/io/output/json_writer.hpp"
#include "bemcontact/io/output/probe_writer.hpp"
#include "bemcontact/io/input/problem_reader.hpp"
#include "bemcontact/io/output/run_summary.hpp"
#include "bemcontact/io/file_names.hpp"
#include "bemcontact/io/input/problem_text.hpp"

namespace bemcontact::driver {

namespace {

using nlohmann::json;

// A body or region of the run: its mesh made again from the text, and its stored solution.
struct StoredRegion {
  std::string name;  // as in the run's file names and messages
  std::string csv;   // its boundary file
  geometry::BoundaryMesh mesh;
  Material material;
  std::vector<geometry::BoundaryPiece> pieces;
  bem::BoundarySolution solution;
  // An elastoplastic region: its cells made again, the file of their plastic strains, and
  // the cells' fields from them (added to Somigliana's of the boundary values inside).
  std::vector<plasticity::Cell> cells;
  std::string cells_csv;
  std::shared_ptr<const bem::PlasticCellFields> cell_fields;
};

struct StoredRun {
  std::string title;
  AnalysisType analysis = AnalysisType::plane_strain;
  std::vector<StoredRegion> regions;
};

InputError run_error(const ProbeOptions& options, const std::string& message) {
  return InputError(SourceLocation{options.run_name, 0, ""}, message);
}

// A string member of a JSON object, or "" (a damaged summary is refused, never a crash).
std::string text_at(const json& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_string()) return "";
  return object[key].get<std::string>();
}

json read_summary(const FileReader& run_files, const ProbeOptions& options) {
  const auto text = run_files("summary.json");
  if (!text)
    throw run_error(options, "not the output folder of a run: it has no summary.json (bemcontact run FILE -o DIR "
                             "writes one)");
  json summary = json::parse(*text, nullptr, false);
  if (summary.is_discarded() || !summary.is_object() || text_at(summary.value("input", json()), "sha256").empty())
    throw run_error(options, "summary.json is not a run summary of bemcontact (it does not parse, or has no "
                             "input.sha256)");
  const std::string command = text_at(summary, "command");
  if (command != "run")
    throw run_error(options, "the folder holds the output of `bemcontact " + command +
                                 "`, not of a run: probe needs a solved problem (bemcontact run FILE -o DIR)");
  return summary;
}

// The problem text the run solved: problem.toml, or the input file for older runs; either
// must still have the SHA-256 the summary recorded.
std::string read_problem_text(const FileReader& run_files, const json& summary, const ProbeOptions& options) {
  const std::string recorded = text_at(summary["input"], "sha256");
  if (const auto copy = run_files("problem.toml")) {
    if (io::sha256_hex(*copy) != recorded)
      throw run_error(options, "problem.toml was changed after the run: its SHA-256 is not summary.json's "
                               "input.sha256, so the stored solution does not belong to it; run the problem again");
    return *copy;
  }
  const std::string path = text_at(summary["input"], "path");
  const std::string file = path.empty() ? text_at(summary["input"], "file") : path;
  const auto original = options.read_input && !file.empty() ? options.read_input(file) : std::nullopt;
  if (!original)
    throw run_error(options, "the folder has no problem.toml (the run is older than `probe`) and its input file '" +
                                 file + "' cannot be read; run the problem again");
  if (io::sha256_hex(*original) != recorded)
    throw run_error(options, "the input file '" + file + "' changed since the run (its SHA-256 is not summary.json's "
                             "input.sha256) and the folder has no problem.toml (the run is older than `probe`): the "
                             "stored solution belongs to the old text; run the problem again");
  return *original;
}

// The run's evaluated parameters: replayed as overrides, they reproduce any --set.
io::ParameterOverrides recorded_parameters(const json& summary) {
  io::ParameterOverrides overrides;
  if (!summary.contains("parameters") || !summary["parameters"].is_object()) return overrides;
  for (const auto& [name, value] : summary["parameters"].items()) {
    if (!value.is_number()) continue;
    io::ParameterValue replacing(value.get<double>());
    replacing.origin = "the run's parameter " + name + " (summary.json)";
    overrides[name] = replacing;
  }
  return overrides;
}

// The run passed its limits already; meshing again allocates little.
ResourceLimits unbounded_limits() {
  ResourceLimits limits;
  limits.max_elements = std::numeric_limits<std::int64_t>::max();
  limits.max_interior_points = std::numeric_limits<std::int64_t>::max();
  return limits;
}

// The meshes the run's adaptive contact zones ended with (summary.json: results.contacts[c].zone).
void apply_adapted_zones(const json& summary, contact::ContactProblem& model) {
  const auto results = summary.find("results");
  if (results == summary.end() || !results->contains("contacts")) return;
  const json& contacts = (*results)["contacts"];
  for (std::size_t c = 0; c < contacts.size() && c < model.contacts.size(); ++c) {
    const auto zone = contacts[c].find("zone");
    if (zone == contacts[c].end()) continue;
    using Meshes = std::vector<std::vector<double>>;
    contact::set_zone_meshes(model, static_cast<int>(c), zone->value("breakpoints1", Meshes{}),
                             zone->value("breakpoints2", Meshes{}));
  }
}

// The run's regions meshed again by the solver that ran them (the model's route), with
// the files their boundary solutions were written to.
StoredRun mesh_again(std::string_view text, const std::string& file_name, const io::ParameterOverrides& overrides,
                     const json& summary) {
  auto input = io::read_problem(text, file_name, overrides, unbounded_limits());
  auto& model = input.model;
  apply_adapted_zones(summary, model);
  StoredRun run{model.title, model.analysis, {}};
  switch (contact::route_of(model)) {
    case contact::SolverRoute::direct: {
      const auto problem = contact::single_region_problem(model);
      const auto& body = problem.body;
      const auto& named = model.bodies[0];
      const std::string csv = io::body_file_prefix(named.name, named.named) + "boundary.csv";
      run.regions.push_back({body.name, csv, bem::mesh_body(problem), body.material, body.pieces, {}, {}, {}, {}});
      break;
    }
    case contact::SolverRoute::decomposition: {
      const auto problem = contact::decomposition_problem(model, input.decomposition, input.region_word);
      auto meshes = dd::mesh_subdomains(problem);
      for (std::size_t s = 0; s < meshes.size(); ++s) {
        const auto& body = problem.subdomains[s].body;
        run.regions.push_back({body.name, io::file_stem(body.name) + "_boundary.csv", std::move(meshes[s]),
                               body.material, body.pieces, {}, {}, {}, {}});
      }
      break;
    }
    case contact::SolverRoute::condensed: {
      auto prepared = contact::prepare_contact(model);
      for (auto& region : prepared.regions) {
        const auto& body = model.bodies[region.body];
        const std::string name = body.regions.size() == 1 ? body.name : region.definition.name;
        StoredRegion stored{name, io::file_stem(name) + "_boundary.csv", std::move(region.mesh),
                            region.definition.material, region.definition.pieces, {}, {}, {}, {}};
        if (region.definition.plasticity) {
          stored.cells = bem::region_cells_of(stored.mesh, region.definition, model.analysis, 0.0);
          stored.cells_csv = io::file_stem(name) + "_cells.csv";
        }
        run.regions.push_back(std::move(stored));
      }
      break;
    }
    case contact::SolverRoute::elastoplastic: {
      const auto history = contact::elastoplastic_history(model);
      const auto& body = history.problem.body;
      const auto& named = model.bodies[0];
      const std::string prefix = io::body_file_prefix(named.name, named.named);
      StoredRegion stored{body.name, prefix + "boundary.csv", bem::mesh_elastoplastic_body(history.problem),
                          body.material, body.pieces, {}, {}, {}, {}};
      stored.cells = bem::region_cells_of(stored.mesh, body, model.analysis, 0.0);
      stored.cells_csv = prefix + "cells.csv";
      run.regions.push_back(std::move(stored));
      break;
    }
  }
  return run;
}

// The mesh made again must be the run's, node for node.
void check_same_nodes(const StoredRegion& region, const std::vector<Vec2>& stored, const ProbeOptions& options) {
  const auto mismatch = [&](const std::string& what) {
    return run_error(options, "the mesh of '" + region.name + "' made from the problem text does not match " +
                                  region.csv + " (" + what + "): the run was made by another version of bemcontact, "
                                  "or a geometry file it read changed since; run the problem again");
  };
  if (static_cast<Index>(stored.size()) != region.mesh.node_count())
    throw mismatch(std::to_string(stored.size()) + " nodes stored, " + std::to_string(region.mesh.node_count()) +
                   " now");
  const double tolerance = 1e-9 * region.mesh.scale;
  for (Index i = 0; i < region.mesh.node_count(); ++i)
    if ((region.mesh.nodes[i].position - stored[i]).norm() > tolerance)
      throw mismatch("node " + std::to_string(i) + " at " + point_text(stored[i]) + " stored, " +
                     point_text(region.mesh.nodes[i].position) + " now");
}

// The plastic strains of an elastoplastic region's cells, on the cells made again (the same,
// centroid for centroid), and their fields.
void load_cells(const FileReader& run_files, AnalysisType analysis, StoredRegion& region, const ProbeOptions& options) {
  const auto csv = run_files(region.cells_csv);
  if (!csv)
    throw run_error(options, "the run has no " + region.cells_csv + " (the plastic strains of '" + region.name +
                                 "'): it did not finish, or the file was removed");
  auto stored = io::parse_cells_csv(*csv, options.run_name + "/" + region.cells_csv);
  const auto mismatch = [&](const std::string& what) {
    return run_error(options, "the cells of '" + region.name + "' made from the problem text do not match " +
                                  region.cells_csv + " (" + what + "): the run was made by another version of "
                                  "bemcontact; run the problem again");
  };
  if (stored.centroids.size() != region.cells.size())
    throw mismatch(std::to_string(stored.centroids.size()) + " cells stored, " + std::to_string(region.cells.size()) +
                   " now");
  const double tolerance = 1e-9 * region.mesh.scale;
  for (std::size_t k = 0; k < region.cells.size(); ++k)
    if ((region.cells[k].centroid() - stored.centroids[k]).norm() > tolerance)
      throw mismatch("cell " + std::to_string(k) + " at " + point_text(stored.centroids[k]) + " stored, " +
                     point_text(region.cells[k].centroid()) + " now");
  region.cell_fields = std::make_shared<const bem::PlasticCellFields>(analysis, region.material, region.mesh,
                                                                      region.cells, stored.plastic_strains);
}

StoredRun load_run(const FileReader& run_files, const json& summary, const ProbeOptions& options) {
  const std::string text = read_problem_text(run_files, summary, options);
  const std::string path = text_at(summary["input"], "path");
  // The recorded path: messages name the file, and relative geometry files resolve from it.
  const std::string file_name = path.empty() ? text_at(summary["input"], "file") : path;
  const auto overrides = recorded_parameters(summary);
  StoredRun run = mesh_again(text, file_name, overrides, summary);
  for (auto& region : run.regions) {
    const auto csv = run_files(region.csv);
    if (!csv)
      throw run_error(options, "the run has no " + region.csv + " (the boundary solution of '" + region.name +
                                   "'): it did not finish, or the file was removed");
    auto stored = io::parse_boundary_csv(*csv, options.run_name + "/" + region.csv);
    check_same_nodes(region, stored.positions, options);
    region.solution = std::move(stored.solution);
    if (!region.cells_csv.empty()) load_cells(run_files, run.analysis, region, options);
  }
  return run;
}

// The points asked for, in order: the points file's, then each line's.
struct AskedPoints {
  std::vector<Vec2> positions;
  std::vector<int> line;         // 0: listed; k: the k-th --line
  std::vector<double> distance;  // along its line
};

AskedPoints asked_points(const ProbeRequest& request) {
  AskedPoints asked;
  for (const auto& p : request.listed) {
    asked.positions.push_back(p.position);
    asked.line.push_back(0);
    asked.distance.push_back(0.0);
  }
  for (std::size_t k = 0; k < request.lines.size(); ++k)
    for (const Vec2& p : io::line_points(request.lines[k])) {
      asked.positions.push_back(p);
      asked.line.push_back(static_cast<int>(k) + 1);
      asked.distance.push_back((p - request.lines[k].start).norm());
    }
  return asked;
}

// Counted before the lines are made into points: a line of 10^9 points is refused, not made.
void check_point_count(const ProbeRequest& request, const ProbeOptions& options) {
  double count = static_cast<double>(request.listed.size());
  for (const auto& line : request.lines) count += static_cast<double>(line.count);
  if (count == 0)
    throw InputError(SourceLocation{options.request_source, 0, ""}, "give points: " + options.points_hint);
  if (count > static_cast<double>(options.limits.max_interior_points))
    throw InputError(SourceLocation{options.request_source, 0, ""},
                     std::to_string(static_cast<long long>(count)) + " points, over the limit of " +
                         std::to_string(options.limits.max_interior_points) + " (" + options.limit_hint + ")");
}

// A listed point that no body holds is a mistake in the points file.
void check_listed_points_held(const bem::ProbeResult& result, const AskedPoints& asked, const ProbeRequest& request) {
  for (const Index k : result.outside) {
    if (asked.line[k] != 0) continue;
    const auto& p = request.listed[k];
    std::size_t listed_outside = 0;
    for (const Index j : result.outside) listed_outside += asked.line[j] == 0;
    throw InputError(SourceLocation{request.points_file, p.line, ""},
                     "point " + point_text(p.position) + " lies inside no body" +
                         (listed_outside > 1
                              ? " (and " + std::to_string(listed_outside - 1) + " more points of the file)"
                              : std::string()));
  }
}

std::size_t request_count(const AskedPoints& asked, int line) {
  return static_cast<std::size_t>(std::count(asked.line.begin(), asked.line.end(), line));
}

// One warning per line with points outside every body, naming the first few.
std::vector<std::string> outside_warnings(const bem::ProbeResult& result, const AskedPoints& asked,
                                          std::size_t lines) {
  std::vector<std::string> warnings;
  for (std::size_t k = 1; k <= lines; ++k) {
    std::vector<Index> out;
    for (const Index j : result.outside)
      if (asked.line[j] == static_cast<int>(k)) out.push_back(j);
    if (out.empty()) continue;
    const std::size_t count = request_count(asked, static_cast<int>(k));
    std::string text = "line " + std::to_string(k) + ": " + std::to_string(out.size()) + " of its " +
                       std::to_string(count) + (out.size() == 1 ? " points is" : " points are") +
                       " inside no body and left out:";
    for (std::size_t i = 0; i < out.size() && i < 5; ++i)
      text += (i ? ", " : " ") + point_text(asked.positions[out[i]]);
    if (out.size() > 5) text += ", ...";
    warnings.push_back(text);
  }
  return warnings;
}

// The rows of a line's point on an interface in the order the line crosses it: the body of
// the line's previous point first, that of its next point last (polylines and the
// linearisation follow the rows).
void order_along_line(std::vector<io::ProbeRow>& rows) {
  for (std::size_t first = 0; first < rows.size();) {
    std::size_t last = first;
    while (last + 1 < rows.size() && rows[last + 1].point == rows[first].point) ++last;
    const int line = rows[first].line;
    if (line > 0 && last > first) {
      const bool has_previous = first > 0 && rows[first - 1].line == line;
      const bool has_next = last + 1 < rows.size() && rows[last + 1].line == line;
      const auto rank = [&](const io::ProbeRow& row) {
        if (has_previous && row.body == rows[first - 1].body) return 0;
        if (has_next && row.body == rows[last + 1].body) return 2;
        return 1;
      };
      std::stable_sort(rows.begin() + static_cast<std::ptrdiff_t>(first),
                       rows.begin() + static_cast<std::ptrdiff_t>(last + 1),
                       [&](const io::ProbeRow& a, const io::ProbeRow& b) { return rank(a) < rank(b); });
    }
    first = last + 1;
  }
}

std::vector<io::ProbeRow> probe_rows(const bem::ProbeResult& result, const AskedPoints& asked) {
  std::vector<io::ProbeRow> rows;
  for (const auto& value : result.values) {
    const Index k = value.point;
    rows.push_back({k, asked.line[k], asked.distance[k], asked.positions[k], value.region, value});
  }
  order_along_line(rows);
  return rows;
}

json point_json(const Vec2& p) { return json::array({p.x(), p.y()}); }

// The line's membrane and bending stresses in its own frame (along it, across it, their
// shear, s33); the bending of the across and out-of-plane components only, as pressure-vessel
// codes bend (ASME VIII-2, 5-A): null when some of its points lie inside no body.
json linearised_json(const std::vector<io::ProbeRow>& rows, const io::ProbeLine& line, int number,
                     std::size_t outside) {
  if (outside > 0) return nullptr;
  const Vec2 along = (line.end - line.start).normalized();
  std::vector<double> s;
  std::vector<bem::StressTensor> stress;
  for (const auto& row : rows)
    if (row.line == number) s.push_back(row.distance), stress.push_back(bem::stress_in_frame(row.value.stress, along));
  const auto parts = bem::linearised_stress(s, stress);
  const bem::StressTensor& m = parts.membrane;
  const double across = parts.bending.s22, hoop = parts.bending.s33;
  const bem::StressTensor start{m.s11, m.s22 + across, m.s12, m.s33 + hoop};
  const bem::StressTensor end{m.s11, m.s22 - across, m.s12, m.s33 - hoop};
  return {{"membrane",
           {{"along", m.s11}, {"across", m.s22}, {"shear", m.s12}, {"s33", m.s33}, {"von_mises", m.von_mises()}}},
          {"bending", {{"across", across}, {"s33", hoop}}},
          {"membrane_plus_bending_von_mises", {{"start", start.von_mises()}, {"end", end.von_mises()}}}};
}

// Per --line: its ends, points, how many lie inside no body, and its linearised stress.
json lines_json(const ProbeRequest& request, const AskedPoints& asked, const std::vector<io::ProbeRow>& rows,
                const bem::ProbeResult& result) {
  json lines = json::array();
  for (std::size_t k = 0; k < request.lines.size(); ++k) {
    const auto& line = request.lines[k];
    std::size_t outside = 0;
    for (const Index j : result.outside) outside += asked.line[j] == static_cast<int>(k) + 1;
    lines.push_back({{"start", point_json(line.start)},
                     {"end", point_json(line.end)},
                     {"points", line.count},
                     {"outside", outside},
                     {"linearised", linearised_json(rows, line, static_cast<int>(k) + 1, outside)}});
  }
  return lines;
}

json probe_json(const json& summary, const StoredRun& run, const ProbeRequest& request, const AskedPoints& asked,
                const std::vector<io::ProbeRow>& rows, const bem::ProbeResult& result, const json& lines,
                const ProbeOptions& options, const std::vector<std::string>& warnings, double seconds) {
  json outside = json::array();
  for (const Index k : result.outside)
    outside.push_back({{"point", k}, {"line", asked.line[k]}, {"position", point_json(asked.positions[k])}});
  json bodies = json::array();
  for (const auto& region : run.regions) bodies.push_back(region.name);
  const auto peak = std::max_element(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
    return a.value.stress.von_mises() < b.value.stress.von_mises();
  });
  std::size_t on_boundary = 0;
  for (const auto& row : rows) on_boundary += row.value.on_boundary;
  return {{"schema", "bemcontact.probe/1"},
          {"bemcontact_version", BEMCONTACT_VERSION},
          {"run", options.run_name},
          {"title", run.title},
          {"analysis", to_string(run.analysis)},
          {"kind", text_at(summary, "kind")},
          {"input", summary["input"]},
          {"bodies", bodies},
          {"points_file", request.points_file},
          {"listed_points", request.listed.size()},
          {"lines", lines},
          {"rows", rows.size()},
          {"rows_on_boundary", on_boundary},
          {"outside", outside},
          {"max_von_mises", {{"value", peak->value.stress.von_mises()},
                             {"at", point_json(peak->position)},
                             {"body", run.regions[peak->body].name}}},
          {"timings_seconds", {{"total", seconds}}},
          {"warnings", warnings},
          {"outputs", {"probe.csv", "probe.vtk"}}};
}

std::string report_text(const StoredRun& run, const AskedPoints& asked, const std::vector<io::ProbeRow>& rows,
                        const bem::ProbeResult& result, const json& lines, const ProbeOptions& options) {
  char line[512];
  std::string report = "probe of " + options.run_name + ": " + run.title + "\n";
  std::size_t on_boundary = 0;
  for (const auto& row : rows) on_boundary += row.value.on_boundary;
  std::snprintf(line, sizeof line, "  %zu points: %zu rows (%zu on a boundary), %zu inside no body left out\n",
                asked.positions.size(), rows.size(), on_boundary, result.outside.size());
  report += line;
  const auto peak = std::max_element(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
    return a.value.stress.von_mises() < b.value.stress.von_mises();
  });
  std::snprintf(line, sizeof line, "  max von Mises = %.6g at (%.6g, %.6g) in '%s'\n", peak->value.stress.von_mises(),
                peak->position.x(), peak->position.y(), run.regions[peak->body].name.c_str());
  report += line;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const json& linearised = lines[k]["linearised"];
    if (linearised.is_null()) continue;
    const json& both = linearised["membrane_plus_bending_von_mises"];
    std::snprintf(line, sizeof line,
                  "  line %zu linearised: von Mises of the membrane stress %.6g, of membrane + bending %.6g at its "
                  "start, %.6g at its end\n",
                  k + 1, linearised["membrane"]["von_mises"].get<double>(), both["start"].get<double>(),
                  both["end"].get<double>());
    report += line;
  }
  return report;
}

}  // namespace

ProbeOutput probe_run(const FileReader& run_files, const ProbeRequest& request, const ProbeOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  check_point_count(request, options);
  const AskedPoints asked = asked_points(request);
  const json summary = read_summary(run_files, options);
  const StoredRun run = load_run(run_files, summary, options);

  std::vector<bem::ProbeRegion> regions;
  for (const auto& region : run.regions) {
    bem::DomainTerm cells;
    if (region.cell_fields)
      cells = [fields = region.cell_fields](const Vec2& x, Vec2& u, bem::StressTensor& stress) {
        fields->add_at(x, u, stress);
      };
    regions.push_back({&region.mesh, &region.solution, run.analysis, region.material,
                       bem::chord_bulges(region.mesh, region.pieces), cells});
  }
  const auto result = bem::probe_points(regions, asked.positions, options.progress);
  check_listed_points_held(result, asked, request);
  if (result.values.empty())
    throw InputError(SourceLocation{options.request_source, 0, ""},
                     "none of the " + std::to_string(asked.positions.size()) + " points lies inside a body of " +
                         options.run_name + " (" + run.title + ")");

  ProbeOutput output;
  output.warnings = outside_warnings(result, asked, request.lines.size());
  const auto rows = probe_rows(result, asked);
  std::vector<std::string> names;
  for (const auto& region : run.regions) names.push_back(region.name);
  auto table = io::probe_table(rows, names);
  output.files.add("probe.csv", io::csv_text(table));
  if (options.keep_tables) output.tables.emplace("probe.csv", std::move(table));
  output.files.add("probe.vtk", io::probe_vtk(rows, names, run.title + " (probe)"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const json lines = lines_json(request, asked, rows, result);
  output.files.add("probe.json", io::write_json_string(probe_json(summary, run, request, asked, rows, result, lines,
                                                                  options, output.warnings, seconds)));
  check_output_finite(output.files);
  output.report = report_text(run, asked, rows, result, lines, options);
  return output;
}

}  // namespace bemcontact::driver

#include "bemcontact/io/input/decomposition_file.hpp"
#include "io/input/region_parser.hpp"


#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "io/input/body_parser.hpp"
#include "bemcontact/io/input/problem_schema.hpp"
#include "bemcontact/io/input/suggestions.hpp"
#include "io/input/readers.hpp"
#include "io/input/toml_reader.hpp"
#include "bemcontact/io/text_format.hpp"
#include "bemcontact/io/file_names.hpp"
#include "bemcontact/io/input/problem_text.hpp"

namespace bemcontact::io {

namespace {

// [parameters]: numbers or expressions of the parameters above (as in one-body files).

void read_options(const TableReader& root, const FileContext& context, dd::DecompositionOptions& options) {
  const toml::table* table = root.optional_table("decomposition", "[decomposition]");
  if (!table) return;
  const TableReader reader(*table, "decomposition", context, root.line());
  reader.check_keys(schema::table("decomposition"));
  const std::string method = reader.choice("method");
  options.set_method(method == "conforming" ? dd::InterfaceMethod::conforming
                     : method == "hybrid"   ? dd::InterfaceMethod::hybrid
                                            : dd::InterfaceMethod::mixed);
  if (reader.has("preconditioner")) {
    const bool balancing = reader.choice("preconditioner", {"balancing", "none"}, "balancing") == "balancing";
    if (balancing && options.method != dd::InterfaceMethod::conforming)
      reader.fail("preconditioner", "the balancing preconditioner is for method = \"conforming\" (its unknowns are "
                                    "the interface displacements); use preconditioner = \"none\" with method = \"" +
                                        method + "\"");
    options.preconditioner = balancing ? dd::InterfacePreconditioner::balancing : dd::InterfacePreconditioner::none;
  }
  options.restart = reader.integer_or("restart", options.restart);
  options.max_iterations = reader.integer_or("max_iterations", options.max_iterations);
  options.tolerance = reader.optional_number("tolerance").value_or(options.tolerance);
  options.interface_tolerance = reader.optional_number("interface_tolerance").value_or(options.interface_tolerance);
  options.displacement_nodes = reader.integer_or("displacement_nodes", options.displacement_nodes);
  options.explicit_operators = reader.boolean_or("explicit_operators", options.explicit_operators);
  if (reader.has("explicit_operators") && !options.explicit_operators &&
      options.preconditioner == dd::InterfacePreconditioner::balancing)
    reader.fail("explicit_operators", "the balancing preconditioner needs every subdomain's interface map, so it "
                                      "forms them: explicit_operators = false applies with preconditioner = \"none\"");
  if (reader.has("displacement_nodes") && options.method != dd::InterfaceMethod::mixed)
    reader.fail("displacement_nodes", "displacement_nodes applies to method = \"mixed\" only");
}

std::vector<bem::InteriorPoint> read_points(const TableReader& sub, const FileContext& context) {
  std::vector<bem::InteriorPoint> points;
  const toml::table* table = sub.optional_table("interior", "[" + sub.key_path("interior") + "]");
  if (!table) return points;
  const TableReader interior(*table, sub.key_path("interior"), context, sub.line());
  interior.check_keys(schema::table("interior"));
  if (const toml::node* node = interior.find("points")) {
    const toml::array* list = node->as_array();
    if (!list) interior.fail("points", "must be a list of points [" + context.point_form() + ", ...], found " +
                                           describe_node(*node));
    for (const toml::node& point : *list) {
      SourceLocation where = interior.where("points");
      if (line_of(point) > 0) where.line = line_of(point);
      points.push_back(bem::InteriorPoint{read_point(point, where, context), false, where});
    }
  }
  if (const toml::table* grid = interior.optional_table("grid", "grid")) {
    const auto grid_points = read_interior_grid(TableReader(*grid, interior.key_path("grid"), context, interior.line()), context);
    points.insert(points.end(), grid_points.begin(), grid_points.end());
  }
  return points;
}

}  // namespace

dd::Subdomain parse_region(toml::table& table, const std::string& path, FileContext& context, int line,
                           const std::string& name, const schema::Table& table_keys,
                           const schema::Table& boundary_table, const toml::table* shared_vertices) {
  const TableReader sub(table, path, context, line);
  if (name.empty()) sub.fail("name", "the name must not be empty");
  dd::Subdomain subdomain;
  // interface = "<name>" is read here and removed, so parse_body sees a plain boundary.
  std::vector<std::string> interfaces;
  if (toml::array* boundaries = table.get("boundary") ? table.get("boundary")->as_array() : nullptr;
      boundaries && boundaries->is_array_of_tables()) {
    int b = 0;
    for (toml::node& boundary_node : *boundaries) {
      ++b;
      toml::table& boundary = *boundary_node.as_table();
      const TableReader reader(boundary, path + ".boundary[" + std::to_string(b) + "]", context, sub.line());
      reader.check_keys(boundary_table);
      std::string interface;
      if (reader.has("interface")) {
        const auto value = reader.optional_string("interface");
        if (!value || value->empty()) reader.fail("interface", "the interface name must be a non-empty string");
        interface = *value;
        for (const char* key : {"u1", "u2", "t1", "t2", "un", "ut", "tn", "tt", "pressure"})
          if (reader.has(key))
            reader.fail(key, "boundary on interface '" + interface + "' takes no condition ('" + key +
                                 "'): continuity with the region on the other side is its condition");
        boundary.erase("interface");
      }
      interfaces.push_back(interface);
    }
  }
  if (shared_vertices) {
    if (!table.contains("vertices")) table.insert("vertices", toml::table{});
    if (toml::table* own = table.get("vertices")->as_table())
      for (const auto& [key, value] : *shared_vertices)
        if (!own->contains(key.str())) own->insert(key, value);
  }
  subdomain.body = parse_body(table, BodyContext{&context, path, &table_keys, sub.line()});
  subdomain.body.name = name;
  subdomain.piece_interface.assign(subdomain.body.pieces.size(), "");
  for (std::size_t p = 0; p < interfaces.size() && p < subdomain.body.pieces.size(); ++p)
    if (!interfaces[p].empty()) dd::mark_interface(subdomain, p, interfaces[p]);
  subdomain.interior_points = read_points(sub, context);
  return subdomain;
}

DecompositionFile read_decomposition_file(const std::filesystem::path& path, const ParameterOverrides& overrides) {
  return parse_decomposition(read_problem_text(path), path.string(), overrides);
}

DecompositionFile parse_decomposition(std::string_view text, const std::string& file_name,
                                      const ParameterOverrides& overrides, const ResourceLimits& limits) {
  toml::table root_table = parse_toml_text(text, file_name);
  return parse_decomposition_table(root_table, file_name, overrides, limits);
}

DecompositionFile parse_decomposition_table(toml::table& root_table, const std::string& file_name,
                                            const ParameterOverrides& overrides, const ResourceLimits& limits) {
  DecompositionFile result;
  FileContext context = FileContext::starting(file_name, overrides, limits);
  const TableReader root(root_table, "", context, 1);
  // Body keys at the top level are a one-body habit: say where they go.
  for (const std::string key : {"material", "boundary", "constraint", "interior"})
    if (root.has(key))
      root.fail(key, "'" + key + "' belongs in each [[subdomain]] table in a file with subdomains (write [subdomain." +
                         key + "] or [[subdomain." + key + "]] after the subdomain's [[subdomain]] line)");
  root.check_keys(schema::table("decomposition.file"));

  auto& problem = result.problem;
  problem.source_file = file_name;
  read_file_header(root, context, file_name, problem.analysis, problem.title, problem.mesh.interpolation);
  result.parameters = context.parameters;
  read_options(root, context, problem.options);
  if (const toml::table* table = root.optional_table("solver", "[solver]")) {
    const TableReader solver(*table, "solver", context, root.line());
    solver.check_keys(schema::table("solver"));
    problem.operator_choice = read_operator_keys(solver);
  }
  read_mesh_options(root, context, problem.mesh);
  if (const toml::table* table = root.optional_table("output", "[output]")) {
    const TableReader output(*table, "output", context, root.line());
    output.check_keys(schema::table("output"));
    result.output.vtk = output.boolean_or("vtk", true);
  }

  // Shared vertices: checked here (with their lines), then copied into every subdomain that
  // does not define a vertex of the same name.
  const toml::table* shared = root.optional_table("vertices", "[vertices]");
  if (shared)
    for (const auto& [key, node] : *shared) {
      const SourceLocation where{file_name, line_of(node), "vertices." + std::string(key.str())};
      const Vec2 point = read_point(node, where, context);
      if (context.axisymmetric() && point.x() < -1e-12 * std::max(1.0, point.norm()))
        throw InputError(where, "the point has r = " + format_number(point.x()) +
                                    " < 0; in an axisymmetric problem the body lies in r >= 0 (the axis of "
                                    "revolution is r = 0)");
    }

  toml::node* subdomain_node = root_table.get("subdomain");
  toml::array* subdomains = subdomain_node ? subdomain_node->as_array() : nullptr;
  if (!subdomains || subdomains->empty() || !subdomains->is_array_of_tables())
    root.fail("subdomain", "must be one or more [[subdomain]] tables (double brackets), found " +
                               (subdomain_node ? describe_node(*subdomain_node) : std::string("nothing")));
  if (subdomains->size() < 2)
    root.fail("subdomain", "a decomposition needs at least two [[subdomain]] tables; for one body write a "
                           "one-body file (docs/problem-file.md)");
  std::map<std::string, int> name_lines, file_lines;
  int index = 0;
  for (toml::node& node : *subdomains) {
    ++index;
    toml::table& table = *node.as_table();
    const std::string path = "subdomain[" + std::to_string(index) + "]";
    const TableReader sub(table, path, context, root.where("subdomain").line);
    sub.check_keys(schema::table("subdomain"));
    const std::string name = sub.optional_name("name").value_or("subdomain" + std::to_string(index));
    const auto [existing, inserted] = name_lines.emplace(name, sub.line());
    if (!inserted)
      sub.fail("name", "the subdomain name '" + name + "' is already used at line " + std::to_string(existing->second) +
                           "; subdomain names must be unique");
    // Its output files (<name>_boundary.csv; <name>_mesh.vtk as a region of `mesh`).
    const auto [same_file, first] = file_lines.emplace(region_file_names(name).front(), sub.line());
    if (!first)
      sub.fail("name", "subdomain '" + name + "' and the subdomain at line " + std::to_string(same_file->second) +
                           " would write files of one name (file names keep letters and digits and write every other "
                           "character as '_'): choose another name");
    dd::Subdomain subdomain = parse_region(table, path, context, sub.line(), name, schema::table("subdomain"),
                                                   schema::table("region.boundary"), shared);
    if (std::none_of(subdomain.piece_interface.begin(), subdomain.piece_interface.end(),
                     [](const std::string& s) { return !s.empty(); }))
      sub.fail("boundary", "subdomain '" + name + "' has no boundary with interface = \"...\"; every subdomain "
                           "must share at least one interface with another");
    problem.subdomains.push_back(std::move(subdomain));
  }
  check_gmsh_overrides(root, context, result.parameters);
  result.warnings = context.warnings;
  return result;
}

}  // namespace bemcontact::io

#include "bemcontact/io/input/problem_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/input/body_parser.hpp"
#include "bemcontact/io/input/problem_schema.hpp"
#include "bemcontact/io/input/suggestions.hpp"
#include "io/input/readers.hpp"
#include "io/input/toml_reader.hpp"
#include "bemcontact/io/input/problem_text.hpp"

namespace bemcontact::io {

namespace {

// Names used in `text` as identifiers (not the exponent of a number like 1e3).

// [parameters]: numbers, or expressions of the parameters written before them.

std::vector<bem::InteriorPoint> read_interior(const TableReader& root, const FileContext& context) {
  std::vector<bem::InteriorPoint> points;
  const toml::table* table = root.optional_table("interior", "[interior]");
  if (!table) return points;
  const TableReader interior(*table, "interior", context, root.line());
  interior.check_keys(schema::table("interior"));
  if (const toml::node* node = interior.find("points")) {
    const toml::array* list = node->as_array();
    if (!list)
      interior.fail("points", "must be a list of points [" + context.point_form() + ", ...], found " +
                                  describe_node(*node));
    for (const toml::node& point : *list) {
      SourceLocation where = interior.where("points");
      if (line_of(point) > 0) where.line = line_of(point);
      points.push_back(bem::InteriorPoint{read_point(point, where, context), false, where});
    }
  }
  if (const toml::node* node = interior.find("grid")) {
    if (const toml::table* grid = node->as_table()) {
      const auto grid_points = read_interior_grid(TableReader(*grid, "interior.grid", context, interior.line()), context);
      points.insert(points.end(), grid_points.begin(), grid_points.end());
    } else if (const toml::array* grids = node->as_array(); grids && grids->is_array_of_tables()) {
      int index = 0;
      for (const toml::node& grid : *grids) {
        ++index;
        const auto grid_points =
            read_interior_grid(TableReader(*grid.as_table(), "interior.grid[" + std::to_string(index) + "]",
                                  context, interior.where("grid").line),
                      context);
        points.insert(points.end(), grid_points.begin(), grid_points.end());
      }
    } else {
      interior.fail("grid", "must be a table { x = [min, max, count], y = [min, max, count] } (or a "
                            "list of such tables), found " + describe_node(*node));
    }
  }
  return points;
}

// [solver]: the operator behind the boundary element system (docs/problem-file.md).
bem::OperatorChoice read_operator_choice(const TableReader& root) {
  const toml::table* table = root.optional_table("solver", "[solver]");
  if (!table) return {};
  const TableReader solver(*table, "solver", root.context(), root.line());
  solver.check_keys(schema::table("solver"));
  return read_operator_keys(solver);
}

}  // namespace

ProblemFile parse_problem(std::string_view text, const std::string& file_name, const ParameterOverrides& overrides,
    const ResourceLimits& limits) {
  toml::table root_table = parse_toml_text(text, file_name);
  return parse_problem_table(root_table, file_name, overrides, limits);
}

ProblemFile parse_problem_table(toml::table& root_table, const std::string& file_name,
                                const ParameterOverrides& overrides, const ResourceLimits& limits) {

  ProblemFile result;
  FileContext context = FileContext::starting(file_name, overrides, limits);
  const TableReader root(root_table, "", context, 1);
  root.check_keys(schema::table("file"));

  bem::ProblemDefinition& problem = result.problem;
  problem.source_file = file_name;
  read_file_header(root, context, file_name, problem.analysis, problem.title, problem.mesh.interpolation);
  result.parameters = context.parameters;

  problem.body = parse_body(root_table, BodyContext{&context, "", &schema::table("file"), 1});
  problem.interior_points = read_interior(root, context);
  check_gmsh_overrides(root, context, result.parameters);

  read_mesh_options(root, context, problem.mesh);
  problem.operator_choice = read_operator_choice(root);
  if (const toml::table* table = root.optional_table("output", "[output]")) {
    const TableReader output(*table, "output", context, root.line());
    output.check_keys(schema::table("output"));
    result.output.vtk = output.boolean_or("vtk", true);
  }
  result.warnings = context.warnings;
  return result;
}

ProblemFile read_problem_file(const std::filesystem::path& path, const ParameterOverrides& overrides) {
  return parse_problem(read_problem_text(path), path.string(), overrides);
}

}  // namespace bemcontact::io

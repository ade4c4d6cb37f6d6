#pragma once
// The body-level part of a problem file: [material], [vertices], [[boundary]] and
// [[constraint]]. Kept apart from the file-level keys so that a file may later hold
// several bodies ([[body]] tables, each read by parse_body); for now the root table is
// the one body.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "bemcontact/bem/problem.hpp"
#include "io/input/toml_reader.hpp"

namespace bemcontact::io {

struct BodyContext {
  const FileContext* file = nullptr;
  std::string path;                         // "" for the root table, later e.g. "body[2]"
  const schema::Table* table = nullptr;     // the whole table's keys (the body's and the file's)
  int fallback_line = 1;                    // line for messages about the table itself
};

bem::BodyDefinition parse_body(const toml::table& table, const BodyContext& context);

// A boundary value read from a number, an expression string or a table of values.
struct PrescribedValue {
  bem::ScalarField field;  // empty when identically zero
  std::string canonical;   // e.g. "0", "((0.001*x)+1)", "table(x;0:1,2:3)"
  bool zero = true;
  std::optional<double> constant;  // set when the value does not depend on the position
};
PrescribedValue read_prescribed_value(const toml::node& node, const SourceLocation& where,
                                      const FileContext& context);

// A grid of interior points { x = [min, max, count], y = [...] } (r, z as aliases in
// axisymmetry), row by row with x fastest; the counts are checked against the limits.
std::vector<bem::InteriorPoint> read_interior_grid(const TableReader& grid, const FileContext& context);

// The [parameters] table, in file order: each may use the ones written before it. A
// --set value for no parameter of the file is kept for the .geo files (FileContext).
void read_parameters(const TableReader& root, FileContext& context);

// Once every body is read: a --set value that neither a parameter of the file nor a .geo
// file of it takes is refused; those a .geo took join `parameters` (the echo).
void check_gmsh_overrides(const TableReader& root, const FileContext& context,
                          std::map<std::string, double>& parameters);

// The settings every problem file starts with: analysis (required), title (default: the
// file name without extension), interpolation (default linear), then [parameters].
void read_file_header(const TableReader& root, FileContext& context, const std::string& file_name,
                      AnalysisType& analysis, std::string& title, Interpolation& interpolation);

// The optional [mesh] table: corner_shift (split corner nodes' position, 0 < s < 0.5) and
// corner_transition (growth factor of the grading toward a vertex where a finer piece
// meets a coarser one, 1 < g <= 4, or 0 for none). Keys with no effect for the file's
// interpolation get a warning.
void read_mesh_options(const TableReader& root, FileContext& context, geometry::MeshOptions& options);

// The keys `operator` ("auto" | "dense" | "compressed") and `accuracy` of a [solver]
// table: the operator behind every body's boundary element system (docs/problem-file.md).
bem::OperatorChoice read_operator_keys(const TableReader& solver);

}  // namespace bemcontact::io

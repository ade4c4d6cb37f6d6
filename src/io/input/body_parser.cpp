#include "io/input/body_parser.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "bemcontact/io/input/gmsh_geometry.hpp"
#include "bemcontact/io/input/problem_schema.hpp"
#include "bemcontact/io/input/suggestions.hpp"
#include "bemcontact/io/text_format.hpp"
#include "bemcontact/operators/hmatrix.hpp"

namespace bemcontact::io {

namespace {

using geometry::BoundaryPiece;
using geometry::PieceShape;

struct Vertices {
  std::map<std::string, Vec2> points;
  std::vector<std::string> names;  // in file order, for messages
};

std::string point_text(const Vec2& p) {
  return "(" + format_number(p.x()) + ", " + format_number(p.y()) + ")";
}

// In axisymmetry the body lies in r >= 0; a tiny negative r from rounding is accepted.
void check_half_plane(const Vec2& point, const SourceLocation& where, const FileContext& context) {
  if (context.axisymmetric() && point.x() < -1e-12 * std::max(1.0, point.norm()))
    throw InputError(where, "the point " + point_text(point) +
                                " has r < 0; in an axisymmetric problem the body lies in r >= 0 "
                                "(the axis of revolution is r = 0)");
}

// A vertex name in quotes or a point [x, y]; `label` receives the name or the coordinates.
Vec2 resolve_point(const toml::node& node, const SourceLocation& where, const Vertices& vertices,
                   const FileContext& context, std::string* label = nullptr) {
  if (const auto name = node.value_exact<std::string>()) {
    const auto found = vertices.points.find(*name);
    if (found == vertices.points.end()) {
      std::string message = "unknown vertex '" + *name + "'.";
      if (vertices.names.empty()) {
        message += " The file has no [vertices] table; define the vertex there or write the point as " +
                   context.point_form();
      } else {
        message += did_you_mean(*name, vertices.names) + " Vertices: " + quoted_list(vertices.names) +
                   " (or write the point as " + context.point_form() + ")";
      }
      throw InputError(where, message);
    }
    if (label) *label = *name;
    return found->second;
  }
  if (node.is_array()) {
    const Vec2 point = read_point(node, where, context);
    check_half_plane(point, where, context);
    if (label) *label = point_text(point);
    return point;
  }
  throw InputError(where, "must be a vertex name in quotes or a point " + context.point_form() +
                              ", found " + describe_node(node));
}

bem::ScalarField constant_field(double value) {
  if (value == 0.0) return {};
  return [value](const Vec2&) { return value; };
}

PrescribedValue constant_value(double value) {
  return PrescribedValue{constant_field(value), format_number(value), value == 0.0, value};
}

PrescribedValue negated(const PrescribedValue& value) {
  if (value.zero) return value;
  if (value.constant) return constant_value(-*value.constant);  // a constant stays a constant
  PrescribedValue result;
  result.zero = false;
  result.canonical = "(-" + value.canonical + ")";
  result.field = [field = value.field](const Vec2& p) { return -field(p); };
  return result;
}

// Piecewise linear in one coordinate, constant beyond the first and last abscissae.
PrescribedValue read_tabulated(const toml::table& table, const SourceLocation& where,
                               const FileContext& context) {
  const TableReader reader(table, where.key, context, where.line);
  reader.check_keys(schema::table("tabulated"));
  std::vector<std::string> axes{"x", "y"};
  if (context.axisymmetric()) axes = {"r", "z", "x", "y"};
  const std::string along = reader.choice("along", axes, std::nullopt);
  const int axis = (along == "x" || along == "r") ? 0 : 1;

  const toml::node& rows_node =
      reader.require("table", "the rows [[" + along + "0, value0], [" + along + "1, value1], ...]");
  const toml::array* rows = rows_node.as_array();
  const std::string row_form = "[" + along + ", value]";
  if (!rows)
    reader.fail("table", "must be an array of rows " + row_form + ", found " + describe_node(rows_node));
  if (rows->size() < 2)
    reader.fail("table", "needs at least two rows " + row_form + " (for a constant value write the number)");
  std::vector<double> abscissae, values;
  for (const toml::node& row_node : *rows) {
    SourceLocation row_where = reader.where("table");
    if (line_of(row_node) > 0) row_where.line = line_of(row_node);
    const toml::array* row = row_node.as_array();
    if (!row || row->size() != 2)
      throw InputError(row_where, "each row must be " + row_form + " (two numbers), found " +
                                      (row ? "an array of " + std::to_string(row->size()) + " values"
                                           : describe_node(row_node)));
    const double abscissa = read_number(*row->get(0), row_where, context);
    const double value = read_number(*row->get(1), row_where, context);
    if (!abscissae.empty() && !(abscissa > abscissae.back()))
      throw InputError(row_where, "the " + along + " values of the rows must increase strictly; " +
                                      format_number(abscissa) + " follows " +
                                      format_number(abscissae.back()));
    abscissae.push_back(abscissa);
    values.push_back(value);
  }

  PrescribedValue result;
  result.zero = std::all_of(values.begin(), values.end(), [](double v) { return v == 0.0; });
  result.canonical = "table(" + std::string(axis == 0 ? "x" : "y") + ";";
  for (std::size_t i = 0; i < values.size(); ++i)
    result.canonical += (i ? "," : "") + format_number(abscissae[i]) + ":" + format_number(values[i]);
  result.canonical += ")";
  if (result.zero) return constant_value(0.0);
  result.field = [abscissae, values, axis](const Vec2& p) {
    const double s = p[axis];
    if (s <= abscissae.front()) return values.front();
    if (s >= abscissae.back()) return values.back();
    const std::size_t k = static_cast<std::size_t>(
        std::upper_bound(abscissae.begin(), abscissae.end(), s) - abscissae.begin());
    const double w = (s - abscissae[k - 1]) / (abscissae[k] - abscissae[k - 1]);
    return values[k - 1] + w * (values[k] - values[k - 1]);
  };
  return result;
}

bool before(const toml::node& a, const toml::node& b) {
  return a.source().begin < b.source().begin;
}

// Of two keys present in `reader`, the one written later (the error points there).
std::string later_key(const TableReader& reader, const std::string& a, const std::string& b) {
  return before(*reader.find(a), *reader.find(b)) ? b : a;
}

std::string join(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

bem::BoundaryCondition read_condition(const TableReader& reader, const std::string& piece_name,
                                      bool on_axis) {
  static const std::vector<std::string> global_keys{"u1", "u2", "t1", "t2"};
  static const std::vector<std::string> local_keys{"un", "ut", "tn", "tt", "pressure"};
  const auto present = [&reader](const std::vector<std::string>& keys) {
    std::vector<std::string> found;
    for (const auto& key : keys)
      if (reader.has(key)) found.push_back(key);
    std::sort(found.begin(), found.end(), [&reader](const std::string& a, const std::string& b) {
      return before(*reader.find(a), *reader.find(b));
    });
    return found;
  };
  const std::vector<std::string> global = present(global_keys);
  const std::vector<std::string> local = present(local_keys);
  const std::string label = "boundary '" + piece_name + "'";

  bem::BoundaryCondition condition;
  if (on_axis) {
    if (!global.empty() || !local.empty()) {
      std::vector<std::string> given = global;
      given.insert(given.end(), local.begin(), local.end());
      reader.fail(given.front(), label + " lies on the axis r = 0, which is not a boundary of an axisymmetric "
                               "body (the symmetry there is built into the formulation): remove its "
                               "conditions (" + join(given) + ")");
    }
    condition.signature = "axis";
    return condition;
  }
  if (!global.empty() && !local.empty())
    reader.fail(later_key(reader, global.back(), local.back()),
                label + " mixes global components (" + join(global) + ") with local ones (" +
                    join(local) + "). Give all conditions of a boundary in one frame: u1 u2 t1 t2 "
                    "along x and y, or un ut tn tt pressure along the outward normal and the "
                    "tangent; split the boundary in two if the conditions really differ");

  const bool is_local = !local.empty();
  condition.frame = is_local ? bem::ConditionFrame::local : bem::ConditionFrame::global;
  // Key names per component c and kind (0 displacement, 1 traction).
  static const char* const global_names[2][2] = {{"u1", "t1"}, {"u2", "t2"}};
  static const char* const local_names[2][2] = {{"un", "tn"}, {"ut", "tt"}};
  const auto& names = is_local ? local_names : global_names;
  std::array<PrescribedValue, 2> values;
  for (int c = 0; c < 2; ++c) {
    const std::string u = names[c][0];
    const std::string t = names[c][1];
    const bool has_u = reader.has(u), has_t = reader.has(t);
    const bool has_pressure = is_local && c == 0 && reader.has("pressure");
    const std::string traction_key = has_t ? t : "pressure";
    if (has_u && (has_t || has_pressure))
      reader.fail(later_key(reader, u, traction_key),
                  label + " prescribes both a displacement (" + u + ") and a traction (" +
                      traction_key + ") on the same component. Each component takes one of them; "
                      "the other is what the solver computes. Remove one of '" + u + "' and '" +
                      traction_key + "'");
    if (has_t && has_pressure)
      reader.fail(later_key(reader, t, "pressure"),
                  label + " gives both 'tn' and 'pressure'; pressure = p is shorthand for tn = -p. "
                          "Remove one of them");
    condition.kind[c] = has_u ? bem::ConditionKind::displacement : bem::ConditionKind::traction;
    if (has_u || has_t) {
      const std::string& key = has_u ? u : t;
      values[c] = read_prescribed_value(*reader.find(key), reader.where(key), reader.context());
    } else if (has_pressure) {
      values[c] = negated(
          read_prescribed_value(*reader.find("pressure"), reader.where("pressure"), reader.context()));
    } else {
      values[c] = constant_value(0.0);  // a missing component is free (zero traction)
    }
    condition.value[c] = values[c].field;
  }

  // Canonical text: equal conditions give equal text. Zero tractions (or zero
  // displacements) on both components are the same in any frame.
  const bool both_zero = values[0].zero && values[1].zero;
  using bem::ConditionKind;
  if (both_zero && condition.kind[0] == ConditionKind::traction &&
      condition.kind[1] == ConditionKind::traction) {
    condition.signature = "free";
    return condition;
  }
  const bool frame_free = both_zero && condition.kind[0] == condition.kind[1];
  const bool write_local = is_local && !frame_free;
  condition.signature = write_local ? "local:" : "global:";
  for (int c = 0; c < 2; ++c) {
    const int k = condition.kind[c] == ConditionKind::displacement ? 0 : 1;
    condition.signature += std::string(c ? ";" : "") + (write_local ? local_names : global_names)[c][k] +
                           "=" + values[c].canonical;
  }
  return condition;
}

BoundaryPiece read_piece(const TableReader& reader, int index, const Vertices& vertices,
                         const FileContext& context) {
  reader.check_keys(schema::table("boundary"));
  BoundaryPiece piece;
  piece.where = SourceLocation{context.file, reader.line(), reader.path()};
  piece.name = reader.optional_name("name").value_or("boundary" + std::to_string(index));
  if (piece.name.empty()) reader.fail("name", "the name must not be empty");
  const std::string label = "boundary '" + piece.name + "'";
  const std::string shape = reader.choice("shape");
  piece.shape = shape == "arc" ? PieceShape::arc : PieceShape::line;
  const std::string point_help = "a vertex name in quotes or a point " + context.point_form();
  piece.start = resolve_point(reader.require("from", "the start point, " + point_help),
                              reader.where("from"), vertices, context);
  piece.end = resolve_point(reader.require("to", "the end point, " + point_help), reader.where("to"),
                            vertices, context);

  if (piece.shape == PieceShape::arc) {
    piece.center = resolve_point(reader.require("center", "an arc needs its center, " + point_help),
                                 reader.where("center"), vertices, context);
    piece.counterclockwise = reader.choice("direction") == "ccw";
  } else {
    for (const char* key : {"center", "direction"})
      if (reader.has(key))
        reader.fail(key, "'" + std::string(key) + "' applies only to arcs: add shape = \"arc\" to " +
                             label + " or remove '" + key + "'");
  }

  piece.elements = reader.integer_or("elements", 1);
  if (piece.elements > reader.context().limits.max_elements)
    reader.fail("elements", std::to_string(piece.elements) + " elements, over the limit of " +
                                std::to_string(reader.context().limits.max_elements) +
                                " per body (raise it with --max-elements if the machine has the memory)");
  piece.grading = reader.optional_number("grading").value_or(1.0);
  piece.refine_toward = reader.choice("refine") == "end"
                            ? geometry::RefineToward::end
                            : geometry::RefineToward::start;
  if (reader.has("refine") && (piece.grading == 1.0 || piece.elements == 1))
    reader.context().warnings.push_back(reader.where("refine").describe() +
                                        ": refine has no effect on a uniform boundary (grading = 1 or one element)");

  // Geometry that can be checked on the piece alone, with the file position at hand;
  // the contour checks (closure, crossings, orientation) come later in geometry/.
  const double chord = (piece.end - piece.start).norm();
  const double size = std::max({piece.start.norm(), piece.end.norm(), chord});
  if (!(chord > 1e-12 * size) || size == 0.0) {
    if (piece.shape == PieceShape::arc)
      reader.fail("to", label + ": 'from' and 'to' are the same point " + point_text(piece.start) +
                            "; split a full circle into two or more arcs");
    reader.fail("to", label + " has zero length: 'from' and 'to' are the same point " +
                          point_text(piece.start));
  }
  if (piece.shape == PieceShape::arc) {
    const double r0 = (piece.start - piece.center).norm();
    const double r1 = (piece.end - piece.center).norm();
    if (!(r0 > 1e-12 * size))
      reader.fail("center", label + ": the center coincides with the start point");
    // 1e-6 lets hand-typed decimals through; exact points come from expressions
    // such as ["R*cos(pi/4)", "R*sin(pi/4)"].
    if (std::fabs(r0 - r1) > 1e-6 * std::max(r0, r1))
      reader.fail("center", label + ": 'from' and 'to' are not on one circle around the center " +
                                point_text(piece.center) + ": their distances to it are " +
                                format_number(r0) + " and " + format_number(r1) +
                                " (write exact coordinates, e.g. [\"R*cos(pi/4)\", \"R*sin(pi/4)\"])");
  }

  return piece;
}

// Axisymmetry: a straight piece along r = 0 is the axis, not a boundary of the body.
bool lies_on_axis(const BoundaryPiece& piece, const FileContext& context) {
  const double chord = (piece.end - piece.start).norm();
  return context.axisymmetric() && piece.shape == PieceShape::line &&
         std::fabs(piece.start.x()) <= 1e-10 * chord && std::fabs(piece.end.x()) <= 1e-10 * chord;
}

const toml::array* array_of_tables(const TableReader& reader, std::string_view key,
                                   const std::string& header) {
  const toml::node* node = reader.find(key);
  if (!node) return nullptr;
  if (node->is_table())
    reader.fail(key, "write " + header + " with double brackets: each entry is one table of an "
                     "array of tables, found a single table [" + std::string(key) + "]");
  const toml::array* array = node->as_array();
  if (!array || array->empty() || !array->is_array_of_tables())
    reader.fail(key, "must be one or more " + header + " tables, found " +
                         (array && array->empty() ? std::string("an empty array") : describe_node(*node)));
  return array;
}

}  // namespace

PrescribedValue read_prescribed_value(const toml::node& node, const SourceLocation& where,
                                      const FileContext& context) {
  if (node.is_integer() || node.is_floating_point())
    return constant_value(read_number(node, where, context));
  if (const auto text = node.value_exact<std::string>()) {
    const Expression expression = Expression::parse(*text, context.field_scope(), where);
    if (expression.is_constant()) {
      const double value = expression.value();
      if (!std::isfinite(value))
        throw InputError(where, "the value is " + format_number(value) + "; a finite number is needed");
      return constant_value(value);
    }
    return PrescribedValue{expression.field(), expression.canonical(), false, std::nullopt};
  }
  if (const toml::table* table = node.as_table()) return read_tabulated(*table, where, context);
  throw InputError(where, "must be a number, an expression in quotes (e.g. \"1 - (2*y/H)^2\") or a "
                          "table of values { table = [[x0, v0], [x1, v1], ...], along = \"x\" }, "
                          "found " + describe_node(node));
}

// `symmetry = true`: the piece is a symmetry line of the body (geometry/symmetry.hpp). It
// carries no elements and no conditions (it holds u_n = 0, t_t = 0 itself), and is straight.
void read_symmetry(const TableReader& reader, BoundaryPiece& piece, bem::BoundaryCondition& condition) {
  piece.symmetry = reader.boolean_or("symmetry", false);
  if (!piece.symmetry) return;
  for (const char* key : {"u1", "u2", "t1", "t2", "un", "ut", "tn", "tt", "pressure"})
    if (reader.has(key))
      reader.fail(key, "boundary '" + piece.name + "' is a symmetry line (symmetry = true): it holds u_n = 0 and "
                           "t_t = 0 itself and takes no condition");
  for (const char* key : {"elements", "grading", "refine"})
    if (reader.has(key))
      reader.fail(key, "boundary '" + piece.name + "' is a symmetry line (symmetry = true): it carries no elements "
                           "(the body's mirror image takes its place)");
  if (piece.shape != PieceShape::line)
    reader.fail("symmetry", "boundary '" + piece.name + "': a symmetry line must be straight");
  condition = bem::BoundaryCondition{};
  condition.signature = "symmetry line";
}

// The [[boundary]] tables: each a piece (line or arc) with its conditions.
void read_boundary_pieces(const TableReader& body, const FileContext& context, const Vertices& vertices,
                          bem::BodyDefinition& definition) {
  // [[boundary]]
  const toml::array* boundaries = array_of_tables(body, "boundary", "[[boundary]]");
  if (!boundaries)
    body.fail("boundary", "missing [[boundary]] tables: the body needs boundary pieces (lines and "
                          "arcs) forming closed contours");
  std::map<std::string, int> name_lines;
  int index = 0;
  for (const toml::node& node : *boundaries) {
    ++index;
    const std::string path = body.key_path("boundary[" + std::to_string(index) + "]");
    const TableReader reader(*node.as_table(), path, context, body.where("boundary").line);
    BoundaryPiece piece = read_piece(reader, index, vertices, context);
    const auto [existing, inserted] = name_lines.emplace(piece.name, reader.line());
    if (!inserted)
      reader.fail(reader.has("name") ? "name" : "",
                  "the boundary name '" + piece.name + "' is already used by the boundary at line " +
                      std::to_string(existing->second) + "; boundary names must be unique");
    bem::BoundaryCondition condition = read_condition(reader, piece.name, lies_on_axis(piece, context));
    read_symmetry(reader, piece, condition);
    piece.condition_signature = condition.signature;
    definition.pieces.push_back(std::move(piece));
    definition.conditions.push_back(std::move(condition));
  }
}

namespace {

std::vector<std::string> identifiers_in(std::string_view text) {
  std::vector<std::string> names;
  const auto name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t i = 0; i < text.size();) {
    const bool starts = (std::isalpha(static_cast<unsigned char>(text[i])) || text[i] == '_') &&
                        (i == 0 || (!name_char(text[i - 1]) && text[i - 1] != '.'));
    if (!starts) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && name_char(text[end])) ++end;
    names.emplace_back(text.substr(i, end - i));
    i = end;
  }
  return names;
}

// How the user gave a replacing value, for messages: "--set P" or the caller's own words.
std::string origin_of(const std::string& name, const ParameterValue& value) {
  return value.origin.empty() ? "--set " + name : value.origin;
}

// A replacing value (a number, or an expression evaluated here with the parameters before
// it); its errors say where it came from, at the parameter's line of the file.
double replacing_value(const std::string& name, const ParameterValue& value, const SourceLocation& where,
                       const FileContext& context) {
  try {
    const double number = value.expression.empty()
                              ? value.number
                              : Expression::parse(value.expression, context.constant_scope(), where).value();
    if (!std::isfinite(number))
      throw InputError(where, "the value is " + format_number(number) + "; a finite number is needed");
    return number;
  } catch (const InputError& error) {
    std::string message = error.what();
    const std::string location = where.describe() + ": ";
    if (message.rfind(location, 0) == 0) message.erase(0, location.size());
    throw InputError(where, origin_of(name, value) + ": " + message);
  }
}

}  // namespace

// The numbers a .geo file gets (gmsh -setnumber): every parameter of the problem file, and
// the --set values for no parameter of it that the .geo declares with DefineConstant.
std::map<std::string, double> gmsh_numbers(const std::filesystem::path& file, const FileContext& context) {
  std::map<std::string, double> numbers(context.parameters.begin(), context.parameters.end());
  if (context.gmsh_overrides.empty()) return numbers;
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const auto declared = geo_constants(text.str());
  for (const auto& [name, value] : context.gmsh_overrides)
    if (declared.count(name)) {
      numbers[name] = replacing_value(name, value, SourceLocation{context.file, 0, "parameters." + name}, context);
      context.gmsh_overrides_used.insert(name);
    }
  return numbers;
}

// The body's pieces from a Gmsh file (io/gmsh_geometry.hpp); each [[boundary]] table
// gives the conditions of the physical curve of its name (none: traction-free).
void read_gmsh_pieces(const TableReader& body, const FileContext& context, bem::BodyDefinition& definition) {
  const auto name = body.optional_string("geometry");
  if (!name || name->empty()) body.fail("geometry", "the Gmsh file (.geo or .msh) as a string");
  std::filesystem::path file(*name);
  // Relative to the problem file's folder.
  if (file.is_relative() && !context.file.empty() && context.file.front() != '<')
    file = std::filesystem::path(context.file).parent_path() / file;
  GmshOptions options;
  options.limits = context.limits;
  if (file.extension() == ".geo") options.numbers = gmsh_numbers(file, context);
  GmshBoundary gmsh;
  try {
    gmsh = read_gmsh_boundary(file, context.axisymmetric(), options);
  } catch (const InputError& e) {
    // The Gmsh file's own position, then the key that named it.
    throw InputError(body.where("geometry"), e.what());
  }
  std::vector<std::string> curve_names;
  for (const auto& piece : gmsh.pieces) {
    if (const std::string problem = name_problem(piece.name); !problem.empty())
      body.fail("geometry", "a physical curve of '" + *name + "': " + problem);
    curve_names.push_back(piece.name);
  }
  std::map<std::string, std::pair<const toml::table*, int>> conditions;  // by curve name: table, line
  if (const toml::array* boundaries = array_of_tables(body, "boundary", "[[boundary]]")) {
    int index = 0;
    for (const toml::node& node : *boundaries) {
      ++index;
      const TableReader reader(*node.as_table(), body.key_path("boundary[" + std::to_string(index) + "]"), context,
                               body.where("boundary").line);
      reader.check_keys(schema::table("boundary"));
      for (const char* key : {"shape", "from", "to", "center", "direction", "elements", "grading", "refine"})
        if (reader.has(key))
          reader.fail(key, "'" + std::string(key) + "' comes from the Gmsh file '" + *name +
                               "' (its curves, their mesh and grading): give only name and conditions here");
      const auto boundary_name = reader.optional_name("name");
      if (!boundary_name) reader.fail("name", "name the physical curve of '" + *name + "' these conditions apply to");
      if (std::find(curve_names.begin(), curve_names.end(), *boundary_name) == curve_names.end())
        reader.fail("name", "'" + *name + "' has no physical curve named '" + *boundary_name + "'." +
                                did_you_mean(*boundary_name, curve_names) + " Its curves: " + quoted_list(curve_names));
      const auto [existing, added] = conditions.emplace(*boundary_name, std::pair{node.as_table(), reader.line()});
      if (!added)
        reader.fail("name", "the boundary '" + *boundary_name + "' already has conditions at line " +
                                std::to_string(existing->second.second));
    }
  }
  const toml::table traction_free;
  for (auto& piece : gmsh.pieces) {
    const auto found = conditions.find(piece.name);
    const int line = found != conditions.end() ? found->second.second : body.where("geometry").line;
    const TableReader reader(found != conditions.end() ? *found->second.first : traction_free,
                             body.key_path("boundary '" + piece.name + "'"), context, line);
    piece.where = SourceLocation{context.file, line, reader.path()};
    if (piece.elements > context.limits.max_elements)
      body.fail("geometry", "curve '" + piece.name + "' has " + std::to_string(piece.elements) +
                                " elements, over the limit of " + std::to_string(context.limits.max_elements));
    bem::BoundaryCondition condition = read_condition(reader, piece.name, lies_on_axis(piece, context));
    read_symmetry(reader, piece, condition);
    const bool reversed = std::find(gmsh.reversed.begin(), gmsh.reversed.end(), piece.name) != gmsh.reversed.end();
    if (reversed && (reader.has("ut") || reader.has("tt")))
      context.warnings.push_back(reader.where().describe() + ": curve '" + piece.name +
                                 "' runs against the body's orientation in '" + *name +
                                 "' and was reversed: 'ut'/'tt' act along the reversed direction (body on the left)");
    piece.condition_signature = condition.signature;
    definition.pieces.push_back(std::move(piece));
    definition.conditions.push_back(std::move(condition));
  }
}

namespace {

// A list of points [[x, y], ...] (`count` of them when count > 0).
std::vector<Vec2> read_point_list(const TableReader& table, std::string_view key, std::size_t count,
                                  const std::string& form) {
  const toml::node& node = table.require(key, form);
  const toml::array* list = node.as_array();
  if (!list || list->empty() || (count > 0 && list->size() != count))
    table.fail(key, "must be " + form + ", found " + describe_node(node));
  std::vector<Vec2> points;
  for (const toml::node& point : *list) {
    SourceLocation where = table.where(key);
    if (line_of(point) > 0) where.line = line_of(point);
    points.push_back(read_point(point, where, table.context()));
  }
  return points;
}

// [material] yield_stress, hardening, kinematic_hardening and the region's [cells]: an
// elastoplastic region (docs/plasticity.md). Each needs the other.
std::optional<bem::RegionPlasticity> read_plasticity(const TableReader& body, const TableReader& material,
                                                     const FileContext& context) {
  const toml::table* cells_table = body.optional_table("cells", "[cells]");
  if (!material.has("yield_stress")) {
    for (const char* key : {"hardening", "kinematic_hardening"})
      if (material.has(key))
        material.fail(key, "has no effect without yield_stress: give the yield stress (the region is then "
                           "elastoplastic) or remove it");
    if (cells_table)
      body.fail("cells", "has no effect on a linear elastic region: give [material] yield_stress, or remove [cells]");
    return std::nullopt;
  }
  if (!cells_table)
    material.fail("yield_stress", "makes the region elastoplastic: it needs a [cells] table with the cells' size "
                                  "(where it may yield; docs/plasticity.md)");
  bem::RegionPlasticity plasticity;
  plasticity.where = material.where("yield_stress");
  plasticity.hardening.yield_stress = material.number("yield_stress");
  plasticity.hardening.isotropic = material.optional_number("hardening").value_or(0.0);
  plasticity.hardening.kinematic = material.optional_number("kinematic_hardening").value_or(0.0);

  const TableReader cells(*cells_table, body.key_path("cells"), context, body.line());
  cells.check_keys(schema::table("cells"));
  plasticity.cells_where = cells.where();
  auto& options = plasticity.cells;
  options.size = cells.number("size");
  options.crossed = cells.optional_string("shape").value_or("rectangles") == "crossed";
  plasticity.nodes_at_cells = cells.boolean_or("nodes_at_cells", true);
  plasticity.cell_operator = cells.optional_string("operator").value_or("dense") == "compressed"
                                 ? bem::OperatorKind::compressed
                                 : bem::OperatorKind::dense;
  if (plasticity.cell_operator == bem::OperatorKind::compressed && !operators::hmatrix_available())
    cells.fail("operator", "\"compressed\" needs hmat-oss, which this build was made without (install "
                           "libhmat-oss-dev and build with BEMCONTACT_WITH_HMAT=ON), or use \"dense\"");
  if (cells.has("box")) {
    const auto corners = read_point_list(cells, "box", 2, "[[x0, y0], [x1, y1]] (lower-left, upper-right)");
    if (!(corners[1].x() > corners[0].x() && corners[1].y() > corners[0].y()))
      cells.fail("box", "its second corner must lie above and right of the first (lower-left, upper-right)");
    options.box = std::array<Vec2, 2>{corners[0], corners[1]};
  }
  if (cells.has("refine")) {
    options.refine_points = read_point_list(cells, "refine", 0, "a list of points [[x, y], ...]");
    if (!cells.has("refine_size")) cells.fail("refine", "needs refine_size, the cells' edge at the points");
    options.refine_size = cells.number("refine_size");
    if (options.refine_size > options.size)
      cells.fail("refine_size", "must be at most size (" + format_number(options.size) + ")");
    options.growth = cells.optional_number("growth").value_or(0.5);
  } else {
    for (const char* key : {"refine_size", "growth"})
      if (cells.has(key)) cells.fail(key, "has no effect without refine (the points the cells are graded toward)");
  }
  return plasticity;
}

}  // namespace

bem::BodyDefinition parse_body(const toml::table& table, const BodyContext& body_context) {
  const FileContext& context = *body_context.file;
  const TableReader body(table, body_context.path, context, body_context.fallback_line);
  body.check_keys(*body_context.table);

  bem::BodyDefinition definition;
  if (!body_context.path.empty()) definition.name = body_context.path;

  // [material]
  const toml::table* material_table = body.optional_table("material", "[material]");
  if (!material_table)
    body.fail("material", "missing required table [material] with E (Young's modulus) and nu "
                          "(Poisson's ratio)");
  const TableReader material(*material_table, body.key_path("material"), context, body.line());
  material.check_keys(schema::table("material"));
  definition.material.young_modulus = material.number("E");
  definition.material.poisson_ratio = material.number("nu");
  definition.plasticity = read_plasticity(body, material, context);

  // [vertices]
  Vertices vertices;
  if (const toml::table* vertex_table = body.optional_table("vertices", "[vertices]")) {
    std::vector<std::pair<const toml::key*, const toml::node*>> entries;
    for (const auto& [key, node] : *vertex_table) entries.emplace_back(&key, &node);
    std::sort(entries.begin(), entries.end(),
              [](const auto& a, const auto& b) { return before(*a.second, *b.second); });
    for (const auto& [key, node] : entries) {
      const std::string name(key->str());
      // (Vertices copied from a decomposition's shared [vertices] have no line of their own.)
      SourceLocation where{context.file, line_of(*node) > 0 ? line_of(*node) : body.line(),
                           body.key_path("vertices." + name)};
      const Vec2 point = read_point(*node, where, context);
      check_half_plane(point, where, context);
      vertices.points[name] = point;
      vertices.names.push_back(name);
    }
  }

  // geometry = "part.msh" / "part.geo": the pieces are Gmsh's physical curves.
  if (body.has("geometry"))
    read_gmsh_pieces(body, context, definition);
  else
    read_boundary_pieces(body, context, vertices, definition);

  // [[constraint]]
  if (const toml::array* constraints = array_of_tables(body, "constraint", "[[constraint]]")) {
    int index = 0;
    for (const toml::node& node : *constraints) {
      ++index;
      const std::string path = body.key_path("constraint[" + std::to_string(index) + "]");
      const TableReader reader(*node.as_table(), path, context, body.where("constraint").line);
      reader.check_keys(schema::table("constraint"));
      bem::PointConstraint constraint;
      constraint.where = SourceLocation{context.file, reader.line(), path};
      constraint.position =
          resolve_point(reader.require("at", "the point, a vertex name or " + context.point_form()),
                        reader.where("at"), vertices, context, &constraint.label);
      constraint.displacement[0] = reader.optional_number("u1");
      constraint.displacement[1] = reader.optional_number("u2");
      if (!constraint.displacement[0] && !constraint.displacement[1])
        reader.fail("", "a point constraint needs u1 and/or u2 (the prescribed displacement "
                        "components at '" + constraint.label + "')");
      definition.constraints.push_back(std::move(constraint));
    }
  }
  return definition;
}


void read_parameters(const TableReader& root, FileContext& context) {
  const toml::table* table = root.optional_table("parameters", "[parameters]");
  // Values for no parameter of the file may be for a .geo file (checked once it is read).
  for (const auto& [name, value] : context.overrides)
    if (!table || !table->contains(name)) context.gmsh_overrides[name] = value;
  if (!table) return;
  const TableReader parameters(*table, "parameters", context, root.line());
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [key, node] : *table) entries.emplace_back(std::string(key.str()), &node);
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    return a.second->source().begin < b.second->source().begin;
  });
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& [name, node] = entries[i];
    const SourceLocation where = parameters.where(name);
    if (!is_identifier(name))
      throw InputError(where, "invalid parameter name '" + name + "': a name starts with a letter or "
                              "'_' and holds only letters, digits and '_'");
    if (is_reserved_name(name))
      throw InputError(where, "'" + name + "' cannot be a parameter name: x, y, r, z, pi and the "
                              "function names are reserved");
    if (!node->is_string() && !node->is_integer() && !node->is_floating_point())
      throw InputError(where, "a parameter must be a number or an expression in quotes, found " +
                                  describe_node(*node));
    const auto replaced = context.overrides.find(name);
    const bool overridden = replaced != context.overrides.end();
    // Say plainly when an expression (the file's, or the one replacing it) uses a parameter
    // defined further down.
    const auto check_order = [&](const std::string& text, const std::string& origin) {
      for (const std::string& used : identifiers_in(text))
        for (std::size_t j = i + 1; j < entries.size(); ++j)
          if (entries[j].first == used && !context.parameters.count(used))
            throw InputError(where, origin + "parameter '" + name + "' uses '" + used +
                                        "', which is defined later (line " +
                                        std::to_string(line_of(*entries[j].second)) +
                                        "); a parameter may only use the parameters written before it");
    };
    if (node->is_string()) check_order(*node->value_exact<std::string>(), "");
    if (overridden) check_order(replaced->second.expression, origin_of(name, replaced->second) + ": ");
    context.parameters[name] =
        overridden ? replacing_value(name, replaced->second, where, context) : read_number(*node, where, context);
  }
}

void read_file_header(const TableReader& root, FileContext& context, const std::string& file_name,
                      AnalysisType& analysis, std::string& title, Interpolation& interpolation) {
  const std::string type = root.choice("analysis");
  analysis = type == "plane_stress"   ? AnalysisType::plane_stress
             : type == "axisymmetric" ? AnalysisType::axisymmetric
                                      : AnalysisType::plane_strain;
  context.analysis = analysis;
  title = root.optional_string("title").value_or(std::filesystem::path(file_name).stem().string());
  const std::string order = root.choice("interpolation");
  interpolation = order == "constant"    ? Interpolation::constant
                  : order == "quadratic" ? Interpolation::quadratic
                                         : Interpolation::linear;
  read_parameters(root, context);
}

void check_gmsh_overrides(const TableReader& root, const FileContext& context,
                          std::map<std::string, double>& parameters) {
  for (const auto& [name, value] : context.gmsh_overrides) {
    if (context.gmsh_overrides_used.count(name)) {
      // Echoed with the file's own.
      parameters[name] = replacing_value(name, value, SourceLocation{context.file, 0, "parameters." + name}, context);
      continue;
    }
    const toml::table* table = root.optional_table("parameters", "[parameters]");
    std::string known;
    if (table)
      for (const auto& [key, node] : *table) known += (known.empty() ? "" : ", ") + std::string(key.str());
    throw InputError(SourceLocation{context.file, table ? root.where("parameters").line : 0, "parameters." + name},
                     origin_of(name, value) + ": the file has no parameter '" + name + "' to replace (" +
                         (known.empty() ? "it has no [parameters]" : "its parameters: " + known) +
                         "), and no .geo file of it declares '" + name + "' with DefineConstant");
  }
}

std::vector<bem::InteriorPoint> read_interior_grid(const TableReader& grid, const FileContext& context) {
  grid.check_keys(schema::table("grid"));
  if (!context.axisymmetric())
    for (const char* key : {"r", "z"})
      if (grid.has(key)) grid.fail(key, "'r' and 'z' name the coordinates of an axisymmetric problem; write x and y");
  std::array<std::vector<double>, 2> coordinates;
  for (int axis = 0; axis < 2; ++axis) {
    const std::string plane_name = axis == 0 ? "x" : "y";
    const std::string axisymmetric_name = axis == 0 ? "r" : "z";
    std::string key = plane_name;
    if (context.axisymmetric()) {
      if (grid.has(plane_name) && grid.has(axisymmetric_name))
        grid.fail(axisymmetric_name, "give '" + axisymmetric_name + "' or its alias '" + plane_name +
                                         "', not both");
      key = grid.has(plane_name) ? plane_name : axisymmetric_name;
    }
    const toml::node& node =
        grid.require(key, "[min, max, count] of the grid along " + key);
    const toml::array* range = node.as_array();
    if (!range || range->size() != 3)
      grid.fail(key, "must be [min, max, count], found " +
                         (range ? "an array of " + std::to_string(range->size()) + " values"
                                : describe_node(node)));
    const SourceLocation where = grid.where(key);
    const double low = read_number(*range->get(0), where, context);
    const double high = read_number(*range->get(1), where, context);
    const int count = read_integer(*range->get(2), where, context);
    if (count < 1) grid.fail(key, "the count must be >= 1, found " + std::to_string(count));
    if (high < low)
      grid.fail(key, "max (" + format_number(high) + ") is below min (" + format_number(low) + ")");
    if (count == 1 && high != low)
      grid.fail(key, "a count of 1 needs min = max (one line of points); use a count >= 2 to "
                     "span [" + format_number(low) + ", " + format_number(high) + "]");
    if (count > context.limits.max_interior_points)
      grid.fail(key, "the count " + std::to_string(count) + " is over the limit of " +
                         std::to_string(context.limits.max_interior_points) + " interior points (raise it with --max-points)");
    for (int i = 0; i < count; ++i)
      coordinates[axis].push_back(count == 1 ? low : low + (high - low) * i / (count - 1));
  }
  const double total = static_cast<double>(coordinates[0].size()) * static_cast<double>(coordinates[1].size());
  if (total > static_cast<double>(context.limits.max_interior_points))
    grid.fail("", "the grid has " + format_number(total) + " points, over the limit of " +
                      std::to_string(context.limits.max_interior_points) + " (raise it with --max-points)");
  // Row by row: x (r) varies fastest.
  std::vector<bem::InteriorPoint> points;
  for (std::size_t row = 0; row < coordinates[1].size(); ++row)
    for (std::size_t column = 0; column < coordinates[0].size(); ++column)
      points.push_back(bem::InteriorPoint{Vec2(coordinates[0][column], coordinates[1][row]), true, {},
                                          {static_cast<int>(column), static_cast<int>(row)}});
  return points;
}

void read_mesh_options(const TableReader& root, FileContext& context, geometry::MeshOptions& options) {
  const toml::table* table = root.optional_table("mesh", "[mesh]");
  if (!table) return;
  const TableReader mesh(*table, "mesh", context, root.line());
  mesh.check_keys(schema::table("mesh"));
  if (const auto continuity = mesh.optional_string("continuity")) {
    if (*continuity == "discontinuous") {
      geometry::use_discontinuous_elements(options);
      if (options.interpolation == Interpolation::constant)
        context.warnings.push_back(SourceLocation{context.file, mesh.line(), "mesh.continuity"}.describe() +
                                   ": continuity has no effect with constant elements (they are discontinuous)");
    }
  }
  if (const auto shift = mesh.optional_number("corner_shift")) {
    options.corner_shift = *shift;
    if (options.interpolation == Interpolation::constant)
      context.warnings.push_back(SourceLocation{context.file, mesh.line(), "mesh.corner_shift"}.describe() +
                                 ": corner_shift has no effect with constant elements (their nodes are at "
                                 "element middles)");
  }
  if (const auto growth = mesh.optional_number("corner_transition")) {
    if (!(*growth == 0.0 || (*growth > 1.0 && *growth <= 4.0)))
      mesh.fail("corner_transition", "the corner transition (growth factor of the element lengths away from a "
                                     "vertex where finer elements meet) must satisfy 1 < corner_transition <= 4, "
                                     "or be 0 to keep every boundary's elements as given; found " +
                                         format_number(*growth));
    options.corner_transition = *growth;
  }
}

bem::OperatorChoice read_operator_keys(const TableReader& solver) {
  bem::OperatorChoice choice;
  const std::string kind = solver.choice("operator");
  choice.kind = kind == "dense" ? bem::OperatorKind::dense
                : kind == "compressed" ? bem::OperatorKind::compressed
                                       : bem::OperatorKind::automatic;
  if (const auto accuracy = solver.optional_number("accuracy")) {
    if (choice.kind == bem::OperatorKind::dense)
      solver.fail("accuracy", "accuracy sets the compressed operator; with operator = \"dense\" it has no effect");
    choice.accuracy = *accuracy;
  }
  return choice;
}

}  // namespace bemcontact::io

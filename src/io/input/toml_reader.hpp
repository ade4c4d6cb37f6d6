#pragma once
// Typed, checked access to the tables of a problem file (toml++). Every failure throws
// InputError naming the file, the line and the dotted key ("material.E",
// "boundary[2].elements", 1-based indices), says what was found and what is valid.
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "bemcontact/core/error.hpp"
#include "bemcontact/core/limits.hpp"
#include "bemcontact/io/input/expression.hpp"
#include "bemcontact/io/input/parameter_overrides.hpp"
#include "bemcontact/io/input/problem_schema.hpp"

namespace bemcontact::io {

// What every part of the file needs to know about the whole file.
struct FileContext {
  std::string file;  // as given by the user, for messages
  AnalysisType analysis = AnalysisType::plane_strain;
  std::map<std::string, double> parameters;
  ParameterOverrides overrides;
  // --set values the file has no [parameters] entry for: they go to the .geo files that
  // declare them (DefineConstant), and are refused when none does (check_gmsh_overrides).
  ParameterOverrides gmsh_overrides;
  mutable std::set<std::string> gmsh_overrides_used;
  ResourceLimits limits;
  // Documented warnings found while reading (a key whose value makes it have no effect);
  // copied into the file's result, printed on stderr and kept in summary.json.
  mutable std::vector<std::string> warnings;

  // A file's reading starts from its name, the command's overrides and the limits.
  static FileContext starting(std::string file, ParameterOverrides overrides, ResourceLimits limits) {
    FileContext context;
    context.file = std::move(file);
    context.overrides = std::move(overrides);
    context.limits = limits;
    return context;
  }

  bool axisymmetric() const { return analysis == AnalysisType::axisymmetric; }
  // Numbers, pi and parameters (geometry, material, parameter definitions).
  ExpressionScope constant_scope() const;
  // Plus the coordinates x, y (r, z): boundary values.
  ExpressionScope field_scope() const;
  // "[x, y]" or "[r, z]".
  std::string point_form() const;
};

// Line of a node in the file; 0 when toml++ does not know it (implicit tables).
int line_of(const toml::node& node);
// "a string \"abc\"", "an integer (3)", "a table", ... for "found ..." in messages.
std::string describe_node(const toml::node& node);

// Readers of single values. `where` names the value (file, line, key).
double read_number(const toml::node& node, const SourceLocation& where, const FileContext& context);
int read_integer(const toml::node& node, const SourceLocation& where, const FileContext& context);
Vec2 read_point(const toml::node& node, const SourceLocation& where, const FileContext& context);

// One table of the file with its dotted path, e.g. path "boundary[2]" for the second
// [[boundary]] table, "" for the root.
// Parses TOML text; a syntax error becomes an InputError with the file, line and column.
toml::table parse_toml_text(std::string_view text, const std::string& file_name);


// Names (of boundaries, bodies, regions, subdomains, contacts, loads) go into messages,
// CSV columns and output file names ("<body>_boundary.csv"): at most 100 characters (a
// file name may hold 255 bytes), none of them a control character.
inline constexpr std::size_t max_name_characters = 100;
// Why `name` cannot be a name (empty, too long, a control character), or "" when it can.
std::string name_problem(std::string_view name);

class TableReader {
 public:
  TableReader(const toml::table& table, std::string path, const FileContext& context,
              int fallback_line = 1);

  const toml::table& table() const { return table_; }
  const std::string& path() const { return path_; }
  const FileContext& context() const { return context_; }

  std::string key_path(std::string_view key) const;  // "material.E"
  int line() const;                                  // of the table (header line)
  SourceLocation where() const;                      // the table itself
  SourceLocation where(std::string_view key) const;  // the key's value, or the table
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;

  // Rejects every key not in `valid`: names the first one in the file, suggests the
  // closest valid key, and lists the valid keys. `section` (e.g. "the [mesh] table")
  // lets the message point to the table where a misplaced key belongs.
  void check_keys(const std::vector<std::string>& valid, std::string_view section) const;
  // The same against a table of the schema (problem_schema.hpp), then each key's value:
  // its type, its choices, its range. The table is kept for choice(key).
  void check_keys(const schema::Table& table) const;

  const toml::node* find(std::string_view key) const;
  bool has(std::string_view key) const { return find(key) != nullptr; }
  const toml::node& require(std::string_view key, std::string_view what) const;

  double number(std::string_view key) const;  // required
  std::optional<double> optional_number(std::string_view key) const;
  int integer_or(std::string_view key, int fallback) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  std::optional<std::string> optional_string(std::string_view key) const;
  // A string checked as a name (name_problem).
  std::optional<std::string> optional_name(std::string_view key) const;
  // One of `choices`; `fallback` empty = required.
  std::string choice(std::string_view key, const std::vector<std::string>& choices,
                     std::optional<std::string> fallback) const;
  // One of the schema's choices for `key`, its default when absent (required without one).
  std::string choice(std::string_view key) const;
  // A sub-table, or nullptr when absent; throws when the key holds something else.
  const toml::table* optional_table(std::string_view key, std::string_view header) const;

 private:
  const toml::table& table_;
  std::string path_;
  const FileContext& context_;
  int fallback_line_;
  mutable const schema::Table* schema_ = nullptr;  // set by check_keys(table)

  void check_value(const schema::Key& key, const toml::node& node) const;
};

}  // namespace bemcontact::io

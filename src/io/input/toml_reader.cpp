#include "io/input/toml_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "bemcontact/io/input/problem_schema.hpp"
#include "bemcontact/io/input/suggestions.hpp"
#include "bemcontact/io/text_format.hpp"

namespace bemcontact::io {

ExpressionScope FileContext::constant_scope() const {
  ExpressionScope scope;
  scope.parameters = parameters;
  scope.coordinates = false;
  scope.axisymmetric = axisymmetric();
  return scope;
}

ExpressionScope FileContext::field_scope() const {
  ExpressionScope scope = constant_scope();
  scope.coordinates = true;
  return scope;
}

std::string FileContext::point_form() const { return axisymmetric() ? "[r, z]" : "[x, y]"; }

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

std::string describe_node(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "the string \"" + std::string(*node.value<std::string_view>()) + "\"";
    case toml::node_type::integer: return "the integer " + std::to_string(*node.value_exact<int64_t>());
    case toml::node_type::floating_point: return "the number " + format_number(*node.value_exact<double>());
    case toml::node_type::boolean: return std::string("the boolean ") + (*node.value_exact<bool>() ? "true" : "false");
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date/time";
    default: return "nothing";
  }
}

namespace {

// The location of an array element: same key, the element's own line.
SourceLocation at_node(const toml::node& node, const SourceLocation& where) {
  SourceLocation located = where;
  if (line_of(node) > 0) located.line = line_of(node);
  return located;
}

double checked_finite(double value, const SourceLocation& where) {
  if (!std::isfinite(value))
    throw InputError(where, "the value is " + format_number(value) + "; a finite number is needed");
  return value;
}

}  // namespace

double read_number(const toml::node& node, const SourceLocation& where, const FileContext& context) {
  if (const auto integer = node.value_exact<int64_t>()) return static_cast<double>(*integer);
  if (const auto number = node.value_exact<double>()) return checked_finite(*number, where);
  if (const auto text = node.value_exact<std::string>()) {
    const Expression expression = Expression::parse(*text, context.constant_scope(), where);
    return checked_finite(expression.value(), where);
  }
  throw InputError(where, "must be a number or an expression of parameters in quotes (e.g. \"L/2\"), found " +
                              describe_node(node));
}

int read_integer(const toml::node& node, const SourceLocation& where, const FileContext& context) {
  double value = 0.0;
  if (const auto integer = node.value_exact<int64_t>()) {
    value = static_cast<double>(*integer);
  } else if (node.is_floating_point() || node.is_string()) {
    value = read_number(node, where, context);
  } else {
    throw InputError(where, "must be an integer (or an expression of parameters in quotes), found " +
                                describe_node(node));
  }
  if (std::fabs(value) > std::numeric_limits<int>::max())
    throw InputError(where, "must be an integer, found " + format_number(value));
  if (value != std::floor(value))
    throw InputError(where, "must be an integer, found " + format_number(value) +
                                (node.is_string() ? " (round the expression: round(...), floor(...) or ceil(...))" : ""));
  return static_cast<int>(value);
}

Vec2 read_point(const toml::node& node, const SourceLocation& where, const FileContext& context) {
  const toml::array* array = node.as_array();
  if (!array || array->size() != 2)
    throw InputError(where, "must be a point " + context.point_form() + " (two numbers), found " +
                                (array ? "an array of " + std::to_string(array->size()) + " values"
                                       : describe_node(node)));
  Vec2 point(read_number(*array->get(0), at_node(*array->get(0), where), context),
             read_number(*array->get(1), at_node(*array->get(1), where), context));
  return point;
}

TableReader::TableReader(const toml::table& table, std::string path, const FileContext& context,
                         int fallback_line)
    : table_(table), path_(std::move(path)), context_(context), fallback_line_(fallback_line) {}

std::string TableReader::key_path(std::string_view key) const {
  if (path_.empty()) return std::string(key);
  if (key.empty()) return path_;
  return path_ + "." + std::string(key);
}

int TableReader::line() const {
  const int line = line_of(table_);
  return line > 0 ? line : fallback_line_;
}

SourceLocation TableReader::where() const { return SourceLocation{context_.file, line(), path_}; }

SourceLocation TableReader::where(std::string_view key) const {
  SourceLocation location{context_.file, line(), key_path(key)};
  if (const toml::node* node = find(key); node && line_of(*node) > 0) location.line = line_of(*node);
  return location;
}

void TableReader::fail(std::string_view key, const std::string& message) const {
  throw InputError(where(key), message);
}

void TableReader::check_keys(const std::vector<std::string>& valid, std::string_view section) const {
  // Report the unknown key that comes first in the file (the table is sorted by name).
  const toml::key* first = nullptr;
  for (const auto& [key, node] : table_) {
    if (std::find(valid.begin(), valid.end(), key.str()) != valid.end()) continue;
    if (!first || key.source().begin < first->source().begin) first = &key;
  }
  if (!first) return;
  const std::string name(first->str());
  std::string message = "unknown key '" + name + "'.";
  const std::string elsewhere = schema::section_of(name, section);
  if (!elsewhere.empty())
    message += " '" + name + "' belongs in " + elsewhere + ".";
  else
    message += did_you_mean(name, valid);
  message += " Valid keys here: " + quoted_list(valid);
  SourceLocation location{context_.file, line(), key_path(name)};
  if (first->source().begin.line > 0) location.line = static_cast<int>(first->source().begin.line);
  throw InputError(location, message);
}

void TableReader::check_keys(const schema::Table& table) const {
  check_keys(table.names(), table.section);
  schema_ = &table;
  for (const auto& key : table.keys)
    if (const toml::node* node = find(key.name)) check_value(key, *node);
}

void TableReader::check_value(const schema::Key& key, const toml::node& node) const {
  using schema::Type;
  const std::string found = ", found " + describe_node(node);
  switch (key.type) {
    case Type::number:
    case Type::integer: {
      const double value = key.type == Type::integer ? read_integer(node, where(key.name), context_)
                                                     : read_number(node, where(key.name), context_);
      if (key.range && !key.range->contains(value))
        fail(key.name, "'" + key.name + "' (" + key.meaning + ") must " + key.range->condition(key.name) +
                           ", found " + format_number(value) + (key.range_hint.empty() ? "" : "; " + key.range_hint));
      return;
    }
    case Type::boolean:
      if (!node.is_boolean()) fail(key.name, "must be true or false" + found);
      return;
    case Type::string:
    case Type::name:
      if (!node.is_string()) fail(key.name, "must be a string in quotes" + found);
      if (key.type == Type::name)
        if (const std::string problem = name_problem(*node.value<std::string>()); !problem.empty())
          fail(key.name, problem);
      return;
    case Type::strings:
      if (!node.is_string() && !(node.is_array() && !node.as_array()->empty() &&
                                 node.as_array()->is_homogeneous(toml::node_type::string)))
        fail(key.name, "must be a string in quotes or a list of strings [\"a\", \"b\"]" + found);
      return;
    case Type::choice:
      (void)choice(key.name, key.choices, std::nullopt);  // present: checked as the readers read it
      return;
    case Type::point:
      if (!node.is_string() && !node.is_array())
        fail(key.name, "must be a vertex name in quotes or a point " + context_.point_form() + found);
      return;
    case Type::points:
      if (!node.is_array()) fail(key.name, "must be a list of points or numbers in brackets [...]" + found);
      return;
    case Type::field:
      if (!node.is_number() && !node.is_string() && !node.is_table())
        fail(key.name, "must be a number, an expression in quotes or a table of values { table = [...], along = "
                       "\"x\" }" + found);
      return;
    case Type::amplitude:
      if (!node.is_array() && !node.is_table())
        fail(key.name, "must be a table of points [[t, value], ...] or a cyclic amplitude { mean, amplitude, "
                       "cycles, start, period }" + found);
      return;
    case Type::table:
      if (!node.is_table()) fail(key.name, "must be a table ([" + key_path(key.name) + "])" + found);
      return;
    case Type::tables:
      if (!node.is_array_of_tables())
        fail(key.name, "must be tables: write [[" + key_path(key.name) + "]] with double brackets, one table per "
                       "entry" + found);
      return;
    case Type::table_or_tables:
    case Type::grid:
      if (!node.is_table() && !node.is_array_of_tables())
        fail(key.name, "must be a table or a list of tables" + found);
      return;
  }
}

std::string TableReader::choice(std::string_view key) const {
  if (!schema_) throw std::logic_error("TableReader::choice: check_keys(table) first");
  const schema::Key& entry = schema_->key(key);
  if (entry.default_value.empty()) return choice(key, entry.choices, std::nullopt);
  if (std::find(entry.choices.begin(), entry.choices.end(), entry.default_value) == entry.choices.end())
    throw std::logic_error("TableReader::choice: the default of '" + entry.name + "' depends on other keys");
  return choice(key, entry.choices, entry.default_value);
}

const toml::node* TableReader::find(std::string_view key) const { return table_.get(key); }

const toml::node& TableReader::require(std::string_view key, std::string_view what) const {
  const toml::node* node = find(key);
  if (!node)
    fail(key, "missing required key '" + std::string(key) + "'" +
                  (path_.empty() ? std::string() : " in " + path_) + ": " + std::string(what));
  return *node;
}

double TableReader::number(std::string_view key) const {
  return read_number(require(key, "a number"), where(key), context_);
}

std::optional<double> TableReader::optional_number(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  return read_number(*node, where(key), context_);
}

int TableReader::integer_or(std::string_view key, int fallback) const {
  const toml::node* node = find(key);
  return node ? read_integer(*node, where(key), context_) : fallback;
}

bool TableReader::boolean_or(std::string_view key, bool fallback) const {
  const toml::node* node = find(key);
  if (!node) return fallback;
  if (const auto value = node->value_exact<bool>()) return *value;
  fail(key, "must be true or false, found " + describe_node(*node));
}

std::optional<std::string> TableReader::optional_string(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  if (const auto value = node->value_exact<std::string>()) return *value;
  fail(key, "must be a string in quotes, found " + describe_node(*node));
}

std::optional<std::string> TableReader::optional_name(std::string_view key) const {
  auto name = optional_string(key);
  if (name)
    if (const std::string problem = name_problem(*name); !problem.empty()) fail(key, problem);
  return name;
}

namespace {

// Characters of UTF-8 text: every byte but the continuation bytes 10xxxxxx.
std::size_t utf8_length(std::string_view text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

}  // namespace

std::string name_problem(std::string_view name) {
  if (name.empty()) return "the name must not be empty";
  const std::size_t length = utf8_length(name);
  if (length > max_name_characters) {
    std::string start(name.substr(0, 40));
    while (!start.empty() && (static_cast<unsigned char>(start.back()) & 0xC0) == 0x80) start.pop_back();
    return "the name '" + start + "...' is " + std::to_string(length) + " characters long, over the limit of " +
           std::to_string(max_name_characters) + " (names become parts of output file names)";
  }
  for (const char c : name)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
      return "the name holds a control character (code " + std::to_string(static_cast<unsigned char>(c)) +
             "); names are printed in messages and written to CSV files and file names";
  return {};
}

std::string TableReader::choice(std::string_view key, const std::vector<std::string>& choices,
                                std::optional<std::string> fallback) const {
  const toml::node* node = find(key);
  if (!node) {
    if (fallback) return *fallback;
    fail(key, "missing required key '" + std::string(key) + "'" +
                  (path_.empty() ? std::string() : " in " + path_) + "; valid values: " +
                  quoted_list(choices));
  }
  const auto value = node->value_exact<std::string>();
  if (!value)
    fail(key, "must be one of " + quoted_list(choices) + " (in quotes), found " + describe_node(*node));
  if (std::find(choices.begin(), choices.end(), *value) == choices.end())
    fail(key, "invalid value '" + *value + "'." + did_you_mean(*value, choices) +
                  " Valid values: " + quoted_list(choices));
  return *value;
}

const toml::table* TableReader::optional_table(std::string_view key, std::string_view header) const {
  const toml::node* node = find(key);
  if (!node) return nullptr;
  if (const toml::table* table = node->as_table()) return table;
  fail(key, "must be a table (" + std::string(header) + "), found " + describe_node(*node));
}

toml::table parse_toml_text(std::string_view text, const std::string& file_name) {
  try {
    return toml::parse(text, std::string_view(file_name));
  } catch (const toml::parse_error& error) {
    const auto& begin = error.source().begin;
    std::string message = "TOML syntax error at column " + std::to_string(begin.column) + ": " +
                          std::string(error.description());
    // A bare word where a value goes: most often a parameter name or an expression unquoted.
    if (message.find("could not determine value type") != std::string::npos)
      message += " (a value is a number, true/false, a \"quoted string\", [a, list] or a {table}; a parameter "
                 "name or an expression goes in quotes: E = \"E_steel\", elements = \"2*n\")";
    throw InputError(SourceLocation{file_name, static_cast<int>(begin.line), ""}, message);
  }
}

}  // namespace bemcontact::io

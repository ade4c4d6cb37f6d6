#pragma once
// The keys of every table of a problem file, as data: name, type, allowed values or range,
// default and a one-line meaning. The readers check each table against it (unknown keys
// with "did you mean", a key of another table, types, choices, ranges: TableReader::
// check_keys) and take their choices from it; `bemcontact keys` prints it and the key
// tables of docs/ are generated from it (test SchemaDocs.*).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bemcontact::io::schema {

// What a key holds. number / integer: a number or an expression of parameters in quotes;
// field: a number, an expression of the position in quotes, or a { table, along } table;
// point: a vertex name or [x, y]; amplitude: [[t, value], ...] or a cyclic table.
enum class Type { number, integer, boolean, string, strings, name, choice, point, points, field, amplitude, table, tables,
                  table_or_tables, grid };

// An interval of valid numbers; an open end excludes its value.
struct Range {
  std::optional<double> min, max;
  bool min_open = false, max_open = false;
  bool contains(double value) const;
  std::string text() const;  // ">= 1", "> 0", "in (-1, 0.5)", "in [1e-14, 0.01]"
  // "be >= 1", "satisfy -1 < nu < 0.5": what a value of `name` must do.
  std::string condition(std::string_view name) const;
};

struct Key {
  std::string name;
  Type type = Type::number;
  std::string default_value;  // as the docs show it: "required", "`\"linear\"`", "1", ...
  std::string meaning;        // one line
  std::vector<std::string> choices;  // Type::choice
  std::optional<Range> range;        // Type::number / integer
  std::string range_hint;            // appended to an out-of-range message
};

struct Table {
  std::string id;       // "material", "contact.solver", ...
  std::string title;    // as a heading shows it: "[material]", "[[boundary]]"
  std::string section;  // in messages: "the [material] table"
  std::vector<Key> keys;

  std::vector<std::string> names() const;
  const Key* find(std::string_view name) const;
  const Key& key(std::string_view name) const;  // std::logic_error when absent (a reader's bug)
};

// Every table, in the order of docs/keys.md.
const std::vector<Table>& tables();
// One table by id; std::logic_error for an unknown id.
const Table& table(std::string_view id);

// The value column of a key's docs row: "number > 0", "`\"line\"` or `\"arc\"`", ...
std::string type_text(const Key& key);
// The markdown table of `table` (| key | value | default | meaning |), no trailing newline.
std::string markdown(const Table& table);
// docs/keys.md: every table with its heading and where it stands.
std::string reference_markdown();
// `text` (a docs page) with each block between "<!-- keys: ID -->" and "<!-- end keys -->"
// replaced by markdown(table(ID)); std::invalid_argument for an unknown ID or an unclosed
// block.
std::string with_key_tables(const std::string& text);

// "the [material] table" when `key` is a key of a table a user could confuse with
// `section`'s and not of `section`'s own, else "".
std::string section_of(std::string_view key, std::string_view section);

}  // namespace bemcontact::io::schema

#include "bemcontact/io/input/probe_input.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "bemcontact/core/error.hpp"

namespace bemcontact::io {

namespace {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

// The whole field as a finite number, or nothing.
std::optional<double> finite_number(std::string_view field) {
  field = trimmed(field);
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error != std::errc() || end != field.data() + field.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

// Fields separated by commas, or by spaces and tabs when the line has no comma.
std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  if (line.find(',') != std::string_view::npos) {
    std::size_t start = 0;
    for (std::size_t at = line.find(','); ; at = line.find(',', start)) {
      fields.emplace_back(trimmed(line.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start)));
      if (at == std::string_view::npos) break;
      start = at + 1;
    }
    return fields;
  }
  std::size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && std::isspace(static_cast<unsigned char>(line[k]))) ++k;
    const std::size_t start = k;
    while (k < line.size() && !std::isspace(static_cast<unsigned char>(line[k]))) ++k;
    if (k > start) fields.emplace_back(line.substr(start, k - start));
  }
  return fields;
}

// A header name without quotes, in lower case.
std::string column_name(std::string_view field) {
  field = trimmed(field);
  if (field.size() >= 2 && field.front() == '"' && field.back() == '"') field = field.substr(1, field.size() - 2);
  std::string name(field);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  return name;
}

std::string joined(const std::vector<std::string>& fields) {
  std::string text;
  for (const auto& f : fields) text += (text.empty() ? "" : ",") + f;
  return text;
}

// The columns of x and y that a header names.
std::array<std::size_t, 2> coordinate_columns(const std::vector<std::string>& header, const SourceLocation& where) {
  if (header.size() == 2) return {0, 1};
  std::vector<std::string> names;
  for (const auto& field : header) names.push_back(column_name(field));
  // ParaView's CSV export names the coordinates Points:0, Points:1, Points:2.
  for (const auto& [first, second] : {std::pair{"x", "y"}, std::pair{"r", "z"}, std::pair{"points:0", "points:1"}}) {
    const auto x = std::find(names.begin(), names.end(), first), y = std::find(names.begin(), names.end(), second);
    if (x != names.end() && y != names.end())
      return {static_cast<std::size_t>(x - names.begin()), static_cast<std::size_t>(y - names.begin())};
  }
  throw InputError(where, "the header '" + joined(header) +
                              "' names no columns x and y (or r and z, Points:0 and Points:1); write x,y as the first line, or no "
                              "header");
}

// A header holds no number (a data line with a typo is an error, not a header).
bool is_header(const std::vector<std::string>& fields) {
  return std::none_of(fields.begin(), fields.end(), [](const std::string& f) { return finite_number(f).has_value(); });
}

}  // namespace

std::vector<ListedPoint> parse_points_file(std::string_view text, const std::string& file_name,
                                           std::size_t max_points) {
  std::vector<ListedPoint> points;
  std::optional<std::array<std::size_t, 2>> columns;
  std::size_t width = 2;
  int line_number = 0;
  for (std::size_t start = 0; start <= text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trimmed(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    const SourceLocation where{file_name, line_number, ""};
    const auto fields = split_fields(line);
    if (!columns && is_header(fields)) {
      columns = coordinate_columns(fields, where);
      width = fields.size();
      continue;
    }
    if (!columns) columns = std::array<std::size_t, 2>{0, 1};
    if (points.size() >= max_points)
      throw InputError(where, "more than " + std::to_string(max_points) + " points, the most this file may hold");
    if (fields.size() != width)
      throw InputError(where, "'" + std::string(line) + "' has " + std::to_string(fields.size()) + " values; " +
                                  std::to_string(width) + " expected (x,y per line" +
                                  (width == 2 ? std::string(")") : std::string(", as the header's columns)")));
    Vec2 position;
    for (int c = 0; c < 2; ++c) {
      const std::string& field = fields[(*columns)[c]];
      const auto value = finite_number(field);
      if (!value) throw InputError(where, std::string(c == 0 ? "x" : "y") + " = '" + field + "' is not a finite number");
      position[c] = *value;
    }
    points.push_back({position, line_number});
  }
  if (points.empty()) throw InputError(SourceLocation{file_name, 0, ""}, "the file holds no point (x,y per line)");
  return points;
}

ProbeLine parse_probe_line(const std::string& specification) {
  const SourceLocation where{"command line", 0, "--line " + specification};
  const auto fields = split_fields(specification);
  if (fields.size() != 5)
    throw InputError(where, "a line is x0,y0,x1,y1,n (its ends and the number of points, ends included); found " +
                                std::to_string(fields.size()) + " values");
  std::array<double, 4> ends{};
  for (int k = 0; k < 4; ++k) {
    const auto value = finite_number(fields[k]);
    if (!value) throw InputError(where, "'" + fields[k] + "' is not a finite number");
    ends[k] = *value;
  }
  const auto count = finite_number(fields[4]);
  if (!count || *count != std::floor(*count) || *count < 2 || *count > 1e9)
    throw InputError(where, "n = '" + fields[4] + "' must be a whole number of points from 2 to 10^9 (ends included)");
  ProbeLine line{Vec2(ends[0], ends[1]), Vec2(ends[2], ends[3]), static_cast<int>(*count)};
  if (line.start == line.end) throw InputError(where, "the line's two ends are the same point");
  return line;
}

std::vector<Vec2> line_points(const ProbeLine& line) {
  std::vector<Vec2> points;
  for (int k = 0; k < line.count; ++k) {
    const double f = static_cast<double>(k) / (line.count - 1);
    // The ends exactly as given (a point on a boundary stays on it).
    points.push_back(k == line.count - 1 ? line.end : line.start + f * (line.end - line.start));
  }
  return points;
}

namespace {

// Calls row(v, line) with the first N numbers of each data line of a CSV file of bemcontact
// that starts with `header` (`what` names the file's kind in the message when it does not);
// the first column must count the rows from 0 (`item` names them).
template <std::size_t N, class Row>
void for_each_stored_row(std::string_view text, const std::string& file_name, std::string_view header,
                         const std::string& what, const std::string& item, Row&& row) {
  if (text.substr(0, header.size()) != header)
    throw InputError(SourceLocation{file_name, 1, ""},
                     "not a " + what + " of bemcontact: the header is not '" + std::string(header) + ",...'");
  int line_number = 1;
  std::size_t count = 0;
  std::size_t start = text.find('\n');
  start = start == std::string_view::npos ? text.size() : start + 1;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (trimmed(line).empty()) continue;
    std::array<double, N> v{};
    std::size_t at = 0;
    for (std::size_t c = 0; c < N; ++c) {
      const std::size_t comma = line.find(',', at);
      const auto value = finite_number(line.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at));
      if (!value || (comma == std::string_view::npos && c + 1 < N))
        throw InputError(SourceLocation{file_name, line_number, ""},
                         "column " + std::to_string(c + 1) + " of '" + std::string(line.substr(0, 80)) +
                             "' is not a finite number (the file is damaged)");
      v[c] = *value;
      at = comma + 1;
    }
    if (v[0] != static_cast<double>(count))
      throw InputError(SourceLocation{file_name, line_number, ""},
                       item + " " + std::to_string(count) + " expected (the file is damaged)");
    ++count;
    row(v);
  }
}

}  // namespace

StoredBoundary parse_boundary_csv(std::string_view text, const std::string& file_name) {
  StoredBoundary stored;
  for_each_stored_row<13>(text, file_name, "node,x,y,nx,ny,u1,u2,t1,t2,s11,s22,s12,s33", "boundary file", "node",
                          [&](const auto& v) {
                            stored.positions.emplace_back(v[1], v[2]);
                            stored.solution.displacement.emplace_back(v[5], v[6]);
                            stored.solution.traction.emplace_back(v[7], v[8]);
                            stored.solution.stress.push_back({v[9], v[10], v[11], v[12]});
                          });
  return stored;
}

StoredCells parse_cells_csv(std::string_view text, const std::string& file_name) {
  StoredCells stored;
  for_each_stored_row<9>(text, file_name, "cell,x,y,area,equivalent_plastic_strain,ep11,ep22,ep33,ep12",
                         "cells file", "cell", [&](const auto& v) {
                           stored.centroids.emplace_back(v[1], v[2]);
                           stored.plastic_strains.push_back(plasticity::mandel(v[5], v[6], v[7], v[8]));
                         });
  return stored;
}

}  // namespace bemcontact::io

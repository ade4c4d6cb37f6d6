#include "bemcontact/io/output/probe_writer.hpp"

#include "bemcontact/io/output/results_writer.hpp"

namespace bemcontact::io {

namespace {

// The polylines of the --line rows: consecutive rows of one line whose points follow each
// other (or are the same point, on an interface); a point outside every body breaks it.
std::vector<std::vector<Index>> line_cells(const std::vector<ProbeRow>& rows) {
  std::vector<std::vector<Index>> cells;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    if (row.line == 0) continue;
    const bool continues = i > 0 && rows[i - 1].line == row.line && row.point - rows[i - 1].point <= 1;
    if (!continues) cells.emplace_back();
    cells.back().push_back(static_cast<Index>(i));
  }
  std::erase_if(cells, [](const std::vector<Index>& cell) { return cell.size() < 2; });
  return cells;
}

}  // namespace

CsvTable probe_table(const std::vector<ProbeRow>& rows, const std::vector<std::string>& body_names) {
  constexpr auto integer = CsvTable::integer;
  CsvTable table({{"point", integer}, {"line", integer}, {"distance"}, {"x"}, {"y"}, {"body", CsvTable::text},
                  {"on_boundary", integer}, {"u1"}, {"u2"}, {"s11"}, {"s22"}, {"s12"}, {"s33"}, {"von_mises"}, {"s1"},
                  {"s2"}, {"s3"}});
  table.reserve(rows.size());
  for (const auto& row : rows) {
    const auto& v = row.value;
    const auto& s = v.stress;
    const auto principal = s.principal();
    table.row() << static_cast<double>(row.point) << row.line << row.distance << row.position.x() << row.position.y()
                << body_names.at(row.body) << (v.on_boundary ? 1 : 0) << v.displacement.x() << v.displacement.y()
                << s.s11 << s.s22 << s.s12 << s.s33 << s.von_mises() << principal[0] << principal[1] << principal[2];
  }
  return table;
}

std::string probe_csv(const std::vector<ProbeRow>& rows, const std::vector<std::string>& body_names) {
  return csv_text(probe_table(rows, body_names));
}

std::string probe_vtk(const std::vector<ProbeRow>& rows, const std::vector<std::string>& body_names,
                      std::string_view title) {
  std::vector<Vec2> points, displacement;
  std::vector<bem::StressTensor> stress;
  std::vector<double> s1, s2, s3, distance, line, on_boundary, body;
  for (const auto& row : rows) {
    points.push_back(row.position);
    displacement.push_back(row.value.displacement);
    stress.push_back(row.value.stress);
    const auto principal = row.value.stress.principal();
    s1.push_back(principal[0]);
    s2.push_back(principal[1]);
    s3.push_back(principal[2]);
    distance.push_back(row.distance);
    line.push_back(row.line);
    on_boundary.push_back(row.value.on_boundary ? 1.0 : 0.0);
    body.push_back(row.body);
  }
  return polyline_vtk(title, points, line_cells(rows), displacement, stress,
                      {{"s1", s1}, {"s2", s2}, {"s3", s3}, {"distance", distance}, {"line", line},
                       {"on_boundary", on_boundary}, {"body", body}},
                      {"body_names", body_names});
}

}  // namespace bemcontact::io

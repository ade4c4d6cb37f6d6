#include "bemcontact/io/output/probe_writer.hpp"

#include "bemcontact/io/output/results_writer.hpp"
#include "bemcontact/io/text_format.hpp"

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

std::string probe_csv(const std::vector<ProbeRow>& rows, const std::vector<std::string>& body_names) {
  std::string out = "point,line,distance,x,y,body,on_boundary,u1,u2,s11,s22,s12,s33,von_mises,s1,s2,s3\n";
  for (const auto& row : rows) {
    const auto& v = row.value;
    const auto& s = v.stress;
    const auto principal = s.principal();
    out += std::to_string(row.point) + "," + std::to_string(row.line) + "," + format_number(row.distance) + "," +
           format_number(row.position.x()) + "," + format_number(row.position.y()) + "," + csv_field(body_names.at(row.body)) +
           "," + (v.on_boundary ? "1" : "0") + "," + format_number(v.displacement.x()) + "," + format_number(v.displacement.y()) +
           "," + format_number(s.s11) + "," + format_number(s.s22) + "," + format_number(s.s12) + "," + format_number(s.s33) + "," +
           format_number(s.von_mises()) + "," + format_number(principal[0]) + "," + format_number(principal[1]) + "," +
           format_number(principal[2]) + "\n";
  }
  return out;
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

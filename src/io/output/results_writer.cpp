#include "bemcontact/io/output/results_writer.hpp"

#include <algorithm>
#include <map>
#include <cstdio>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/text_format.hpp"

namespace bemcontact::io {

namespace {

// A growing text with the shortest round-trip formatting of doubles.
class Text {
 public:
  Text& operator<<(double value) {
    text_ += format_number(value);
    return *this;
  }
  Text& operator<<(Index value) {
    text_ += std::to_string(value);
    return *this;
  }
  Text& operator<<(int value) {
    text_ += std::to_string(value);
    return *this;
  }
  Text& operator<<(std::string_view value) {
    text_.append(value);
    return *this;
  }
  Text& operator<<(const char* value) {
    text_.append(value);
    return *this;
  }
  Text& operator<<(char value) {
    text_.push_back(value);
    return *this;
  }
  std::string str() && { return std::move(text_); }

 private:
  std::string text_;
};

void require_size(std::size_t found, std::size_t expected, const char* what) {
  if (found != expected)
    throw Error(std::string("results writer: ") + what + " has " + std::to_string(found) +
                " entries, expected " + std::to_string(expected));
}

void check_boundary(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution) {
  const std::size_t nodes = mesh.nodes.size();
  require_size(solution.displacement.size(), nodes, "the boundary displacement");
  require_size(solution.traction.size(), nodes, "the boundary traction");
  require_size(solution.stress.size(), nodes, "the boundary stress");
}

void check_interior(const bem::InteriorSolution& solution) {
  require_size(solution.displacement.size(), solution.points.size(), "the interior displacement");
  require_size(solution.stress.size(), solution.points.size(), "the interior stress");
}

void stress_columns(CsvTable::Row& row, const bem::StressTensor& s) {
  row << s.s11 << s.s22 << s.s12 << s.s33 << s.von_mises();
}

// VTK legacy header: the title line must be one line of at most 255 characters.
void vtk_header(Text& out, std::string_view title) {
  std::string line(title.substr(0, 255));
  std::replace(line.begin(), line.end(), '\n', ' ');
  std::replace(line.begin(), line.end(), '\r', ' ');
  if (line.empty()) line = "bemcontact";
  out << "# vtk DataFile Version 3.0\n" << line << "\nASCII\nDATASET POLYDATA\n";
}

void vtk_points(Text& out, const std::vector<Vec2>& points) {
  out << "POINTS " << static_cast<Index>(points.size()) << " double\n";
  for (const Vec2& p : points) out << p.x() << ' ' << p.y() << " 0\n";
}

void vtk_vectors(Text& out, const char* name, const std::vector<Vec2>& values) {
  out << "VECTORS " << name << " double\n";
  for (const Vec2& v : values) out << v.x() << ' ' << v.y() << " 0\n";
}

template <class Value>
void vtk_scalars(Text& out, const char* name, const char* type, const std::vector<Value>& values) {
  out << "SCALARS " << name << ' ' << type << " 1\nLOOKUP_TABLE default\n";
  for (const Value& v : values) out << v << '\n';
}

// von_mises, s11, s22, s12, s33 as scalars and the full tensor (s33 out of plane).
void vtk_stress(Text& out, const std::vector<bem::StressTensor>& stress) {
  std::vector<double> column(stress.size());
  const auto scalars = [&](const char* name, auto get) {
    std::transform(stress.begin(), stress.end(), column.begin(), get);
    vtk_scalars(out, name, "double", column);
  };
  scalars("von_mises", [](const bem::StressTensor& s) { return s.von_mises(); });
  scalars("s11", [](const bem::StressTensor& s) { return s.s11; });
  scalars("s22", [](const bem::StressTensor& s) { return s.s22; });
  scalars("s12", [](const bem::StressTensor& s) { return s.s12; });
  scalars("s33", [](const bem::StressTensor& s) { return s.s33; });
  out << "TENSORS stress double\n";
  for (const auto& s : stress)
    out << s.s11 << ' ' << s.s12 << " 0\n" << s.s12 << ' ' << s.s22 << " 0\n0 0 " << s.s33 << "\n\n";
}

// Geometry of the boundary lines and the point data every boundary file carries.
// A string as VTK's legacy reader decodes it: bytes outside '!'..'~', '%' and '"' as %XX.
std::string vtk_encoded(std::string_view text) {
  std::string out;
  char hex[4];
  for (const unsigned char c : text) {
    if (c <= ' ' || c > '~' || c == '%' || c == '"') {
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out.empty() ? "%00" : out;
}

// Dataset field data: one string array (names indexed by a cell or point array).
void vtk_string_field(Text& out, const char* name, const std::vector<std::string>& values) {
  out << "FIELD FieldData 1\n" << name << " 1 " << static_cast<Index>(values.size()) << " string\n";
  for (const auto& v : values) out << vtk_encoded(v) << '\n';
}

void vtk_cells(Text& out, const char* keyword, const std::vector<std::vector<Index>>& cells) {
  Index size = 0;
  for (const auto& cell : cells) size += 1 + static_cast<Index>(cell.size());
  out << keyword << ' ' << static_cast<Index>(cells.size()) << ' ' << size << '\n';
  for (const auto& cell : cells) {
    out << static_cast<Index>(cell.size());
    for (const Index node : cell) out << ' ' << node;
    out << '\n';
  }
}

void vtk_boundary_geometry(Text& out, const geometry::BoundaryMesh& mesh) {
  std::vector<Vec2> positions, normals;
  std::vector<int> pieces;
  for (const auto& node : mesh.nodes) {
    positions.push_back(node.position);
    normals.push_back(node.normal);
    pieces.push_back(node.piece);
  }
  vtk_string_field(out, "boundary_names", mesh.piece_names);
  vtk_points(out, positions);
  const auto piece_lines = boundary_piece_lines(mesh);
  std::vector<std::vector<Index>> lines;
  std::vector<int> line_pieces;
  for (const auto& [piece, line] : piece_lines) lines.push_back(line), line_pieces.push_back(piece);
  vtk_cells(out, "LINES", lines);
  out << "CELL_DATA " << static_cast<Index>(lines.size()) << '\n';
  vtk_scalars(out, "boundary", "int", line_pieces);
  out << "POINT_DATA " << static_cast<Index>(mesh.nodes.size()) << '\n';
  vtk_vectors(out, "normal", normals);
  vtk_scalars(out, "piece", "int", pieces);
}

// Appends the nodes of `elements` (indices into the mesh) to `line`, shared nodes once.
void append_nodes(const geometry::BoundaryMesh& mesh, const std::vector<Index>& elements,
                  std::vector<Index>& line) {
  for (const Index e : elements) {
    const auto& element = mesh.elements[e];
    // Along the element: a quadratic element stores start, end, middle.
    const std::array<int, geometry::kMaxElementNodes> order =
        element.node_count == 3 ? std::array<int, 3>{0, 2, 1} : std::array<int, 3>{0, 1, 2};
    for (int k = 0; k < element.node_count; ++k) {
      const Index node = element.nodes[order[k]];
      if (node < 0) continue;
      if (line.empty() || line.back() != node) line.push_back(node);
    }
  }
}

}  // namespace

std::vector<std::vector<Index>> boundary_polylines(const geometry::BoundaryMesh& mesh) {
  // Element order along each contour; without contours, the element order of the mesh.
  std::vector<std::vector<Index>> sequences;
  for (const auto& contour : mesh.contours) {
    std::vector<Index> sequence;
    for (const int piece : contour.pieces)
      if (piece >= 0 && piece < static_cast<int>(mesh.piece_elements.size()))
        sequence.insert(sequence.end(), mesh.piece_elements[piece].begin(),
                        mesh.piece_elements[piece].end());
    if (!sequence.empty()) sequences.push_back(std::move(sequence));
  }
  if (sequences.empty() && !mesh.elements.empty()) {
    sequences.emplace_back(mesh.elements.size());
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) sequences.back()[e] = static_cast<Index>(e);
  }

  const double tolerance = 1e-9 * (mesh.scale > 0.0 ? mesh.scale : 1.0);
  std::vector<std::vector<Index>> lines;
  for (const auto& sequence : sequences) {
    const std::size_t m = sequence.size();
    // joined[i]: element i starts where element i-1 (cyclically) ends.
    std::vector<std::size_t> gaps;
    for (std::size_t i = 0; i < m; ++i) {
      const auto& previous = mesh.elements[sequence[(i + m - 1) % m]];
      const auto& current = mesh.elements[sequence[i]];
      if ((current.start - previous.end).norm() > tolerance) gaps.push_back(i);
    }
    if (gaps.empty()) {
      std::vector<Index> line;
      append_nodes(mesh, sequence, line);
      if (line.size() > 1 && line.front() == line.back()) line.pop_back();
      if (line.size() > 1) line.push_back(line.front());  // closed
      lines.push_back(std::move(line));
      continue;
    }
    // Open runs between gaps, starting at the first gap so no run wraps around.
    for (std::size_t g = 0; g < gaps.size(); ++g) {
      const std::size_t begin = gaps[g];
      const std::size_t end = g + 1 < gaps.size() ? gaps[g + 1] : gaps[0] + m;
      std::vector<Index> run;
      for (std::size_t i = begin; i < end; ++i) run.push_back(sequence[i % m]);
      std::vector<Index> line;
      append_nodes(mesh, run, line);
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

std::vector<std::pair<int, std::vector<Index>>> boundary_piece_lines(const geometry::BoundaryMesh& mesh) {
  // The piece of each segment between two nodes of one element; a segment that bridges
  // two elements (across a split corner) goes with the element it leads into.
  std::map<std::pair<Index, Index>, int> segment_piece;
  for (const auto& element : mesh.elements) {
    std::vector<Index> along;
    append_nodes(mesh, {&element - mesh.elements.data()}, along);
    for (std::size_t k = 1; k < along.size(); ++k) {
      segment_piece[{along[k - 1], along[k]}] = element.piece;
      segment_piece[{along[k], along[k - 1]}] = element.piece;
    }
  }
  const auto piece_of = [&](Index a, Index b) {
    const auto found = segment_piece.find({a, b});
    return found != segment_piece.end() ? found->second : mesh.nodes[b].piece;
  };
  std::vector<std::pair<int, std::vector<Index>>> out;
  for (const auto& line : boundary_polylines(mesh)) {
    for (std::size_t k = 1; k < line.size(); ++k) {
      const int piece = piece_of(line[k - 1], line[k]);
      if (out.empty() || k == 1 || out.back().first != piece) out.push_back({piece, {line[k - 1]}});
      out.back().second.push_back(line[k]);
    }
  }
  return out;
}

// Quadrilaterals of the [interior] grid whose four corners were computed (inside the body).
std::vector<std::vector<Index>> interior_grid_cells(const bem::InteriorSolution& solution) {
  std::map<std::array<int, 2>, Index> at;  // by (row, column): cells come row by row
  for (std::size_t i = 0; i < solution.grid_index.size(); ++i)
    if (solution.grid_index[i][0] >= 0) at.emplace(std::array<int, 2>{solution.grid_index[i][1], solution.grid_index[i][0]}, static_cast<Index>(i));
  std::vector<std::vector<Index>> cells;
  for (const auto& [row_column, first] : at) {
    const auto corner = [&, rc = row_column](int di, int dj) {
      const auto found = at.find({rc[0] + dj, rc[1] + di});
      return found == at.end() ? Index(-1) : found->second;
    };
    const std::vector<Index> quad{first, corner(1, 0), corner(1, 1), corner(0, 1)};
    if (std::find(quad.begin(), quad.end(), Index(-1)) == quad.end()) cells.push_back(quad);
  }
  return cells;
}

std::string point_cloud_vtk(std::string_view title, const std::vector<Vec2>& points,
                            const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                            const std::vector<std::pair<std::string, std::vector<Vec2>>>& vectors,
                            const std::pair<std::string, std::vector<std::string>>& names) {
  Text out;
  vtk_header(out, title);
  if (!names.first.empty()) vtk_string_field(out, names.first.c_str(), names.second);
  vtk_points(out, points);
  std::vector<std::vector<Index>> vertices;
  for (std::size_t i = 0; i < points.size(); ++i) vertices.push_back({static_cast<Index>(i)});
  vtk_cells(out, "VERTICES", vertices);
  out << "POINT_DATA " << static_cast<Index>(points.size()) << '\n';
  for (const auto& [name, values] : scalars) {
    require_size(values.size(), points.size(), ("point data '" + name + "'").c_str());
    vtk_scalars(out, name.c_str(), "double", values);
  }
  for (const auto& [name, values] : vectors) {
    require_size(values.size(), points.size(), ("point data '" + name + "'").c_str());
    vtk_vectors(out, name.c_str(), values);
  }
  return std::move(out).str();
}

std::string polyline_vtk(std::string_view title, const std::vector<Vec2>& points,
                         const std::vector<std::vector<Index>>& lines, const std::vector<Vec2>& displacement,
                         const std::vector<bem::StressTensor>& stress,
                         const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                         const std::pair<std::string, std::vector<std::string>>& names) {
  require_size(displacement.size(), points.size(), "the displacement");
  require_size(stress.size(), points.size(), "the stress");
  Text out;
  vtk_header(out, title);
  if (!names.first.empty()) vtk_string_field(out, names.first.c_str(), names.second);
  vtk_points(out, points);
  std::vector<bool> on_line(points.size(), false);
  for (const auto& line : lines)
    for (const Index i : line) on_line[i] = true;
  std::vector<std::vector<Index>> vertices;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!on_line[i]) vertices.push_back({static_cast<Index>(i)});
  if (!vertices.empty()) vtk_cells(out, "VERTICES", vertices);
  if (!lines.empty()) vtk_cells(out, "LINES", lines);
  out << "POINT_DATA " << static_cast<Index>(points.size()) << '\n';
  vtk_vectors(out, "u", displacement);
  vtk_stress(out, stress);
  for (const auto& [name, values] : scalars) {
    require_size(values.size(), points.size(), ("point data '" + name + "'").c_str());
    vtk_scalars(out, name.c_str(), "double", values);
  }
  return std::move(out).str();
}

CsvTable boundary_table(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution) {
  check_boundary(mesh, solution);
  CsvTable table({{"node", CsvTable::integer}, {"x"}, {"y"}, {"nx"}, {"ny"}, {"u1"}, {"u2"}, {"t1"}, {"t2"},
                  {"s11"}, {"s22"}, {"s12"}, {"s33"}, {"von_mises"}, {"boundary", CsvTable::text}});
  table.reserve(mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const auto& node = mesh.nodes[i];
    const Vec2& u = solution.displacement[i];
    const Vec2& t = solution.traction[i];
    auto row = table.row();
    row << static_cast<double>(i) << node.position.x() << node.position.y() << node.normal.x() << node.normal.y()
        << u.x() << u.y() << t.x() << t.y();
    stress_columns(row, solution.stress[i]);
    const bool named = node.piece >= 0 && static_cast<std::size_t>(node.piece) < mesh.piece_names.size();
    row << (named ? std::string_view(mesh.piece_names[node.piece]) : std::string_view());
  }
  return table;
}

CsvTable interior_table(const bem::InteriorSolution& solution) {
  check_interior(solution);
  CsvTable table({{"point", CsvTable::integer}, {"x"}, {"y"}, {"u1"}, {"u2"}, {"s11"}, {"s22"}, {"s12"}, {"s33"},
                  {"von_mises"}, {"grid_column", CsvTable::integer}, {"grid_row", CsvTable::integer}});
  table.reserve(solution.points.size());
  for (std::size_t i = 0; i < solution.points.size(); ++i) {
    const Vec2& p = solution.points[i];
    const Vec2& u = solution.displacement[i];
    const std::array<int, 2> grid = i < solution.grid_index.size() ? solution.grid_index[i] : std::array<int, 2>{-1, -1};
    auto row = table.row();
    row << static_cast<double>(i) << p.x() << p.y() << u.x() << u.y();
    stress_columns(row, solution.stress[i]);
    row << grid[0] << grid[1];
  }
  return table;
}

CsvTable mesh_nodes_table(const geometry::BoundaryMesh& mesh) {
  CsvTable table({{"node", CsvTable::integer}, {"x"}, {"y"}, {"nx"}, {"ny"}, {"piece", CsvTable::integer},
                  {"shifted", CsvTable::integer}});
  table.reserve(mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const auto& node = mesh.nodes[i];
    table.row() << static_cast<double>(i) << node.position.x() << node.position.y() << node.normal.x()
                << node.normal.y() << node.piece << (node.shifted ? 1 : 0);
  }
  return table;
}

CsvTable mesh_elements_table(const geometry::BoundaryMesh& mesh) {
  CsvTable table({{"element", CsvTable::integer}, {"node0", CsvTable::integer}, {"node1", CsvTable::integer},
                  {"x_start"}, {"y_start"}, {"x_end"}, {"y_end"}, {"nx"}, {"ny"}, {"piece", CsvTable::integer},
                  {"node_middle", CsvTable::integer}});
  table.reserve(mesh.elements.size());
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const auto& element = mesh.elements[e];
    const Index node1 = element.node_count > 1 ? element.nodes[1] : Index{-1};
    const Index middle = element.node_count > 2 ? element.nodes[2] : Index{-1};
    table.row() << static_cast<double>(e) << element.nodes[0] << node1 << element.start.x() << element.start.y()
                << element.end.x() << element.end.y() << element.normal.x() << element.normal.y() << element.piece
                << middle;
  }
  return table;
}

std::string boundary_csv(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution) {
  return csv_text(boundary_table(mesh, solution));
}

std::string interior_csv(const bem::InteriorSolution& solution) { return csv_text(interior_table(solution)); }

std::string mesh_nodes_csv(const geometry::BoundaryMesh& mesh) { return csv_text(mesh_nodes_table(mesh)); }

std::string mesh_elements_csv(const geometry::BoundaryMesh& mesh) { return csv_text(mesh_elements_table(mesh)); }

std::string boundary_vtk(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution,
                         std::string_view title) {
  check_boundary(mesh, solution);
  Text out;
  vtk_header(out, title);
  vtk_boundary_geometry(out, mesh);
  vtk_vectors(out, "u", solution.displacement);
  vtk_vectors(out, "t", solution.traction);
  vtk_stress(out, solution.stress);
  return std::move(out).str();
}

std::string mesh_vtk(const geometry::BoundaryMesh& mesh, std::string_view title) {
  Text out;
  vtk_header(out, title);
  vtk_boundary_geometry(out, mesh);
  return std::move(out).str();
}

std::string polygons_vtk(std::string_view title, const std::vector<std::vector<Vec2>>& polygons,
                         const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                         const std::vector<bem::StressTensor>& stress) {
  Text out;
  vtk_header(out, title);
  std::vector<Vec2> points;
  std::vector<std::vector<Index>> cells;
  for (const auto& polygon : polygons) {
    cells.emplace_back();
    for (const Vec2& p : polygon) {
      cells.back().push_back(static_cast<Index>(points.size()));
      points.push_back(p);
    }
  }
  vtk_points(out, points);
  vtk_cells(out, "POLYGONS", cells);
  out << "CELL_DATA " << static_cast<Index>(polygons.size()) << '\n';
  for (const auto& [name, values] : scalars) {
    require_size(values.size(), polygons.size(), "a polygon scalar");
    vtk_scalars(out, name.c_str(), "double", values);
  }
  require_size(stress.size(), polygons.size(), "the polygons' stress");
  vtk_stress(out, stress);
  return std::move(out).str();
}

std::string interior_vtk(const bem::InteriorSolution& solution, std::string_view title) {
  check_interior(solution);
  Text out;
  vtk_header(out, title);
  vtk_points(out, solution.points);
  const Index n = static_cast<Index>(solution.points.size());
  // The grid's cells where all four corners are inside; the other points as vertices.
  const auto cells = interior_grid_cells(solution);
  std::vector<bool> in_cell(solution.points.size(), false);
  for (const auto& cell : cells)
    for (const Index i : cell) in_cell[i] = true;
  std::vector<std::vector<Index>> vertices;
  for (Index i = 0; i < n; ++i)
    if (!in_cell[i]) vertices.push_back({i});
  if (!vertices.empty()) vtk_cells(out, "VERTICES", vertices);
  if (!cells.empty()) vtk_cells(out, "POLYGONS", cells);
  out << "POINT_DATA " << n << '\n';
  vtk_vectors(out, "u", solution.displacement);
  vtk_stress(out, solution.stress);
  return std::move(out).str();
}

namespace {

void vtp_array(Text& out, const char* name, int components, const std::vector<double>& values) {
  out << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"" << components
      << "\" format=\"ascii\">\n";
  for (const double v : values) out << v << ' ';
  out << "\n</DataArray>\n";
}

std::vector<double> vectors3(const std::vector<Vec2>& values) {
  std::vector<double> out;
  for (const Vec2& v : values) out.insert(out.end(), {v.x(), v.y(), 0.0});
  return out;
}

}  // namespace

std::string boundary_vtp(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution) {
  check_boundary(mesh, solution);
  std::vector<std::vector<Index>> lines;
  std::vector<double> line_pieces;
  for (const auto& [piece, line] : boundary_piece_lines(mesh)) lines.push_back(line), line_pieces.push_back(piece);
  std::vector<Vec2> positions, normals;
  for (const auto& node : mesh.nodes) positions.push_back(node.position), normals.push_back(node.normal);
  Text out;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << static_cast<Index>(mesh.nodes.size()) << "\" NumberOfVerts=\"0\" NumberOfLines=\""
      << static_cast<Index>(lines.size()) << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n";
  vtp_array(out, "points", 3, vectors3(positions));
  out << "</Points>\n<Lines>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  Index offset = 0;
  std::string offsets;
  for (const auto& line : lines) {
    for (const Index node : line) out << node << ' ';
    offset += static_cast<Index>(line.size());
    offsets += std::to_string(offset) + " ";
  }
  out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n" << offsets
      << "\n</DataArray>\n</Lines>\n<CellData Scalars=\"boundary\">\n";
  vtp_array(out, "boundary", 1, line_pieces);
  out << "</CellData>\n<PointData Vectors=\"u\">\n";
  vtp_array(out, "normal", 3, vectors3(normals));
  vtp_array(out, "u", 3, vectors3(solution.displacement));
  vtp_array(out, "t", 3, vectors3(solution.traction));
  std::vector<double> vm, s11, s22, s12, s33;
  for (const auto& s : solution.stress) {
    vm.push_back(s.von_mises());
    s11.push_back(s.s11), s22.push_back(s.s22), s12.push_back(s.s12), s33.push_back(s.s33);
  }
  vtp_array(out, "von_mises", 1, vm);
  vtp_array(out, "s11", 1, s11);
  vtp_array(out, "s22", 1, s22);
  vtp_array(out, "s12", 1, s12);
  vtp_array(out, "s33", 1, s33);
  out << "</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return std::move(out).str();
}

std::string point_cloud_vtp(const std::vector<Vec2>& points,
                            const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                            const std::vector<std::pair<std::string, std::vector<Vec2>>>& vectors) {
  const Index n = static_cast<Index>(points.size());
  Text out;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n";
  vtp_array(out, "points", 3, vectors3(points));
  out << "</Points>\n<Verts>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (Index i = 0; i < n; ++i) out << i << ' ';
  out << "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (Index i = 1; i <= n; ++i) out << i << ' ';
  out << "\n</DataArray>\n</Verts>\n<PointData>\n";
  for (const auto& [name, values] : scalars) {
    require_size(values.size(), points.size(), ("point data '" + name + "'").c_str());
    vtp_array(out, name.c_str(), 1, values);
  }
  for (const auto& [name, values] : vectors) {
    require_size(values.size(), points.size(), ("point data '" + name + "'").c_str());
    vtp_array(out, name.c_str(), 3, vectors3(values));
  }
  out << "</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return std::move(out).str();
}

std::string time_series_pvd(const std::vector<std::pair<double, std::string>>& time_and_file) {
  Text out;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [time, file] : time_and_file)
    out << "<DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  return std::move(out).str();
}

}  // namespace bemcontact::io

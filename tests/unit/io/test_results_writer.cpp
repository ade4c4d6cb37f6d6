// CSV and VTK writers on tiny hand-made meshes and solutions: headers, row counts,
// exact round trip of every value, and the line connectivity of the VTK files.
#include <gtest/gtest.h>

#include <sstream>

#include "bemcontact/core/error.hpp"
#include "bemcontact/io/output/results_writer.hpp"

namespace bemcontact::io {
namespace {

using geometry::BoundaryElement;
using geometry::BoundaryMesh;
using geometry::BoundaryNode;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> numbers_of(const std::string& line, char separator) {
  std::vector<double> values;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, separator);)
    if (!field.empty()) values.push_back(std::stod(field));
  return values;
}

BoundaryElement element(const Vec2& a, const Vec2& b, int piece, std::array<Index, 2> nodes, int count) {
  BoundaryElement e = geometry::straight_element(a, b);
  e.piece = piece;
  e.nodes = {nodes[0], nodes[1], -1};
  e.node_count = count;
  if (count == 1) e.node_fraction = {0.5, 0.5, 0.5};
  else e.node_fraction = {0.0, 1.0, 0.5};
  return e;
}

const std::array<Vec2, 4> corners{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};

// Unit square, one piece per side, linear elements sharing the corner nodes.
BoundaryMesh square_mesh() {
  BoundaryMesh mesh;
  for (int k = 0; k < 4; ++k) {
    mesh.nodes.push_back(BoundaryNode{corners[k], Vec2(1.0 / 3.0, -0.1 * k), k, false});
    mesh.elements.push_back(element(corners[k], corners[(k + 1) % 4], k, {k, (k + 1) % 4}, 2));
    mesh.piece_elements.push_back({k});
  }
  geometry::Contour contour;
  contour.pieces = {0, 1, 2, 3};
  mesh.contours.push_back(contour);
  return mesh;
}

bem::BoundarySolution solution_for(std::size_t nodes) {
  bem::BoundarySolution solution;
  for (std::size_t i = 0; i < nodes; ++i) {
    const double a = static_cast<double>(i) + 1.0 / 3.0;
    solution.displacement.emplace_back(a * 1e-17, -a);
    solution.traction.emplace_back(123456.789 * a, 0.1 * a);
    solution.stress.push_back(bem::StressTensor{a, -2.0 * a, a / 7.0, 0.3 * a});
  }
  return solution;
}

// The block of `count` lines after the line `header` in `lines`.
std::vector<std::string> block_after(const std::vector<std::string>& lines, const std::string& header,
                                     std::size_t count) {
  const auto at = std::find(lines.begin(), lines.end(), header);
  EXPECT_NE(at, lines.end()) << header;
  if (at == lines.end() || static_cast<std::size_t>(lines.end() - at) <= count) return {};
  return std::vector<std::string>(at + 1, at + 1 + static_cast<long>(count));
}

TEST(IoResultsWriter, BoundaryCsvRoundTrips) {
  const BoundaryMesh mesh = square_mesh();
  const bem::BoundarySolution solution = solution_for(mesh.nodes.size());
  BoundaryMesh named = mesh;  // the last column names each node's boundary (CSV-quoted when needed)
  named.piece_names = {"bottom", "right, east", "top", "left"};
  const auto lines = lines_of(boundary_csv(named, solution));
  ASSERT_EQ(lines.size(), 1 + mesh.nodes.size());
  EXPECT_EQ(lines[0], "node,x,y,nx,ny,u1,u2,t1,t2,s11,s22,s12,s33,von_mises,boundary");
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const std::string& name = named.piece_names[mesh.nodes[i].piece];
    const std::string field = name.find(',') != std::string::npos ? "\"" + name + "\"" : name;
    ASSERT_GE(lines[1 + i].size(), field.size());
    EXPECT_EQ(lines[1 + i].substr(lines[1 + i].size() - field.size()), field);
    const auto values = numbers_of(lines[1 + i].substr(0, lines[1 + i].size() - field.size() - 1), ',');
    ASSERT_EQ(values.size(), 14u);
    const auto& s = solution.stress[i];
    const std::vector<double> expected{static_cast<double>(i),
                                       mesh.nodes[i].position.x(), mesh.nodes[i].position.y(),
                                       mesh.nodes[i].normal.x(),   mesh.nodes[i].normal.y(),
                                       solution.displacement[i].x(), solution.displacement[i].y(),
                                       solution.traction[i].x(),   solution.traction[i].y(),
                                       s.s11, s.s22, s.s12, s.s33, s.von_mises()};
    for (std::size_t c = 0; c < expected.size(); ++c) EXPECT_EQ(values[c], expected[c]) << i << "," << c;
  }
}

TEST(IoResultsWriter, InteriorCsvRoundTrips) {
  bem::InteriorSolution interior;
  for (int i = 0; i < 3; ++i) {
    interior.points.emplace_back(0.1 * i, 1.0 / 3.0);
    interior.displacement.emplace_back(1e-7 * i, -2e-7);
    interior.stress.push_back(bem::StressTensor{1.0 * i, 2.0, 0.5, 0.1});
  }
  interior.dropped_points.emplace_back(9.0, 9.0);  // not written
  const auto lines = lines_of(interior_csv(interior));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "point,x,y,u1,u2,s11,s22,s12,s33,von_mises,grid_column,grid_row");
  const auto values = numbers_of(lines[3], ',');
  ASSERT_EQ(values.size(), 12u);
  EXPECT_EQ(values[10], -1.0);  // a listed point: no grid index
  EXPECT_EQ(values[0], 2.0);
  EXPECT_EQ(values[1], 0.1 * 2);
  EXPECT_EQ(values[2], 1.0 / 3.0);
  EXPECT_EQ(values[3], 2e-7);
  EXPECT_EQ(values[9], interior.stress[2].von_mises());
}

TEST(IoResultsWriter, MeshCsvFiles) {
  BoundaryMesh mesh = square_mesh();
  mesh.nodes[2].shifted = true;
  mesh.elements[3].node_count = 1;  // a constant element: node1 = -1
  const auto nodes = lines_of(mesh_nodes_csv(mesh));
  ASSERT_EQ(nodes.size(), 5u);
  EXPECT_EQ(nodes[0], "node,x,y,nx,ny,piece,shifted");
  EXPECT_EQ(nodes[3], "2,1,1,0.3333333333333333,-0.2,2,1");
  const auto elements = lines_of(mesh_elements_csv(mesh));
  ASSERT_EQ(elements.size(), 5u);
  EXPECT_EQ(elements[0], "element,node0,node1,x_start,y_start,x_end,y_end,nx,ny,piece,node_middle");
  EXPECT_EQ(elements[1], "0,0,1,0,0,1,0,0,-1,0,-1");
  EXPECT_EQ(elements[4], "3,3,-1,0,1,0,0,-1,0,3,-1");
}

TEST(IoResultsWriter, BoundaryVtkIsAPolylineWithPointData) {
  const BoundaryMesh mesh = square_mesh();
  const bem::BoundarySolution solution = solution_for(mesh.nodes.size());
  const auto lines = lines_of(boundary_vtk(mesh, solution, "Plate\nin tension"));
  ASSERT_GE(lines.size(), 5u);
  EXPECT_EQ(lines[0], "# vtk DataFile Version 3.0");
  EXPECT_EQ(lines[1], "Plate in tension");  // one title line
  EXPECT_EQ(lines[2], "ASCII");
  EXPECT_EQ(lines[3], "DATASET POLYDATA");
  const auto points = block_after(lines, "POINTS 4 double", 4);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[2], "1 1 0");
  // One line cell per boundary piece along the closed contour, named in the field data.
  EXPECT_EQ(block_after(lines, "LINES 4 12", 4), (std::vector<std::string>{"2 0 1", "2 1 2", "2 2 3", "2 3 0"}));
  EXPECT_EQ(block_after(lines, "SCALARS boundary int 1", 5),
            (std::vector<std::string>{"LOOKUP_TABLE default", "0", "1", "2", "3"}));
  EXPECT_NE(std::find(lines.begin(), lines.end(), "POINT_DATA 4"), lines.end());

  const auto u = block_after(lines, "VECTORS u double", 4);
  const auto t = block_after(lines, "VECTORS t double", 4);
  const auto von_mises = block_after(lines, "SCALARS von_mises double 1", 5);  // + LOOKUP_TABLE
  const auto s12 = block_after(lines, "SCALARS s12 double 1", 5);
  const auto tensor = block_after(lines, "TENSORS stress double", 16);
  ASSERT_EQ(u.size(), 4u);
  ASSERT_EQ(von_mises.size(), 5u);
  EXPECT_EQ(von_mises[0], "LOOKUP_TABLE default");
  for (std::size_t i = 0; i < 4; ++i) {
    const auto ui = numbers_of(u[i], ' ');
    const auto ti = numbers_of(t[i], ' ');
    ASSERT_EQ(ui.size(), 3u);
    EXPECT_EQ(ui[0], solution.displacement[i].x());
    EXPECT_EQ(ui[1], solution.displacement[i].y());
    EXPECT_EQ(ui[2], 0.0);
    EXPECT_EQ(ti[0], solution.traction[i].x());
    EXPECT_EQ(std::stod(von_mises[1 + i]), solution.stress[i].von_mises());
    EXPECT_EQ(std::stod(s12[1 + i]), solution.stress[i].s12);
  }
  // Tensor of node 1: rows (s11 s12 0), (s12 s22 0), (0 0 s33), then a blank line.
  ASSERT_EQ(tensor.size(), 16u);
  const auto& s = solution.stress[1];
  EXPECT_EQ(numbers_of(tensor[4], ' '), (std::vector<double>{s.s11, s.s12, 0.0}));
  EXPECT_EQ(numbers_of(tensor[5], ' '), (std::vector<double>{s.s12, s.s22, 0.0}));
  EXPECT_EQ(numbers_of(tensor[6], ' '), (std::vector<double>{0.0, 0.0, s.s33}));

  bem::BoundarySolution short_solution = solution;
  short_solution.stress.pop_back();
  EXPECT_THROW(boundary_vtk(mesh, short_solution, "x"), Error);
  EXPECT_THROW(boundary_csv(mesh, short_solution), Error);
}

TEST(IoResultsWriter, PolylinesFollowSplitCornersAndConstantElements) {
  // Triangle with split corners: each element owns two shifted nodes.
  const std::array<Vec2, 3> p{Vec2(0, 0), Vec2(2, 0), Vec2(0, 2)};
  BoundaryMesh split;
  for (int k = 0; k < 3; ++k) {
    const Vec2 a = p[k], b = p[(k + 1) % 3];
    split.nodes.push_back(BoundaryNode{a + 0.2 * (b - a), Vec2(0, 1), k, true});
    split.nodes.push_back(BoundaryNode{a + 0.8 * (b - a), Vec2(0, 1), k, true});
    split.elements.push_back(element(a, b, k, {2 * k, 2 * k + 1}, 2));
    split.piece_elements.push_back({k});
  }
  split.contours.push_back(geometry::Contour{{0, 1, 2}, 2.0, false});
  EXPECT_EQ(boundary_polylines(split), (std::vector<std::vector<Index>>{{0, 1, 2, 3, 4, 5, 0}}));

  // Constant elements: one node in the middle of each element.
  BoundaryMesh constant;
  for (int k = 0; k < 4; ++k) {
    constant.nodes.push_back(BoundaryNode{0.5 * (corners[k] + corners[(k + 1) % 4]), Vec2(0, 1), k, false});
    constant.elements.push_back(element(corners[k], corners[(k + 1) % 4], k, {k, -1}, 1));
  }
  // No contour information: the element order of the mesh is used.
  EXPECT_EQ(boundary_polylines(constant), (std::vector<std::vector<Index>>{{0, 1, 2, 3, 0}}));
  const auto lines = lines_of(mesh_vtk(constant, "constant"));
  // Segments between the middles of two elements go with the element they lead into.
  EXPECT_EQ(block_after(lines, "LINES 4 12", 4), (std::vector<std::string>{"2 0 1", "2 1 2", "2 2 3", "2 3 0"}));
  EXPECT_EQ(block_after(lines, "SCALARS boundary int 1", 5),
            (std::vector<std::string>{"LOOKUP_TABLE default", "1", "2", "3", "0"}));
  EXPECT_NE(std::find(lines.begin(), lines.end(), "VECTORS normal double"), lines.end());
}

TEST(IoResultsWriter, PolylineBreaksWhereTheContourHasNoElements) {
  // Axisymmetric body: the piece on the axis (0,1) -> (0,0) has no elements. The contour
  // list starts in the middle of the chain; the line must still be one open run.
  BoundaryMesh mesh;
  for (int k = 0; k < 4; ++k) mesh.nodes.push_back(BoundaryNode{corners[k], Vec2(0, 1), k, false});
  for (int k = 0; k < 3; ++k) {
    mesh.elements.push_back(element(corners[k], corners[k + 1], k, {k, k + 1}, 2));
    mesh.piece_elements.push_back({k});
  }
  mesh.piece_elements.push_back({});  // the axis
  mesh.contours.push_back(geometry::Contour{{2, 3, 0, 1}, 1.0, false});
  EXPECT_EQ(boundary_polylines(mesh), (std::vector<std::vector<Index>>{{0, 1, 2, 3}}));
  const auto lines = lines_of(mesh_vtk(mesh, "axis"));
  EXPECT_EQ(block_after(lines, "LINES 3 9", 3), (std::vector<std::string>{"2 0 1", "2 1 2", "2 2 3"}));
}

TEST(IoResultsWriter, PieceLinesJoinTheElementsOfEachNamedBoundary) {
  // Two pieces of two linear elements each along an open line: nodes 0-1-2 | 2-3-4.
  BoundaryMesh mesh;
  for (int k = 0; k < 5; ++k) mesh.nodes.push_back(BoundaryNode{Vec2(k, 0), Vec2(0, -1), k < 2 ? 0 : 1, false});
  for (int k = 0; k < 4; ++k) mesh.elements.push_back(element(Vec2(k, 0), Vec2(k + 1, 0), k / 2, {k, k + 1}, 2));
  mesh.piece_elements = {{0, 1}, {2, 3}};
  mesh.piece_names = {"floor", "contact zone"};
  mesh.contours.push_back(geometry::Contour{{0, 1}, 1.0, false});
  using Lines = std::vector<std::pair<int, std::vector<Index>>>;
  EXPECT_EQ(boundary_piece_lines(mesh), (Lines{{0, {0, 1, 2}}, {1, {2, 3, 4}}}));
  const auto lines = lines_of(mesh_vtk(mesh, "names"));
  // Legacy VTK strings: a space is written %20 (the reader decodes it).
  EXPECT_EQ(block_after(lines, "boundary_names 1 2 string", 2), (std::vector<std::string>{"floor", "contact%20zone"}));
}

TEST(IoResultsWriter, InteriorVtkDrawsTheGridCellsInsideTheBody) {
  // A 3 x 3 grid whose corner (2, 2) fell outside: three cells of four remain.
  bem::InteriorSolution interior;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i == 2 && j == 2) continue;
      interior.points.emplace_back(i, j);
      interior.grid_index.push_back({i, j});
      interior.displacement.emplace_back(0.0, 0.0);
      interior.stress.push_back(bem::StressTensor{1.0, 0.0, 0.0, 0.0});
    }
  interior.points.emplace_back(0.5, 0.5);  // a listed point
  interior.grid_index.push_back({-1, -1});
  interior.displacement.emplace_back(0.0, 0.0);
  interior.stress.push_back(bem::StressTensor{});
  EXPECT_EQ(interior_grid_cells(interior),
            (std::vector<std::vector<Index>>{{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}}));
  const auto lines = lines_of(interior_vtk(interior, "grid"));
  EXPECT_EQ(block_after(lines, "VERTICES 1 2", 1), (std::vector<std::string>{"1 8"}));
  EXPECT_EQ(block_after(lines, "POLYGONS 3 15", 3), (std::vector<std::string>{"4 0 1 4 3", "4 1 2 5 4", "4 3 4 7 6"}));
}

TEST(IoResultsWriter, InteriorVtkHasOneVertexPerPoint) {
  bem::InteriorSolution interior;
  for (int i = 0; i < 3; ++i) {
    interior.points.emplace_back(0.25 * i, 0.5);
    interior.displacement.emplace_back(0.1 * i, 0.2);
    interior.stress.push_back(bem::StressTensor{1.0, 2.0, 3.0 * i, 4.0});
  }
  const auto lines = lines_of(interior_vtk(interior, "interior"));
  EXPECT_EQ(lines[3], "DATASET POLYDATA");
  EXPECT_EQ(block_after(lines, "POINTS 3 double", 3),
            (std::vector<std::string>{"0 0.5 0", "0.25 0.5 0", "0.5 0.5 0"}));
  EXPECT_EQ(block_after(lines, "VERTICES 3 6", 3), (std::vector<std::string>{"1 0", "1 1", "1 2"}));
  EXPECT_NE(std::find(lines.begin(), lines.end(), "POINT_DATA 3"), lines.end());
  const auto u = block_after(lines, "VECTORS u double", 3);
  ASSERT_EQ(u.size(), 3u);
  EXPECT_EQ(numbers_of(u[1], ' '), (std::vector<double>{0.1, 0.2, 0.0}));
  const auto von_mises = block_after(lines, "SCALARS von_mises double 1", 4);
  ASSERT_EQ(von_mises.size(), 4u);
  EXPECT_EQ(std::stod(von_mises[3]), interior.stress[2].von_mises());
}

}  // namespace
}  // namespace bemcontact::io

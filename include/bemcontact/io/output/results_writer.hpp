#pragma once
// Writers of the results: each returns the content of one file as a string, so that
// they are tested without touching the disk and OutputDirectory can write all files or
// none. Numbers are written with the shortest text that reads back as the same double.
//
// CSV files (header line, comma separated, one row per node, element or point):
//   boundary.csv       node,x,y,nx,ny,u1,u2,t1,t2,s11,s22,s12,s33,von_mises,boundary (its name)
//   interior.csv       point,x,y,u1,u2,s11,s22,s12,s33,von_mises,grid_column,grid_row (-1: listed)
//   mesh_nodes.csv     node,x,y,nx,ny,piece,shifted
//   mesh_elements.csv  element,node0,node1,x_start,y_start,x_end,y_end,nx,ny,piece,node_middle
// (node1 = -1 for constant elements, node_middle = -1 but for quadratic ones; indices start
// at 0; components 1, 2 are x, y or r, z.)
//
// VTK files (legacy ASCII, version 3.0, POLYDATA; z = 0):
//   boundary.vtk  the boundary nodes as points, joined by lines in element order along
//                 each contour, one line cell per boundary piece with cell data
//                 `boundary` (its index into the field-data string array
//                 `boundary_names`), and point data u, t, normal (vectors), von_mises, s11,
//                 s22, s12, s33 (scalars), stress (tensor) and piece. Nodes are not always
//                 at element ends (split corner nodes sit inside their elements, constant
//                 elements have their node at the middle), so the drawn line joins the
//                 nodes and cuts corners slightly; a contour is broken where the mesh is
//                 (e.g. at the axis of an axisymmetric body, which carries no elements).
//   mesh.vtk      the same lines with normal and piece only (`bemcontact mesh`).
//   interior.vtk  the interior points with u, von_mises, s11..s33, stress; the points of an
//                 [interior] grid joined by its quadrilateral cells where all four corners
//                 are inside the body (a hole or notch stays empty instead of being
//                 bridged), the other points (listed ones) as vertices.
#include <string>
#include <utility>
#include <string_view>
#include <vector>

#include "bemcontact/bem/solution.hpp"
#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/io/output/csv_table.hpp"

namespace bemcontact::io {

// Each CSV file as a table (io/output/csv_table.hpp), and as its text (csv_text of the table).
CsvTable boundary_table(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution);
CsvTable interior_table(const bem::InteriorSolution& solution);
CsvTable mesh_nodes_table(const geometry::BoundaryMesh& mesh);
CsvTable mesh_elements_table(const geometry::BoundaryMesh& mesh);
std::string boundary_csv(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution);
std::string interior_csv(const bem::InteriorSolution& solution);
std::string mesh_nodes_csv(const geometry::BoundaryMesh& mesh);
std::string mesh_elements_csv(const geometry::BoundaryMesh& mesh);

std::string boundary_vtk(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution,
                         std::string_view title);
std::string mesh_vtk(const geometry::BoundaryMesh& mesh, std::string_view title);
// The same boundary fields as VTK XML PolyData (.vtp), for ParaView time series, and the
// collection (.pvd) that lists files with their times.
std::string boundary_vtp(const geometry::BoundaryMesh& mesh, const bem::BoundarySolution& solution);
// Points as vertices with point data, as VTK XML PolyData (.vtp, for time series).
std::string point_cloud_vtp(const std::vector<Vec2>& points,
                            const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                            const std::vector<std::pair<std::string, std::vector<Vec2>>>& vectors);
std::string time_series_pvd(const std::vector<std::pair<double, std::string>>& time_and_file);
std::string interior_vtk(const bem::InteriorSolution& solution, std::string_view title);
// Polygons (each its own points) with cell data: `scalars`, then the stresses (as interior.vtk).
std::string polygons_vtk(std::string_view title, const std::vector<std::vector<Vec2>>& polygons,
                         const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                         const std::vector<bem::StressTensor>& stress);

// The node sequences the VTK lines follow: per contour, the nodes of its elements in
// order, shared nodes once; a contour without gaps ends with its first node again.
std::vector<std::vector<Index>> boundary_polylines(const geometry::BoundaryMesh& mesh);
// The same lines cut where the boundary piece changes: (piece, nodes); each cut line
// starts at the previous one's last node.
std::vector<std::pair<int, std::vector<Index>>> boundary_piece_lines(const geometry::BoundaryMesh& mesh);
// The quadrilaterals (counter-clockwise point indices) of the interior grid whose four
// corners are in `solution` (InteriorSolution::grid_index).
std::vector<std::vector<Index>> interior_grid_cells(const bem::InteriorSolution& solution);
// Points as vertices with scalar and vector point data, and optionally one string array of
// field data (e.g. the names a numeric code stands for).
std::string point_cloud_vtk(std::string_view title, const std::vector<Vec2>& points,
                            const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                            const std::vector<std::pair<std::string, std::vector<Vec2>>>& vectors,
                            const std::pair<std::string, std::vector<std::string>>& names = {});
// Points joined by polylines (point indices, in order) and the points of no line as
// vertices, with point data u, the stresses (as interior.vtk), then `scalars`, and
// optionally one string array of field data.
std::string polyline_vtk(std::string_view title, const std::vector<Vec2>& points,
                         const std::vector<std::vector<Index>>& lines, const std::vector<Vec2>& displacement,
                         const std::vector<bem::StressTensor>& stress,
                         const std::vector<std::pair<std::string, std::vector<double>>>& scalars,
                         const std::pair<std::string, std::vector<std::string>>& names = {});

}  // namespace bemcontact::io

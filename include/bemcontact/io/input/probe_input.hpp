#pragma once
// What `bemcontact probe` reads: the points it is asked for (a points file, --line
// specifications) and a run's boundary solution (boundary.csv, written at full precision).
// Errors are InputErrors naming the file and line, or the option.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "bemcontact/plasticity/j2_material.hpp"
#include "bemcontact/bem/solution.hpp"

namespace bemcontact::io {

// A point of a points file and the file's line it stands on.
struct ListedPoint {
  Vec2 position = Vec2::Zero();
  int line = 0;
};

// CSV text, one point per line: "x,y" (commas, or spaces or tabs). Blank lines and lines
// starting with '#' are skipped. A first line that holds no number is a header: its columns
// named x and y (or r and z, or ParaView's Points:0 and Points:1) are read, so a file with
// more columns works (interior.csv, a ParaView export);
// a header of two columns names them whatever they are called. A point beyond `max_points`
// is an error at its line (before it is stored: a huge file stops there).
std::vector<ListedPoint> parse_points_file(std::string_view text, const std::string& file_name,
                                           std::size_t max_points = static_cast<std::size_t>(-1));

// A straight line of `count` points, both ends included (count >= 2).
struct ProbeLine {
  Vec2 start = Vec2::Zero(), end = Vec2::Zero();
  int count = 2;
};
// "x0,y0,x1,y1,n"; InputError with key "--line".
ProbeLine parse_probe_line(const std::string& specification);
// The points of the line, start first.
std::vector<Vec2> line_points(const ProbeLine& line);

// The nodes and boundary solution of a boundary.csv (io/results_writer.hpp): positions,
// displacements, tractions and nodal stresses.
struct StoredBoundary {
  std::vector<Vec2> positions;
  bem::BoundarySolution solution;
};
StoredBoundary parse_boundary_csv(std::string_view text, const std::string& file_name);

// The cells of an elastoplastic run's <body>_cells.csv (io/plasticity_writer.hpp): each
// cell's centroid and plastic strain (Mandel: 11, 22, 33, sqrt2 12).
struct StoredCells {
  std::vector<Vec2> centroids;
  std::vector<plasticity::Mandel> plastic_strains;
};
StoredCells parse_cells_csv(std::string_view text, const std::string& file_name);

}  // namespace bemcontact::io

#pragma once
// The cells of a region's plastic area from a target size (docs/plasticity.md, Cells): a
// quadtree of rectangles over the area (the region's bounding box, or a box the user
// names), split toward refinement points, each leaf cut by the region's boundary polygon
// (Sutherland-Hodgman against the leaf). The cells need not match each other node for
// node: each carries its own constant initial stress and its field is the integral over its
// own edges (plasticity/initial_stress.hpp), so hanging vertices are harmless. They must
// tile the polygon the boundary elements' chords draw, with no overlap. A leaf the cut
// leaves concave (a concave arc or a re-entrant corner through it) stays one cell: its
// field is still its edges' integral, and its mean points come from its ear triangles
// (splitting it into those triangles made slivers whose mean strains scattered by 5 Y/E).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bemcontact/plasticity/initial_stress.hpp"

namespace bemcontact::plasticity {

struct CellMeshOptions {
  double size = 0.0;  // the cells' edge away from the refinement points
  std::optional<std::array<Vec2, 2>> box;  // lower-left, upper-right corners; none: the whole region
  // Cells graded toward these points: the edge near a point is refine_size and grows by
  // `growth` per unit distance from it, up to `size`.
  std::vector<Vec2> refine_points;
  double refine_size = 0.0;
  double growth = 0.5;
  // Each leaf cut by its diagonals into four triangles (a leaf the boundary cuts, if convex,
  // fanned about its vertices' mean): cell edges at
  // +-45 degrees everywhere, along which a band of constant plastic shear is compatible
  // (the slip lines of a plane-strain limit load), as crossed-diagonal meshes of
  // constant-strain finite elements avoid locking [NagtegaalParksRice1974].
  bool crossed = false;
  Index max_cells = 50000;
};

// A closed polygon of the region's boundary, in the order of travel (counterclockwise for
// the outer contour, clockwise for a hole).
struct RegionLoop {
  std::vector<Vec2> points;
  bool hole = false;
};

// Throws Error (its text for the caller to place) when the options are not valid, the box
// misses the region, a leaf is cut by two contours or by a hole's (give a box that keeps
// clear of it), the region is narrower than the cells somewhere, or there would be more
// than max_cells cells.
std::vector<Cell> region_cells(const std::vector<RegionLoop>& loops, const CellMeshOptions& options);

// The size of the largest cell (square root of its area) and of the smallest.
std::array<double, 2> cell_size_range(const std::vector<Cell>& cells);

}  // namespace bemcontact::plasticity

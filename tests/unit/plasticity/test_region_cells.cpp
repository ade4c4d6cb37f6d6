// Cells of a region from a target size (plasticity/region_cells.hpp): they tile the
// boundary's polygon exactly (areas sum to its shoelace area to round-off), are simple
// counterclockwise polygons whose mean points lie inside them, stay in their box, grade
// toward a refinement point, and the cases the generator cannot serve are refused with the
// point where it failed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/core/error.hpp"
#include "bemcontact/plasticity/region_cells.hpp"

namespace bemcontact::plasticity {
namespace {

double polygon_area(const std::vector<Vec2>& p) {
  double twice = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k)
    twice += p[k].x() * p[(k + 1) % p.size()].y() - p[(k + 1) % p.size()].x() * p[k].y();
  return 0.5 * twice;
}

double total_area(const std::vector<Cell>& cells) {
  double sum = 0.0;
  for (const auto& c : cells) sum += c.area();
  return sum;
}

// Counterclockwise simple polygons without straight-through vertices, whose triangles tile
// them (their areas sum to the cell's) and whose mean points lie inside them.
void expect_valid_cells(const std::vector<Cell>& cells) {
  for (const auto& cell : cells) {
    ASSERT_GE(cell.vertices.size(), 3u);
    EXPECT_GT(cell.area(), 0.0);
    const std::size_t n = cell.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 a = cell.vertices[k] - cell.vertices[(k + n - 1) % n];
      const Vec2 b = cell.vertices[(k + 1) % n] - cell.vertices[k];
      EXPECT_NE(a.x() * b.y() - a.y() * b.x(), 0.0) << "a straight-through vertex";
    }
    double sum = 0.0;
    for (const auto& [p, q, r] : cell.triangles()) sum += 0.5 * ((q - p).x() * (r - p).y() - (q - p).y() * (r - p).x());
    EXPECT_NEAR(sum, cell.area(), 1e-14);
    double weights = 0.0;
    for (const auto& [point, weight] : cell.mean_points()) {
      EXPECT_TRUE(cell.contains(point));
      weights += weight;
    }
    EXPECT_NEAR(weights, 1.0, 1e-9);  // the shoelace's round-off on cells 1e-4 of the coordinates squared
  }
}

// The quarter tube 1 <= r <= 2 drawn by chords, 16 per arc.
RegionLoop quarter_tube(int chords = 16) {
  RegionLoop loop;
  for (int k = 0; k <= chords; ++k) {
    const double t = 0.5 * std::numbers::pi * k / chords;
    loop.points.emplace_back(2 * std::cos(t), 2 * std::sin(t));
  }
  for (int k = chords; k >= 0; --k) {
    const double t = 0.5 * std::numbers::pi * k / chords;
    loop.points.emplace_back(std::cos(t), std::sin(t));
  }
  return loop;
}

TEST(RegionCells, SquareIsAGrid) {
  const RegionLoop square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const auto cells = region_cells({square}, CellMeshOptions{0.25});
  EXPECT_EQ(cells.size(), 16u);
  EXPECT_NEAR(total_area(cells), 1.0, 1e-14);
  expect_valid_cells(cells);
}

TEST(RegionCells, CrossedCellsAreFourTrianglesPerRectangle) {
  const RegionLoop square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  CellMeshOptions options{0.25};
  options.crossed = true;
  const auto cells = region_cells({square}, options);
  ASSERT_EQ(cells.size(), 64u);
  EXPECT_NEAR(total_area(cells), 1.0, 1e-14);
  expect_valid_cells(cells);
  for (const auto& cell : cells) {
    ASSERT_EQ(cell.vertices.size(), 3u);
    EXPECT_NEAR(cell.area(), 0.25 * 0.25 / 4, 1e-15);
    // two edges at +-45 degrees (the diagonals), one along an axis
    int diagonal = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec2 e = cell.vertices[(k + 1) % 3] - cell.vertices[k];
      diagonal += std::abs(std::abs(e.x()) - std::abs(e.y())) < 1e-14;
    }
    EXPECT_EQ(diagonal, 2);
  }
  // Leaves the boundary cuts are fanned about their vertices' mean (a concave cut stays whole):
  // the tube still tiles exactly.
  const RegionLoop tube = quarter_tube();
  options.size = 0.1;
  const auto curved = region_cells({tube}, options);
  EXPECT_NEAR(total_area(curved), polygon_area(tube.points), 1e-12);
  expect_valid_cells(curved);
}

// Graded crossed cells meet vertex to vertex: a leaf beside smaller ones is fanned through
// their vertices on its sides, so no cell's vertex lies inside another cell's edge (a
// continuous piecewise linear displacement then has a constant strain on each: a compatible
// plastic strain). Rectangles keep their hanging vertices.
TEST(RegionCells, GradedCrossedCellsMeetVertexToVertex) {
  const RegionLoop square{{{0, 0}, {2, 0}, {2, 1}, {0, 1}}};
  CellMeshOptions options{0.25};
  options.refine_points = {Vec2(0.5, 1.0)};
  options.refine_size = 0.03;
  options.growth = 0.3;
  const auto hanging = [](const std::vector<Cell>& cells) {
    int count = 0;
    for (const auto& cell : cells)
      for (std::size_t k = 0, n = cell.vertices.size(); k < n; ++k) {
        const Vec2 a = cell.vertices[k], d = cell.vertices[(k + 1) % n] - a;
        for (const auto& other : cells)
          for (const Vec2& v : other.vertices) {
            const double t = (v - a).dot(d) / d.squaredNorm();
            count += t > 1e-9 && t < 1 - 1e-9 && std::abs(d.x() * (v - a).y() - d.y() * (v - a).x()) < 1e-12;
          }
      }
    return count;
  };
  const auto rectangles = region_cells({square}, options);
  EXPECT_GT(hanging(rectangles), 0);  // the grading's hanging vertices are there
  options.crossed = true;
  const auto cells = region_cells({square}, options);
  EXPECT_NEAR(total_area(cells), 2.0, 1e-13);
  expect_valid_cells(cells);
  EXPECT_EQ(hanging(cells), 0);
  EXPECT_GT(cells.size(), 4 * rectangles.size());  // the fans through the neighbours' vertices
}

TEST(RegionCells, CurvedRegionIsTiledExactly) {
  const RegionLoop tube = quarter_tube();
  for (double size : {0.3, 0.1, 0.05}) {
    const auto cells = region_cells({tube}, CellMeshOptions{size});
    EXPECT_NEAR(total_area(cells), polygon_area(tube.points), 1e-12) << size;
    expect_valid_cells(cells);
    EXPECT_LE(cell_size_range(cells)[0], size * 1.0001);
  }
}

TEST(RegionCells, ReentrantCornerStaysOneCell) {
  // An L whose inner corner (0.55, 0.55) lies inside a leaf of size 0.2.
  const RegionLoop l{{{0, 0}, {1, 0}, {1, 0.55}, {0.55, 0.55}, {0.55, 1}, {0, 1}}};
  const auto cells = region_cells({l}, CellMeshOptions{0.2});
  EXPECT_NEAR(total_area(cells), polygon_area(l.points), 1e-14);
  int concave = 0;
  for (const auto& cell : cells) concave += !cell.convex();
  EXPECT_EQ(concave, 1);  // the leaf around the corner: an L of its own
  expect_valid_cells(cells);
}

TEST(RegionCells, GradedTowardAPointAndKeptInTheBox) {
  const RegionLoop block{{{-2, -2}, {2, -2}, {2, 0}, {-2, 0}}};
  CellMeshOptions options{0.4};
  options.box = std::array<Vec2, 2>{Vec2(-1, -1.5), Vec2(1, 1)};
  options.refine_points = {Vec2(0.3, 0)};
  options.refine_size = 0.02;
  options.growth = 0.5;
  const auto cells = region_cells({block}, options);
  EXPECT_NEAR(total_area(cells), 2.0 * 1.5, 1e-12);  // the box's part of the block
  expect_valid_cells(cells);
  double nearest_size = 0.0, nearest = 1e9;
  for (const auto& cell : cells) {
    for (const Vec2& v : cell.vertices) {
      EXPECT_GE(v.x(), -1 - 1e-12);
      EXPECT_LE(v.x(), 1 + 1e-12);
      EXPECT_GE(v.y(), -1.5 - 1e-12);
      EXPECT_LE(v.y(), 1e-12);
    }
    const double d = (cell.centroid() - options.refine_points[0]).norm();
    const double h = std::sqrt(cell.area());
    if (d < nearest) nearest = d, nearest_size = h;
    // Each cell is no larger than the target at its nearest point plus one split's slack.
    EXPECT_LE(h, std::min(0.4, 2.0 * (0.02 + 0.5 * std::max(0.0, d - h))) + 1e-12);
  }
  EXPECT_LE(nearest_size, 0.02);
  EXPECT_LT(cells.size(), 2000u);  // graded, not uniform at 0.02 (7 500 cells)
}

TEST(RegionCells, RefusesWhatItCannotServe) {
  const RegionLoop outer{{{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}};
  RegionLoop hole{{{-0.5, -0.5}, {-0.5, 0.5}, {0.5, 0.5}, {0.5, -0.5}}, true};
  EXPECT_THROW(region_cells({outer, hole}, CellMeshOptions{0.3}), Error);
  CellMeshOptions clear{0.3};
  clear.box = std::array<Vec2, 2>{Vec2(-2, 1), Vec2(2, 2)};  // above the hole
  EXPECT_NEAR(total_area(region_cells({outer, hole}, clear)), 4.0, 1e-12);
  CellMeshOptions away{0.3};
  away.box = std::array<Vec2, 2>{Vec2(3, 3), Vec2(4, 4)};
  EXPECT_THROW(region_cells({outer}, away), Error);
  EXPECT_THROW(region_cells({outer}, CellMeshOptions{0.0}), Error);
  CellMeshOptions many{1e-3};
  EXPECT_THROW(region_cells({outer}, many), Error);  // 16 million cells
  // A slot narrower than the cells: a leaf would hold two strips of the region.
  const RegionLoop comb{{{0, 0}, {1, 0}, {1, 1}, {0.27, 1}, {0.27, 0.2}, {0.23, 0.2}, {0.23, 1}, {0, 1}}};
  EXPECT_THROW(region_cells({comb}, CellMeshOptions{0.5}), Error);
}

}  // namespace
}  // namespace bemcontact::plasticity

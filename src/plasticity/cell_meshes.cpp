#include "bemcontact/plasticity/cell_meshes.hpp"

#include <cmath>

#include "bemcontact/core/error.hpp"

namespace bemcontact::plasticity {

std::vector<Cell> annular_sector_cells(const Vec2& center, double inner, double outer, double start, double end,
                                       int rings, int sectors) {
  if (!(inner >= 0.0 && outer > inner && end > start && rings >= 1 && sectors >= 1))
    throw Error("annular_sector_cells: needs 0 <= inner < outer, start < end and at least one ring and sector");
  const auto at = [&](int i, int j) {
    const double r = inner + (outer - inner) * i / rings, t = start + (end - start) * j / sectors;
    return Vec2(center + r * Vec2(std::cos(t), std::sin(t)));
  };
  std::vector<Cell> cells;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      Cell cell{{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}};
      if (i == 0 && inner == 0.0) cell.vertices.erase(cell.vertices.begin());  // a triangle at the centre
      cells.push_back(std::move(cell));
    }
  return cells;
}

std::vector<Cell> rectangle_cells(const Vec2& lower_left, const Vec2& upper_right, int nx, int ny) {
  if (!(upper_right.x() > lower_left.x() && upper_right.y() > lower_left.y() && nx >= 1 && ny >= 1))
    throw Error("rectangle_cells: needs a rectangle of positive size and at least one cell each way");
  const Vec2 size = upper_right - lower_left;
  const auto at = [&](int i, int j) {
    return Vec2(lower_left + Vec2(size.x() * i / nx, size.y() * j / ny));
  };
  std::vector<Cell> cells;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) cells.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
  return cells;
}

}  // namespace bemcontact::plasticity

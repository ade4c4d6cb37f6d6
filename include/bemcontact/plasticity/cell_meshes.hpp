#pragma once
// Structured cell meshes of simple plastic areas (plasticity/initial_stress.hpp): an
// annular sector and a rectangle, quadrilaterals with straight edges, counterclockwise.
// A sector's corners lie on its arcs: give it the angles of the boundary's nodes there so
// that the cells and the boundary's chords tile the same polygon.
#include <vector>

#include "bemcontact/plasticity/initial_stress.hpp"

namespace bemcontact::plasticity {

// center + r (cos t, sin t) for inner <= r <= outer, start <= t <= end (radians, end > start):
// `rings` x `sectors` cells, rings uniform in r.
std::vector<Cell> annular_sector_cells(const Vec2& center, double inner, double outer, double start, double end,
                                       int rings, int sectors);

// The rectangle [x0, x1] x [y0, y1] in nx x ny cells.
std::vector<Cell> rectangle_cells(const Vec2& lower_left, const Vec2& upper_right, int nx, int ny);

}  // namespace bemcontact::plasticity

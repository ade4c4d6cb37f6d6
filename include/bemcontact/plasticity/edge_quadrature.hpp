#pragma once
// Quadrature along a cell's edge graded toward the point of the edge nearest to x: the
// logarithm of U when x lies on the edge (a collocation node), the 1/r of D near it
// (plasticity/initial_stress.hpp and ring_initial_stress.hpp); and the cells' small
// geometric helpers.
#include <algorithm>
#include <cmath>

#include "bemcontact/core/types.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::plasticity {

// The z component of a x b.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// The outward normal of the edge from a to b of a counterclockwise cell.
inline Vec2 edge_outward_normal(const Vec2& a, const Vec2& b) {
  const Vec2 d = (b - a).normalized();
  return Vec2(d.y(), -d.x());
}

// Calls add(y, w) at the quadrature points of the segment [a, b], graded toward the point
// of the segment nearest to x.
template <class Add>
inline void for_each_edge_point(const Vec2& a, const Vec2& b, const Vec2& x, Add&& add) {
  constexpr int kPanelPoints = 8;
  // Panels halve toward the nearest point down to this fraction of its distance (of the edge
  // length when x lies on the edge: the logarithm's panel there is negligible).
  constexpr double kPanelToDistance = 0.25;
  constexpr double kSmallestPanel = 1e-10;
  constexpr int kMaxLevels = 40;
  // An edge farther than this many lengths from x takes one panel of kFarPoints (Gauss's
  // error there is of order (1/8)^8 of its contribution).
  constexpr double kFarEdge = 4.0;
  constexpr int kFarPoints = 6;
  // Beyond kDistantEdge lengths, kDistantPoints (error of order (1/16)^6).
  constexpr double kDistantEdge = 8.0;
  constexpr int kDistantPoints = 4;
  const Vec2 d = b - a;
  const double length = d.norm();
  const double nearest = std::clamp((x - a).dot(d) / (length * length), 0.0, 1.0) * length;
  const double distance = (a + d * (nearest / length) - x).norm();
  if (distance > kFarEdge * length) {  // a smooth integrand: one panel
    const quadrature::Rule& rule = quadrature::gauss_legendre(distance > kDistantEdge * length ? kDistantPoints : kFarPoints);
    for (int g = 0; g < rule.size(); ++g) add(a + d * (0.5 * (1.0 + rule.nodes[g])), 0.5 * length * rule.weights[g]);
    return;
  }
  const double finest = std::max(kPanelToDistance * distance, kSmallestPanel * length);
  const quadrature::Rule& rule = quadrature::gauss_legendre(kPanelPoints);
  const auto panel = [&](double s0, double s1) {
    for (int g = 0; g < rule.size(); ++g) {
      const double s = s0 + 0.5 * (s1 - s0) * (1.0 + rule.nodes[g]);
      add(a + d * (s / length), 0.5 * std::abs(s1 - s0) * rule.weights[g]);
    }
  };
  // Each side of the nearest point: panels [nearest + h/2, nearest + h], h halving.
  for (const double side : {-1.0, 1.0}) {
    const double span = side < 0.0 ? nearest : length - nearest;
    if (span <= kSmallestPanel * length) continue;  // x at this end (to round-off): nothing beyond
    double h = span;
    int level = 0;
    while (h > finest && level < kMaxLevels) {
      panel(nearest + side * 0.5 * h, nearest + side * h);
      h *= 0.5;
      ++level;
    }
    panel(nearest, nearest + side * h);
  }
}

}  // namespace bemcontact::plasticity

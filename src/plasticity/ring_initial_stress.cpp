#include "bemcontact/plasticity/ring_initial_stress.hpp"

#include <cmath>
#include <vector>

#include "bemcontact/plasticity/edge_quadrature.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::plasticity {
namespace {

// Duffy's square on a triangle from x: s (toward the apex x, where U has its logarithm)
// in geometric panels [0, 4^-3], [4^-3, 4^-2], [4^-2, 4^-1], [4^-1, 1] of kApexPoints each,
// t in kSidePoints; away from x the cell's own triangles with kFarPoints each way. Near:
// the centroid within kNearCells cell sizes. (Uniform Gauss in s left 2e-5 of the area
// term's logarithm at 16 points; these panels reach 1e-8 with fewer points.)
constexpr int kApexPoints = 8;
constexpr int kSidePoints = 16;
constexpr int kFarPoints = 6;
constexpr double kNearCells = 1.25;
// Beyond kDistantCells sizes the area's integrand varies on a scale of 4 sizes or more:
// kDistantPoints each way (Gauss's error of order (1/8)^8 of the area term); most
// pairs of cells are that far apart, and the area term was 3/4 of their cost.
constexpr double kDistantCells = 4.0;
constexpr int kDistantPoints = 4;
// Beyond kRemoteCells sizes, kRemotePoints: the same order of error as kDistantPoints at
// kDistantCells ((1/16)^6 against (1/8)^8 of the area term), and most of the yielding
// cells' columns are that far (the cells near the contact are the small ones). Two points
// even at 30-50 sizes left 1e-6 to 7e-6 of the cell's field (its terms cancel to a
// dipole): not taken.
constexpr double kRemoteCells = 8.0;
constexpr int kRemotePoints = 3;

// The traction sigma0 n per unit component (rr, zz, rz, tt) on an edge of outward normal n.
Matrix24 ring_traction_of_components(const Vec2& n) {
  Matrix24 t;
  t << n.x(), 0.0, n.y(), 0.0,  //
      0.0, n.y(), n.x(), 0.0;
  return t;
}

// The body force -div sigma0 times r per unit component: -(s_rr - s_tt) e_r - s_rz e_z.
Matrix24 body_force_of_components() {
  Matrix24 b;
  b << -1.0, 0.0, 0.0, 1.0,  //
      0.0, 0.0, -1.0, 0.0;
  return b;
}

// Calls add(y, w) with the quadrature of the triangle (apex, a, b) collapsed at the apex
// (Duffy: y = apex + s (a - apex + t (b - a)), dA = s cross(a - apex, b - apex) ds dt; the
// weight is signed, so the triangles from any apex to a polygon's edges sum to its area),
// s in `panels` (fractions of [0, 1]).
template <class Add>
void for_each_triangle_point(const Vec2& apex, const Vec2& a, const Vec2& b, const std::vector<double>& panels,
                             int s_points, int t_points, Add&& add) {
  const double twice = (a - apex).x() * (b - apex).y() - (a - apex).y() * (b - apex).x();
  if (twice == 0.0) return;
  const auto& s_rule = quadrature::gauss_legendre(s_points);
  const auto& t_rule = quadrature::gauss_legendre(t_points);
  for (std::size_t p = 0; p + 1 < panels.size(); ++p) {
    const double s0 = panels[p], s1 = panels[p + 1];
    for (int i = 0; i < s_rule.size(); ++i) {
      const double s = s0 + 0.5 * (s1 - s0) * (1.0 + s_rule.nodes[i]);
      for (int j = 0; j < t_rule.size(); ++j) {
        const double t = 0.5 * (1.0 + t_rule.nodes[j]);
        add(Vec2(apex + s * ((a - apex) + t * (b - a))), 0.25 * (s1 - s0) * s_rule.weights[i] * t_rule.weights[j] * s * twice);
      }
    }
  }
}

// Calls add(y, w) with a quadrature of the cell's area (dr dz), exact enough for an
// integrand singular at x only.
template <class Add>
void for_each_area_point(const Cell& cell, const Vec2& x, Add&& add) {
  const double size = std::sqrt(std::abs(cell.area()));
  const auto& v = cell.vertices;
  if ((cell.centroid() - x).norm() < kNearCells * size) {
    static const std::vector<double> apex_panels{0.0, 1.0 / 64.0, 1.0 / 16.0, 0.25, 1.0};
    for (std::size_t k = 0; k < v.size(); ++k)
      for_each_triangle_point(x, v[k], v[(k + 1) % v.size()], apex_panels, kApexPoints, kSidePoints, add);
    return;
  }
  static const std::vector<double> whole{0.0, 1.0};
  const double distance = (cell.centroid() - x).norm() / size;
  const int points = distance > kRemoteCells ? kRemotePoints : distance > kDistantCells ? kDistantPoints : kFarPoints;
  for (const auto& [a, b, c] : cell.triangles()) for_each_triangle_point(a, b, c, whole, points, points, add);
}

// Calls edge(y, w, t) at the edges' points (w with the ring's weight r, t = sigma0 n per
// unit component) and area(y, w) at the area's points.
template <class Edge, class Area>
void for_each_ring_point(const Cell& cell, const Vec2& x, Edge&& edge, Area&& area) {
  const auto& v = cell.vertices;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 &a = v[k], &b = v[(k + 1) % v.size()];
    const Matrix24 traction = ring_traction_of_components(edge_outward_normal(a, b));
    for_each_edge_point(a, b, x, [&](const Vec2& y, double w) { edge(y, w * y.x(), traction); });
  }
  for_each_area_point(cell, x, area);
}

}  // namespace

Matrix24 ring_cell_displacement_influence(const kernels::KelvinAxisymmetric& kernel, const Vec2& x, const Cell& cell) {
  Matrix24 out = Matrix24::Zero();
  const Vec2 normal(1.0, 0.0);  // T is not used
  const Matrix24 body = body_force_of_components();
  for_each_ring_point(
      cell, x,
      [&](const Vec2& y, double w, const Matrix24& traction) {
        out += w * kernels::ring_kernels(kernel, x, y, normal).U * traction;
      },
      [&](const Vec2& y, double w) { out += w * kernels::ring_kernels(kernel, x, y, normal).U * body; });
  return out;
}

Matrix44 ring_cell_stress_influence(const kernels::KelvinAxisymmetric& kernel, const Vec2& x, const Cell& cell) {
  Matrix44 out = Matrix44::Zero();
  const Matrix24 body = body_force_of_components();
  const auto add = [&](const Vec2& y, double w, const Matrix24& load) {
    const auto D = kernels::ring_stress_from_traction(kernel, x, y);  // [i][component]
    for (int component = 0; component < 4; ++component)
      for (int row = 0; row < 4; ++row)
        out(row, component) += w * (D[0][row] * load(0, component) + D[1][row] * load(1, component));
  };
  for_each_ring_point(
      cell, x, [&](const Vec2& y, double w, const Matrix24& traction) { add(y, w, traction); },
      [&](const Vec2& y, double w) { add(y, w, body); });
  return out;
}

}  // namespace bemcontact::plasticity

#include "bemcontact/plasticity/initial_stress.hpp"

#include <optional>

#include <algorithm>
#include <cmath>

#include "bemcontact/plasticity/edge_quadrature.hpp"
#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::plasticity {
namespace {

// The traction sigma0 n per unit component (11, 22, 12) of sigma0.
Eigen::Matrix<double, 2, 3> traction_of_components(const Vec2& n) {
  Eigen::Matrix<double, 2, 3> t;
  t << n.x(), 0.0, n.y(),  //
      0.0, n.y(), n.x();
  return t;
}

// Calls add(y, w, t) at the quadrature points of the cell's edges, t the traction sigma0 n
// there per unit component of sigma0 (n the edge's outward normal).
template <class Add>
void for_each_cell_point(const Cell& cell, const Vec2& x, Add&& add) {
  for (std::size_t k = 0; k < cell.vertices.size(); ++k) {
    const Vec2& a = cell.vertices[k];
    const Vec2& b = cell.vertices[(k + 1) % cell.vertices.size()];
    const Eigen::Matrix<double, 2, 3> traction = traction_of_components(edge_outward_normal(a, b));
    for_each_edge_point(a, b, x, [&](const Vec2& y, double w) { add(y, w, traction); });
  }
}

}  // namespace

Matrix33 in_plane_stiffness(AnalysisType type, const Material& material) {
  const double G = material.shear_modulus(), nu = material.poisson_ratio;
  // lambda of plane strain; plane stress's reduced 2 G nu / (1 - nu).
  const double lambda = type == AnalysisType::plane_stress ? 2.0 * G * nu / (1.0 - nu) : 2.0 * G * nu / (1.0 - 2.0 * nu);
  Matrix33 C;
  C << lambda + 2 * G, lambda, 0.0,  //
      lambda, lambda + 2 * G, 0.0,   //
      0.0, 0.0, 2 * G;
  return C;
}

double Cell::area() const {
  double twice = 0.0;  // the shoelace formula
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const Vec2& p = vertices[k];
    const Vec2& q = vertices[(k + 1) % vertices.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

namespace {

bool in_triangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0;
}

}  // namespace

bool Cell::convex() const {
  const std::size_t n = vertices.size();
  for (std::size_t k = 0; k < n; ++k)
    if (cross(vertices[k] - vertices[(k + n - 1) % n], vertices[(k + 1) % n] - vertices[k]) < 0.0) return false;
  return true;
}

std::vector<std::array<Vec2, 3>> Cell::triangles() const {
  std::vector<std::array<Vec2, 3>> out;
  if (vertices.size() == 3) return {{vertices[0], vertices[1], vertices[2]}};
  if (convex()) {  // the fan from vertex 0
    for (std::size_t k = 1; k + 1 < vertices.size(); ++k) out.push_back({vertices[0], vertices[k], vertices[k + 1]});
    return out;
  }
  // Ear clipping: a convex vertex whose triangle holds no other vertex is cut off.
  std::vector<Vec2> polygon = vertices;
  while (polygon.size() > 3) {
    const std::size_t n = polygon.size();
    bool clipped = false;
    for (std::size_t k = 0; k < n && !clipped; ++k) {
      const Vec2 &a = polygon[(k + n - 1) % n], &b = polygon[k], &c = polygon[(k + 1) % n];
      if (cross(b - a, c - b) <= 0.0) continue;
      bool empty = true;
      for (std::size_t j = 0; j < n && empty; ++j)
        if (j != k && j != (k + 1) % n && j != (k + n - 1) % n && in_triangle(polygon[j], a, b, c)) empty = false;
      if (!empty) continue;
      out.push_back({a, b, c});
      polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
    }
    if (!clipped) return {};
  }
  out.push_back({polygon[0], polygon[1], polygon[2]});
  return out;
}

bool Cell::contains(const Vec2& p) const {
  bool inside = false;  // the even-odd rule
  for (std::size_t k = 0, n = vertices.size(); k < n; ++k) {
    const Vec2 &a = vertices[k], &b = vertices[(k + 1) % n];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x()))
      inside = !inside;
  }
  return inside;
}

std::optional<std::array<Vec2, 2>> Cell::rectangle() const {
  if (vertices.size() != 4) return std::nullopt;
  Vec2 lo = vertices[0], hi = vertices[0];
  for (const Vec2& v : vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  // Within round-off of the corners (a cut leaf's corners come from the boundary's points).
  const double tolerance = 1e-9 * (hi - lo).norm();
  for (const Vec2& v : vertices)
    if ((std::abs(v.x() - lo.x()) > tolerance && std::abs(v.x() - hi.x()) > tolerance) ||
        (std::abs(v.y() - lo.y()) > tolerance && std::abs(v.y() - hi.y()) > tolerance))
      return std::nullopt;
  if (!(std::abs(area() - (hi - lo).prod()) <= 1e-8 * (hi - lo).prod())) return std::nullopt;
  return std::array<Vec2, 2>{lo, hi};
}

std::vector<std::pair<Vec2, double>> Cell::mean_points(int refinement) const {
  std::vector<std::pair<Vec2, double>> out;
  // An axis-aligned rectangle (a quadtree leaf): the n x n Gauss rule, n = 2 refinement,
  // symmetric, so a mirrored cell has the mirrored points.
  if (const auto box = rectangle()) {
    const auto& rule = quadrature::gauss_legendre(2 * refinement);
    const Vec2 centre = 0.5 * ((*box)[0] + (*box)[1]), half = 0.5 * ((*box)[1] - (*box)[0]);
    for (int i = 0; i < rule.size(); ++i)
      for (int j = 0; j < rule.size(); ++j)
        out.emplace_back(centre + Vec2(rule.nodes[i] * half.x(), rule.nodes[j] * half.y()),
                         0.25 * rule.weights[i] * rule.weights[j]);
    return out;
  }
  // Each triangle split into refinement^2 similar ones, three points each.
  const double total = area();
  for (const auto& [a, b, c] : triangles()) {
    const Vec2 u = (b - a) / refinement, v = (c - a) / refinement;
    const double share = 0.5 * cross(u, v) / total / 3.0;
    for (int i = 0; i < refinement; ++i)
      for (int j = 0; i + j < refinement; ++j)
        for (const bool flipped : {false, true}) {
          if (flipped && i + j + 1 >= refinement) continue;
          const Vec2 p = a + static_cast<double>(i) * u + static_cast<double>(j) * v;
          const Vec2 q = flipped ? Vec2(p + u + v) : p;  // the flipped one: (p + u + v) - u, - v
          const Vec2 e1 = flipped ? Vec2(-v) : u, e2 = flipped ? Vec2(-u) : v;
          out.emplace_back(q + (e1 + e2) / 6.0, share);
          out.emplace_back(q + (4.0 * e1 + e2) / 6.0, share);
          out.emplace_back(q + (e1 + 4.0 * e2) / 6.0, share);
        }
  }
  return out;
}

Vec2 Cell::centroid() const {
  Vec2 sum = Vec2::Zero();
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const Vec2& p = vertices[k];
    const Vec2& q = vertices[(k + 1) % vertices.size()];
    sum += (p + q) * (p.x() * q.y() - q.x() * p.y());
  }
  return sum / (6.0 * area());
}

Matrix23 cell_displacement_influence(const kernels::KelvinPlane& kernel, const Vec2& x, const Cell& cell) {
  Matrix23 out = Matrix23::Zero();
  for_each_cell_point(cell, x, [&](const Vec2& y, double w, const Eigen::Matrix<double, 2, 3>& traction) {
    // u_k(x) += U(x, y)(k, i) p_i(y)
    out += w * kernels::kelvin_displacement(kernel, x, y) * traction;
  });
  return out;
}

Matrix33 cell_stress_influence(const kernels::KelvinPlane& kernel, const Vec2& x, const Cell& cell) {
  Matrix33 out = Matrix33::Zero();
  for_each_cell_point(cell, x, [&](const Vec2& y, double w, const Eigen::Matrix<double, 2, 3>& traction) {
    // sigma_ij(x) += D(x, y)[k](i, j) p_k(y)
    const kernels::StressKernel D = kernels::kelvin_stress_from_traction(kernel, x, y);
    for (int component = 0; component < 3; ++component)
      for (int c = 0; c < 2; ++c) {
        const double p = w * traction(c, component);
        out(0, component) += D[c](0, 0) * p;
        out(1, component) += D[c](1, 1) * p;
        out(2, component) += D[c](0, 1) * p;
      }
  });
  return out;
}

}  // namespace bemcontact::plasticity

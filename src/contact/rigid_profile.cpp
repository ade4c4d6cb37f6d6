#include "bemcontact/contact/rigid_profile.hpp"

#include <cmath>

#include "bemcontact/core/error.hpp"

namespace bemcontact::contact {
namespace {

geometry::BoundaryPiece line(const std::string& name, const Vec2& a, const Vec2& b) {
  return geometry::line_piece(name, a, b, 1);
}

// Arc counterclockwise about `center` (a convex part of the indenter).
geometry::BoundaryPiece arc(const std::string& name, const Vec2& a, const Vec2& b, const Vec2& center) {
  geometry::BoundaryPiece piece = geometry::line_piece(name, a, b, 1);
  piece.shape = geometry::PieceShape::arc;
  piece.center = center;
  piece.counterclockwise = true;
  return piece;
}

void polyline(const std::vector<Vec2>& points, std::vector<geometry::BoundaryPiece>& pieces) {
  if (points.size() < 2) throw GeometryError("rigid contour: needs at least two points");
  pieces.reserve(points.size() - 1);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if ((points[k + 1] - points[k]).norm() == 0.0)
      throw GeometryError("rigid contour: points " + std::to_string(k + 1) + " and " + std::to_string(k + 2) +
                          " coincide");
    pieces.push_back(line("segment " + std::to_string(k + 1), points[k], points[k + 1]));
  }
}

}  // namespace

std::vector<geometry::BoundaryPiece> rigid_contour(const ProfileShape& s) {
  std::vector<geometry::BoundaryPiece> pieces;
  const Vec2 c = s.center;
  if (s.profile == "sphere" || s.profile == "cylinder") {
    if (!(s.radius > 0.0)) throw GeometryError("rigid " + s.profile + ": the radius must be > 0");
    const Vec2 right = c + Vec2(s.radius, 0.0), left = c - Vec2(s.radius, 0.0);
    pieces.push_back(arc("upper half", right, left, c));
    pieces.push_back(arc("lower half", left, right, c));
  } else if (s.profile == "flat") {
    const double a = s.half_width, r = s.edge_radius;
    if (!(a > 0.0) || !(r >= 0.0) || !(s.height > r))
      throw GeometryError("rigid flat punch: needs half_width > 0, edge_radius >= 0 and sides higher than the edge radius");
    const double w = a + r;
    pieces.push_back(line("left side", c + Vec2(-w, s.height), c + Vec2(-w, r)));
    if (r > 0.0) pieces.push_back(arc("left edge", c + Vec2(-w, r), c + Vec2(-a, 0.0), c + Vec2(-a, r)));
    pieces.push_back(line("face", c + Vec2(-a, 0.0), c + Vec2(a, 0.0)));
    if (r > 0.0) pieces.push_back(arc("right edge", c + Vec2(a, 0.0), c + Vec2(w, r), c + Vec2(a, r)));
    pieces.push_back(line("right side", c + Vec2(w, r), c + Vec2(w, s.height)));
  } else if (s.profile == "cone") {
    if (!(s.half_angle > 0.0 && s.half_angle < 0.5 * 3.141592653589793) || !(s.height > 0.0))
      throw GeometryError("rigid cone: needs 0 < half_angle < 90 degrees and a height > 0");
    const double x = s.height * std::tan(s.half_angle);
    pieces.push_back(line("left flank", c + Vec2(-x, s.height), c));
    pieces.push_back(line("right flank", c, c + Vec2(x, s.height)));
  } else if (s.profile == "contour") {
    polyline(s.points, pieces);
  } else if (s.profile == "rough") {
    const std::vector<double> h = rough_heights(s.rough);
    std::vector<Vec2> points(h.size());
    const double spacing = s.rough.length / static_cast<double>(h.size() - 1);
    for (std::size_t k = 0; k < h.size(); ++k)
      points[k] = c + Vec2(-0.5 * s.rough.length + spacing * static_cast<double>(k), -h[k]);
    polyline(points, pieces);
  } else {
    throw GeometryError("rigid body: unknown profile '" + s.profile + "'");
  }
  return pieces;
}

}  // namespace bemcontact::contact

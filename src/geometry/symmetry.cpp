#include "bemcontact/geometry/symmetry.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "bemcontact/core/error.hpp"
#include "bemcontact/geometry/boundary.hpp"
#include "bemcontact/geometry/mesh.hpp"

namespace bemcontact::geometry {
namespace {

// A symmetry line: the points x with m . x = level, m the outward normal of its piece (the
// body lies where m . x <= level).
struct SymmetryLine {
  Vec2 normal;
  double level = 0.0;
  std::string names;  // the boundaries on it, for messages
};

ImageMap reflection_across(const SymmetryLine& line) {
  ImageMap map;
  map.matrix = Mat2::Identity() - 2.0 * line.normal * line.normal.transpose();
  map.offset = 2.0 * line.level * line.normal;
  return map;
}

ImageMap composed(const ImageMap& a, const ImageMap& b) {  // a after b
  return {a.matrix * b.matrix, a.matrix * b.offset + a.offset};
}

// The farthest a piece reaches past the line (> 0: on the mirror side).
double reach_past(const BoundaryPiece& piece, const SymmetryLine& line) {
  double reach = -std::numeric_limits<double>::infinity();
  const int samples = piece.shape == PieceShape::arc ? 64 : 1;
  for (int k = 0; k <= samples; ++k)
    reach = std::max(reach, line.normal.dot(point_on_piece(piece, static_cast<double>(k) / samples).position) - line.level);
  return reach;
}

}  // namespace

std::vector<ImageMap> symmetry_images(const std::vector<BoundaryPiece>& pieces, bool axisymmetric) {
  std::vector<SymmetryLine> lines;
  const double tolerance = 1e-9 * geometry_scale(pieces);
  for (const auto& piece : pieces) {
    if (!piece.symmetry) continue;
    if (piece.shape != PieceShape::line)
      throw GeometryError("boundary '" + piece.name + "' is a symmetry line and must be straight");
    const Vec2 normal = point_on_piece(piece, 0.0).outward_normal;
    if (axisymmetric && std::abs(normal.x()) > 1e-9)
      throw GeometryError("boundary '" + piece.name + "': in axisymmetry a symmetry line must be perpendicular to the "
                          "axis (z = const), the mirror of the section in the plane z = const");
    const double level = normal.dot(piece.start);
    bool known = false;
    for (auto& line : lines)
      if (line.normal.dot(normal) > 1.0 - 1e-9 && std::abs(line.level - level) <= tolerance) {
        line.names += ", '" + piece.name + "'";
        known = true;
      }
    if (!known) lines.push_back({normal, level, "'" + piece.name + "'"});
  }
  if (lines.empty()) return {};
  if (lines.size() > 2 || (lines.size() == 2 && std::abs(lines[0].normal.dot(lines[1].normal)) > 1e-9))
    throw GeometryError("the symmetry lines (boundaries " + lines[0].names + "; " + lines[1].names +
                        ") must be one line or two perpendicular lines");
  for (const auto& line : lines)
    for (const auto& piece : pieces)
      if (reach_past(piece, line) > tolerance)
        throw GeometryError("boundary '" + piece.name + "' reaches past the symmetry line " + line.names +
                            ": the body must lie on one side of each symmetry line (its outward normal points "
                            "to the mirror side)");
  std::vector<ImageMap> images{reflection_across(lines[0])};
  if (lines.size() == 2) {
    images.push_back(reflection_across(lines[1]));
    images.push_back(composed(images[0], images[1]));
  }
  return images;
}

BoundaryElement image_element(const BoundaryElement& element, const ImageMap& image) {
  BoundaryElement out = element;
  const bool reverse = image.reverses();
  out.start = image.apply(reverse ? element.end : element.start);
  out.end = image.apply(reverse ? element.start : element.end);
  out.tangent = (out.end - out.start) / element.length;
  out.normal = Vec2(out.tangent.y(), -out.tangent.x());
  if (reverse)
    for (int a = 0; a < element.node_count; ++a) out.node_fraction[a] = 1.0 - element.node_fraction[a];
  if (element.arc) {
    out.center = image.apply(element.center);
    // The image of the point at angle theta is at angle 2 phi - theta (reflection across a
    // line of direction phi) or theta + pi (half-turn); reversed travel keeps the span.
    const Vec2 first = image.apply(element.point(reverse ? 1.0 : 0.0)) - out.center;
    out.angle_start = std::atan2(first.y(), first.x());
  }
  return out;
}

}  // namespace bemcontact::geometry

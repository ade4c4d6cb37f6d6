#include "bemcontact/geometry/boundary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace bemcontact::geometry {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

std::string point_text(const Vec2& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

std::string piece_text(const BoundaryPiece& piece) {
  std::string text = "boundary '" + piece.name + "'";
  if (piece.where.line > 0) text += " (" + piece.where.describe() + ")";
  return text;
}

// Signed sweep of an arc from start to end, in (0, 2 pi] or [-2 pi, 0).
double arc_sweep(const BoundaryPiece& piece) {
  const Vec2 a = piece.start - piece.center;
  const Vec2 b = piece.end - piece.center;
  double sweep = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  if (piece.counterclockwise) {
    if (sweep <= 1e-14) sweep += two_pi;
  } else {
    if (sweep >= -1e-14) sweep -= two_pi;
  }
  return sweep;
}

double arc_radius(const BoundaryPiece& piece) { return (piece.start - piece.center).norm(); }

bool segments_cross(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2, double tol) {
  auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
  const Vec2 r = p2 - p1, s = q2 - q1;
  const double denom = cross(r, s);
  const Vec2 qp = q1 - p1;
  if (std::abs(denom) < 1e-300) return false;  // parallel: overlaps are caught as zero-area loops
  const double t = cross(qp, s) / denom;
  const double u = cross(qp, r) / denom;
  return t > tol && t < 1.0 - tol && u > tol && u < 1.0 - tol;
}

}  // namespace

double piece_length(const BoundaryPiece& piece) {
  if (piece.shape == PieceShape::line) return (piece.end - piece.start).norm();
  return std::abs(arc_sweep(piece)) * arc_radius(piece);
}

PiecePoint point_on_piece(const BoundaryPiece& piece, double s) {
  if (piece.shape == PieceShape::line) {
    const Vec2 d = piece.end - piece.start;
    const Vec2 t = d.normalized();
    return {piece.start + s * d, Vec2(t.y(), -t.x())};
  }
  const Vec2 a = piece.start - piece.center;
  const double angle = std::atan2(a.y(), a.x()) + s * arc_sweep(piece);
  const Vec2 radial(std::cos(angle), std::sin(angle));
  const Vec2 position = s == 1.0 ? piece.end : Vec2(piece.center + arc_radius(piece) * radial);
  // Travelling counterclockwise the domain (on the left) is inside the circle, so the
  // outward normal points away from the centre; clockwise (a hole) toward it.
  return {position, piece.counterclockwise ? radial : Vec2(-radial)};
}

std::vector<double> element_breakpoints(const BoundaryPiece& piece) {
  const int n = piece.elements;
  std::vector<double> lengths(n, 1.0);
  if (piece.grading != 1.0 && n > 1) {
    const double ratio = std::pow(piece.grading, 1.0 / (n - 1));
    for (int i = 1; i < n; ++i) lengths[i] = lengths[i - 1] * ratio;
    if (piece.refine_toward == RefineToward::end) std::reverse(lengths.begin(), lengths.end());
  }
  double total = 0.0;
  for (double l : lengths) total += l;
  std::vector<double> s(n + 1, 0.0);
  for (int i = 0; i < n; ++i) s[i + 1] = s[i] + lengths[i] / total;
  s[n] = 1.0;
  return s;
}

double geometry_scale(const std::vector<BoundaryPiece>& pieces) {
  if (pieces.empty()) return 1.0;
  Vec2 lo = pieces.front().start, hi = lo;
  for (const auto& piece : pieces) {
    for (int k = 0; k <= 8; ++k) {
      const Vec2 p = point_on_piece(piece, k / 8.0).position;
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  const double diagonal = (hi - lo).norm();
  return diagonal > 0.0 ? diagonal : 1.0;
}

std::vector<Contour> build_contours(const std::vector<BoundaryPiece>& pieces) {
  if (pieces.empty()) throw GeometryError("the body has no boundary");
  const double scale = geometry_scale(pieces);
  const double tol = 1e-9 * scale;

  for (const auto& piece : pieces) {
    if (piece.elements < 1)
      throw GeometryError(piece_text(piece) + " needs at least one element");
    if (piece.shape == PieceShape::arc) {
      const double r0 = arc_radius(piece), r1 = (piece.end - piece.center).norm();
      if (r0 <= tol)
        throw GeometryError(piece_text(piece) + ": arc centre coincides with its start point");
      if (std::abs(r0 - r1) > 1e-7 * scale)
        throw GeometryError(piece_text(piece) + ": arc end " + point_text(piece.end) +
                            " is not on the circle through its start (radius " +
                            std::to_string(r0) + ", end at distance " + std::to_string(r1) + ")");
    }
    if (piece_length(piece) <= tol)
      throw GeometryError(piece_text(piece) + " has zero length");
    const auto s = element_breakpoints(piece);
    for (std::size_t i = 0; i + 1 < s.size(); ++i)
      if ((s[i + 1] - s[i]) * piece_length(piece) <= tol)
        throw GeometryError(piece_text(piece) + ": element " + std::to_string(i) +
                            " has zero length (grading too strong?)");
  }

  // Chain pieces end-to-start.
  const int n = static_cast<int>(pieces.size());
  std::vector<int> next(n, -1), previous_count(n, 0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if ((pieces[i].end - pieces[j].start).norm() <= tol) {
        if (next[i] >= 0)
          throw GeometryError("boundaries '" + pieces[next[i]].name + "' and '" + pieces[j].name +
                              "' both start at " + point_text(pieces[j].start) +
                              ", the end of '" + pieces[i].name + "'");
        next[i] = j;
        ++previous_count[j];
      }
    }
    if (next[i] < 0)
      throw GeometryError("open contour: no boundary starts at " + point_text(pieces[i].end) +
                          ", the end of " + piece_text(pieces[i]) +
                          " (boundaries must chain end to start, with the domain on their left)");
  }
  for (int j = 0; j < n; ++j)
    if (previous_count[j] != 1)
      throw GeometryError("open contour: no boundary ends at " + point_text(pieces[j].start) +
                          ", the start of " + piece_text(pieces[j]));

  std::vector<Contour> contours;
  std::vector<bool> used(n, false);
  for (int first = 0; first < n; ++first) {
    if (used[first]) continue;
    Contour contour;
    for (int i = first; !used[i]; i = next[i]) {
      used[i] = true;
      contour.pieces.push_back(i);
    }
    // Signed area of a fine polygon through the pieces (shoelace).
    double area = 0.0;
    for (int i : contour.pieces) {
      const int m = pieces[i].shape == PieceShape::arc ? 64 : 1;
      for (int k = 0; k < m; ++k) {
        const Vec2 a = point_on_piece(pieces[i], static_cast<double>(k) / m).position;
        const Vec2 b = point_on_piece(pieces[i], static_cast<double>(k + 1) / m).position;
        area += 0.5 * (a.x() * b.y() - a.y() * b.x());
      }
    }
    contour.signed_area = area;
    contours.push_back(contour);
  }

  // The outer contour has the largest area and runs counterclockwise; holes clockwise.
  std::size_t outer = 0;
  for (std::size_t c = 1; c < contours.size(); ++c)
    if (std::abs(contours[c].signed_area) > std::abs(contours[outer].signed_area)) outer = c;
  auto names = [&](const Contour& contour) {
    std::string text;
    for (int i : contour.pieces) text += (text.empty() ? "'" : ", '") + pieces[i].name + "'";
    return text;
  };
  for (std::size_t c = 0; c < contours.size(); ++c) {
    contours[c].is_hole = c != outer;
    if (std::abs(contours[c].signed_area) <= tol * tol)
      throw GeometryError("the contour made of " + names(contours[c]) + " encloses no area");
    if (!contours[c].is_hole && contours[c].signed_area < 0.0)
      throw GeometryError("the outer contour (" + names(contours[c]) +
                          ") runs clockwise; it must run counterclockwise, with the domain on "
                          "the left of each boundary");
    if (contours[c].is_hole && contours[c].signed_area > 0.0)
      throw GeometryError("the hole made of " + names(contours[c]) +
                          " runs counterclockwise; holes must run clockwise, with the domain on "
                          "the left of each boundary");
  }
  if (outer != 0) std::swap(contours[0], contours[outer]);

  // Crossing pieces: test the polylines through the element breakpoints (and arc points).
  struct Chord { Vec2 a, b; int piece; };
  std::vector<Chord> chords;
  for (int i = 0; i < n; ++i) {
    const int m = std::max(pieces[i].elements, pieces[i].shape == PieceShape::arc ? 32 : 1);
    for (int k = 0; k < m; ++k)
      chords.push_back({point_on_piece(pieces[i], static_cast<double>(k) / m).position,
                        point_on_piece(pieces[i], static_cast<double>(k + 1) / m).position, i});
  }
  // Sort by min x for a sweep that keeps the check near-linear for large meshes.
  std::sort(chords.begin(), chords.end(), [](const Chord& l, const Chord& r) {
    return std::min(l.a.x(), l.b.x()) < std::min(r.a.x(), r.b.x());
  });
  for (std::size_t p = 0; p < chords.size(); ++p) {
    const double max_x = std::max(chords[p].a.x(), chords[p].b.x());
    for (std::size_t q = p + 1; q < chords.size(); ++q) {
      if (std::min(chords[q].a.x(), chords[q].b.x()) > max_x + tol) break;
      if (segments_cross(chords[p].a, chords[p].b, chords[q].a, chords[q].b, 1e-9)) {
        const auto& a = pieces[chords[p].piece];
        const auto& b = pieces[chords[q].piece];
        throw GeometryError("boundaries '" + a.name + "' and '" + b.name + "' cross each other");
      }
    }
  }
  return contours;
}

}  // namespace bemcontact::geometry

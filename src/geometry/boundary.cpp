#include "bemcontact/geometry/boundary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <unordered_map>

namespace bemcontact::geometry {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

// Warnings stand alone: the whole place of the boundary.
std::string piece_text(const BoundaryPiece& piece) {
  std::string text = "boundary '" + piece.name + "'";
  if (piece.where.line > 0) text += " (" + piece.where.describe() + ")";
  return text;
}

// In an error, whose message starts with the file and line of the first boundary it
// names: "'name' (line 12)".
std::string quoted_name(const BoundaryPiece& piece) {
  return "'" + piece.name + "'" + (piece.where.line > 0 ? " (line " + std::to_string(piece.where.line) + ")" : "");
}
std::string boundary_text(const BoundaryPiece& piece) { return "boundary " + quoted_name(piece); }

GeometryError piece_error(std::initializer_list<const BoundaryPiece*> pieces, const std::string& message) {
  std::vector<SourceLocation> where;
  for (const auto* piece : pieces) where.push_back(piece->where);
  return GeometryError(std::move(where), message);
}

// Signed sweep of an arc from start to end, in (0, 2 pi] or [-2 pi, 0).
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

// The polyline through every element end (and 32 points at least per arc) of each piece.
struct Chord {
  Vec2 a, b;
  int piece;
  int index;  // along the piece
  int count;  // chords of the piece
};

std::vector<Chord> boundary_chords(const std::vector<BoundaryPiece>& pieces) {
  std::vector<Chord> chords;
  for (int i = 0; i < static_cast<int>(pieces.size()); ++i) {
    const int m = std::max(pieces[i].elements, pieces[i].shape == PieceShape::arc ? 32 : 1);
    for (int k = 0; k < m; ++k)
      chords.push_back({point_on_piece(pieces[i], static_cast<double>(k) / m).position,
                        point_on_piece(pieces[i], static_cast<double>(k + 1) / m).position, i, k, m});
  }
  return chords;
}

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

// Distance between two closed segments (0 when they cross).
double segment_distance(const Chord& p, const Chord& q) {
  if (segments_cross(p.a, p.b, q.a, q.b, 0.0)) return 0.0;
  return std::min({point_segment_distance(p.a, q.a, q.b), point_segment_distance(p.b, q.a, q.b),
                   point_segment_distance(q.a, p.a, p.b), point_segment_distance(q.b, p.a, p.b)});
}

// Chords that follow each other along a contour share an end by construction.
bool consecutive(const Chord& p, const Chord& q, const std::vector<int>& next) {
  if (p.piece == q.piece && std::abs(p.index - q.index) == 1) return true;
  if (next[p.piece] == q.piece && p.index == p.count - 1 && q.index == 0) return true;
  if (next[q.piece] == p.piece && q.index == q.count - 1 && p.index == 0) return true;
  return false;
}

// No two chords that do not follow each other may cross or touch (within tol), ends
// included: boundaries that meet at an element end are caught too. Chords are binned on
// a uniform grid along their length, so the check costs about linear time whatever the
// orientation of the edges.
void check_no_crossings(const std::vector<BoundaryPiece>& pieces, const std::vector<Chord>& chords,
                        const std::vector<int>& next, double tol) {
  Vec2 lo = chords.front().a, hi = lo;
  double total_length = 0.0;
  for (const auto& c : chords) {
    lo = lo.cwiseMin(c.a).cwiseMin(c.b);
    hi = hi.cwiseMax(c.a).cwiseMax(c.b);
    total_length += (c.b - c.a).norm();
  }
  const double extent = std::max((hi - lo).maxCoeff(), tol);
  // Cells twice the mean chord length: each chord enters a few cells, and all chords
  // together about as many cells as there are chords.
  const double cell = std::max(2.0 * total_length / static_cast<double>(chords.size()), extent * 1e-7);
  const auto cell_of = [&](double v, double origin) {
    return static_cast<long>(std::floor((v - origin) / cell));
  };
  std::unordered_map<long long, std::vector<int>> grid;
  const long columns = cell_of(hi.x(), lo.x()) + 2;
  for (int c = 0; c < static_cast<int>(chords.size()); ++c) {
    const Vec2 a = chords[c].a, b = chords[c].b;
    const int steps = 1 + static_cast<int>((b - a).norm() / cell);
    long long last = -1;
    for (int k = 0; k < steps; ++k) {
      // The box of each piece of the chord one cell long, widened by the tolerance.
      const Vec2 p = a + (b - a) * (static_cast<double>(k) / steps);
      const Vec2 q = a + (b - a) * (static_cast<double>(k + 1) / steps);
      for (long i = cell_of(std::min(p.x(), q.x()) - tol, lo.x()); i <= cell_of(std::max(p.x(), q.x()) + tol, lo.x()); ++i)
        for (long j = cell_of(std::min(p.y(), q.y()) - tol, lo.y()); j <= cell_of(std::max(p.y(), q.y()) + tol, lo.y()); ++j) {
          const long long key = static_cast<long long>(j + 1) * (columns + 2) + (i + 1);
          auto& list = grid[key];
          if (key != last && (list.empty() || list.back() != c)) list.push_back(c);
          last = key;
        }
    }
  }
  std::vector<long long> keys;
  keys.reserve(grid.size());
  for (const auto& [key, list] : grid) keys.push_back(key);
  std::sort(keys.begin(), keys.end());  // the same first finding on every run
  for (const long long key : keys) {
    const auto& list = grid[key];
    for (std::size_t u = 0; u < list.size(); ++u)
      for (std::size_t v = u + 1; v < list.size(); ++v) {
        const Chord& p = chords[list[u]];
        const Chord& q = chords[list[v]];
        if (consecutive(p, q, next) || segment_distance(p, q) > tol) continue;
        const auto& first = pieces[p.piece];
        const auto& second = pieces[q.piece];
        Vec2 where = p.a;
        const Vec2 r = p.b - p.a, d = q.b - q.a;
        const double denom = r.x() * d.y() - r.y() * d.x();
        if (std::abs(denom) > 0.0) {
          const Vec2 w = q.a - p.a;
          where = p.a + std::clamp((w.x() * d.y() - w.y() * d.x()) / denom, 0.0, 1.0) * r;
        }
        for (const Vec2& end : {p.a, p.b, q.a, q.b})
          if (point_segment_distance(end, p.a, p.b) <= tol && point_segment_distance(end, q.a, q.b) <= tol) where = end;
        if (p.piece == q.piece)
          throw piece_error({&first}, boundary_text(first) + " crosses or touches itself near " + point_text(where));
        throw piece_error({&first, &second}, "boundaries " + quoted_name(first) + " and " + quoted_name(second) +
                                                 " cross or touch near " + point_text(where) +
                                                 " (contours may not meet except end to start)");
      }
  }
}

// Crossing number of `point` with the closed polylines of a contour's chords.
bool inside_contour(const Vec2& point, const Contour& contour, const std::vector<Chord>& chords) {
  bool inside = false;
  for (const auto& c : chords) {
    if (std::find(contour.pieces.begin(), contour.pieces.end(), c.piece) == contour.pieces.end()) continue;
    if ((c.a.y() > point.y()) == (c.b.y() > point.y())) continue;
    const double x = c.a.x() + (point.y() - c.a.y()) / (c.b.y() - c.a.y()) * (c.b.x() - c.a.x());
    if (x > point.x()) inside = !inside;
  }
  return inside;
}

// Every hole lies inside the outer contour (contours[0]) and outside every other hole.
// "'a' (line 3), 'b' (line 7)": the boundaries of a contour in order of travel.
std::string contour_names(const std::vector<BoundaryPiece>& pieces, const Contour& contour) {
  std::string text;
  for (int i : contour.pieces) text += (text.empty() ? "" : ", ") + quoted_name(pieces[i]);
  return text;
}

// An error about contours, placed at their boundaries (the first contour's first).
GeometryError contour_error(const std::vector<BoundaryPiece>& pieces, std::initializer_list<const Contour*> contours,
                            const std::string& message) {
  std::vector<SourceLocation> where;
  for (const auto* contour : contours)
    for (int i : contour->pieces) where.push_back(pieces[i].where);
  return GeometryError(std::move(where), message);
}

void check_holes_inside(const std::vector<BoundaryPiece>& pieces, const std::vector<Contour>& contours,
                        const std::vector<Chord>& chords) {
  const auto names = [&](const Contour& contour) { return contour_names(pieces, contour); };
  for (std::size_t h = 1; h < contours.size(); ++h) {
    // The middle of the hole's first chord: a vertex would sit on the horizontal line
    // through other holes' vertices when holes are aligned (fibres on a grid), where the
    // crossing count turns on rounding.
    Vec2 point = pieces[contours[h].pieces.front()].start;
    for (const auto& c : chords)
      if (c.piece == contours[h].pieces.front()) {
        point = 0.5 * (c.a + c.b);
        break;
      }
    if (!inside_contour(point, contours[0], chords))
      throw contour_error(pieces, {&contours[h], &contours[0]},
                          "the hole made of " + names(contours[h]) + " lies outside the outer contour made of " +
                              names(contours[0]) + ": a clockwise contour is a hole and must lie inside the body");
    for (std::size_t other = 1; other < contours.size(); ++other)
      if (other != h && inside_contour(point, contours[other], chords))
        throw contour_error(pieces, {&contours[h], &contours[other]},
                            "the hole made of " + names(contours[h]) + " lies inside the hole made of " +
                                names(contours[other]));
  }
}

}  // namespace

BoundaryPiece line_piece(const std::string& name, const Vec2& start, const Vec2& end, int elements) {
  BoundaryPiece piece;
  piece.name = name;
  piece.start = start;
  piece.end = end;
  piece.elements = elements;
  return piece;
}

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
  if (!piece.breakpoints.empty()) return piece.breakpoints;
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

double arc_length_at(const BoundaryPiece& piece, const Vec2& point) {
  const double length = piece_length(piece);
  if (piece.shape == PieceShape::line) {
    const Vec2 d = piece.end - piece.start;
    return std::clamp((point - piece.start).dot(d) / d.squaredNorm(), 0.0, 1.0) * length;
  }
  // The angle from the start in the sense of travel, in [0, 2 pi); beyond the sweep, the
  // nearer end.
  const double sweep = arc_sweep(piece);
  const Vec2 a = piece.start - piece.center, b = point - piece.center;
  double angle = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  if (sweep < 0.0) angle = -angle;
  if (angle < 0.0) angle += 2.0 * std::numbers::pi;
  const double span = std::abs(sweep);
  if (angle <= span) return angle / span * length;
  return angle - span < 2.0 * std::numbers::pi - angle ? length : 0.0;
}

std::vector<double> zone_breakpoints(double length, double from, double to, double size, double growth,
                                     double coarsest) {
  from = std::clamp(from, 0.0, length);
  to = std::clamp(to, from, length);
  if (from < size) from = 0.0;
  if (length - to < size) to = length;
  // Element lengths growing away from the stretch, scaled to fill `span` exactly.
  const auto graded = [&](double span) {
    std::vector<double> lengths;
    double h = size, total = 0.0;
    while (total < span) {
      h = std::min(h * growth, std::max(coarsest, size));
      lengths.push_back(h);
      total += h;
    }
    for (double& l : lengths) l *= span / total;
    return lengths;
  };
  std::vector<double> ends{0.0};
  std::vector<double> before = graded(from);
  double x = 0.0;
  for (auto it = before.rbegin(); it != before.rend(); ++it) ends.push_back(x += *it);
  const int fine = std::max(1, static_cast<int>(std::ceil((to - from) / size - 1e-9)));
  for (int k = 1; k <= fine; ++k) ends.push_back(from + (to - from) * k / fine);
  x = to;
  for (const double l : graded(length - to)) ends.push_back(x += l);
  for (double& e : ends) e /= length;
  ends.back() = 1.0;
  return ends;
}

std::vector<double> transition_breakpoints(const BoundaryPiece& piece, double cap_start, double cap_end,
                                           double growth) {
  const std::vector<double> nominal = element_breakpoints(piece);
  const double length = piece_length(piece);
  const int n = static_cast<int>(nominal.size()) - 1;
  // Linear size function kappa (cap + (growth - 1) x): with kappa = ln(growth)/(growth - 1)
  // unit steps of its integral of dx / h give the geometric sequence cap, cap growth, ...
  const double kappa = growth > 1.0 ? std::log(growth) / (growth - 1.0) : 1.0;
  cap_start *= kappa;
  cap_end *= kappa;
  const double slope = kappa * (growth - 1.0);
  if (!(slope > 0.0) || (!(cap_start / kappa < (nominal[1] - nominal[0]) * length) &&
                         !(cap_end / kappa < (nominal[n] - nominal[n - 1]) * length)))
    return nominal;
  // Pieces of the size function on which one expression holds: the piece's element
  // length H, cap_start + slope x, or cap_end + slope (length - x). Cut at the nominal
  // breakpoints and where the expressions cross, then integrate 1/h exactly on each.
  std::vector<double> cuts;
  for (double s : nominal) cuts.push_back(s * length);
  for (int k = 0; k < n; ++k) {
    const double h = (nominal[k + 1] - nominal[k]) * length;
    if (std::isfinite(cap_start)) cuts.push_back((h - cap_start) / slope);
    if (std::isfinite(cap_end)) cuts.push_back(length - (h - cap_end) / slope);
  }
  if (std::isfinite(cap_start) && std::isfinite(cap_end)) cuts.push_back(0.5 * (length + (cap_end - cap_start) / slope));
  std::erase_if(cuts, [&](double x) { return !(x > 0.0 && x < length); });
  cuts.push_back(0.0);
  cuts.push_back(length);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  struct Segment {
    double x0, x1, phi0;  // phi0 = integral of 1/h up to x0
    double c, a;          // h(x) = c + a (x - x0) on the segment
    double phi(double x) const { return a == 0.0 ? (x - x0) / c : std::log1p(a * (x - x0) / c) / a; }
    double inverse(double p) const { return a == 0.0 ? x0 + p * c : x0 + c * std::expm1(a * p) / a; }
  };
  std::vector<Segment> segments;
  double phi = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double x0 = cuts[k], x1 = cuts[k + 1], mid = 0.5 * (x0 + x1);
    const auto it = std::upper_bound(nominal.begin(), nominal.end(), mid / length);
    const int e = std::clamp(static_cast<int>(it - nominal.begin()) - 1, 0, n - 1);
    Segment seg{x0, x1, phi, (nominal[e + 1] - nominal[e]) * length, 0.0};
    const double from_start = cap_start + slope * mid, from_end = cap_end + slope * (length - mid);
    if (from_start < seg.c && from_start <= from_end) seg = {x0, x1, phi, cap_start + slope * x0, slope};
    else if (from_end < seg.c) seg = {x0, x1, phi, cap_end + slope * (length - x0), -slope};
    phi += seg.phi(x1);
    segments.push_back(seg);
  }
  const int count = std::max(1, static_cast<int>(std::ceil(phi - 1e-9)));
  std::vector<double> s(count + 1, 0.0);
  std::size_t j = 0;
  for (int k = 1; k < count; ++k) {
    const double target = phi * k / count;
    while (j + 1 < segments.size() && segments[j + 1].phi0 <= target) ++j;
    s[k] = std::clamp(segments[j].inverse(target - segments[j].phi0), segments[j].x0, segments[j].x1) / length;
  }
  s[count] = 1.0;
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

namespace {

// Each piece on its own: at least one element, an arc's end on its circle, no zero length
// (of the piece or of an element).
void check_pieces(const std::vector<BoundaryPiece>& pieces, double scale, double tol) {
  for (const auto& piece : pieces) {
    if (piece.elements < 1) throw piece_error({&piece}, boundary_text(piece) + " needs at least one element");
    if (piece.shape == PieceShape::arc) {
      const double r0 = arc_radius(piece), r1 = (piece.end - piece.center).norm();
      if (r0 <= tol)
        throw piece_error({&piece}, boundary_text(piece) + ": arc centre coincides with its start point");
      if (std::abs(r0 - r1) > 1e-7 * scale)
        throw piece_error({&piece}, boundary_text(piece) + ": arc end " + point_text(piece.end) +
                                        " is not on the circle through its start (radius " + std::to_string(r0) +
                                        ", end at distance " + std::to_string(r1) + ")");
    }
    if (piece_length(piece) <= tol) throw piece_error({&piece}, boundary_text(piece) + " has zero length");
    const auto s = element_breakpoints(piece);
    for (std::size_t i = 0; i + 1 < s.size(); ++i)
      if ((s[i + 1] - s[i]) * piece_length(piece) <= tol)
        throw piece_error({&piece}, boundary_text(piece) + ": element " + std::to_string(i) +
                                        " has zero length (grading too strong?)");
  }
}

// Chain pieces end-to-start: the piece that starts where each one ends, one and only one.
std::vector<int> chain_pieces(const std::vector<BoundaryPiece>& pieces, double tol) {
  const int n = static_cast<int>(pieces.size());
  std::vector<int> next(n, -1), previous_count(n, 0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if ((pieces[i].end - pieces[j].start).norm() <= tol) {
        if (next[i] >= 0)
          throw piece_error({&pieces[next[i]], &pieces[j], &pieces[i]},
                            "boundaries " + quoted_name(pieces[next[i]]) + " and " + quoted_name(pieces[j]) +
                                " both start at " + point_text(pieces[j].start) + ", the end of " +
                                quoted_name(pieces[i]));
        next[i] = j;
        ++previous_count[j];
      }
    }
    if (next[i] < 0)
      throw piece_error({&pieces[i]}, "open contour: no boundary starts at " + point_text(pieces[i].end) +
                                          ", the end of " + boundary_text(pieces[i]) +
                                          " (boundaries must chain end to start, with the domain on their left)");
  }
  for (int j = 0; j < n; ++j)
    if (previous_count[j] != 1)
      throw piece_error({&pieces[j]}, "open contour: no boundary ends at " + point_text(pieces[j].start) +
                                          ", the start of " + boundary_text(pieces[j]));
  return next;
}

// Signed area of a fine polygon through the contour's pieces (shoelace).
double signed_area(const std::vector<BoundaryPiece>& pieces, const Contour& contour) {
  double area = 0.0;
  for (int i : contour.pieces) {
    const int m = pieces[i].shape == PieceShape::arc ? 64 : 1;
    for (int k = 0; k < m; ++k) {
      const Vec2 a = point_on_piece(pieces[i], static_cast<double>(k) / m).position;
      const Vec2 b = point_on_piece(pieces[i], static_cast<double>(k + 1) / m).position;
      area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
  }
  return area;
}

// The closed chains of pieces, each from its lowest-numbered piece, with their areas.
std::vector<Contour> trace_contours(const std::vector<BoundaryPiece>& pieces, const std::vector<int>& next) {
  const int n = static_cast<int>(pieces.size());
  std::vector<Contour> contours;
  std::vector<bool> used(n, false);
  for (int first = 0; first < n; ++first) {
    if (used[first]) continue;
    Contour contour;
    for (int i = first; !used[i]; i = next[i]) {
      used[i] = true;
      contour.pieces.push_back(i);
    }
    contour.signed_area = signed_area(pieces, contour);
    contours.push_back(contour);
  }
  return contours;
}

// The outer contour has the largest area and runs counterclockwise; holes clockwise. Marks
// the holes and returns the outer contour.
std::size_t mark_holes(const std::vector<BoundaryPiece>& pieces, std::vector<Contour>& contours, double tol) {
  std::size_t outer = 0;
  for (std::size_t c = 1; c < contours.size(); ++c)
    if (std::abs(contours[c].signed_area) > std::abs(contours[outer].signed_area)) outer = c;
  const auto names = [&](const Contour& contour) { return contour_names(pieces, contour); };
  for (std::size_t c = 0; c < contours.size(); ++c) {
    contours[c].is_hole = c != outer;
    if (std::abs(contours[c].signed_area) <= tol * tol)
      throw contour_error(pieces, {&contours[c]}, "the contour made of " + names(contours[c]) + " encloses no area");
    if (!contours[c].is_hole && contours[c].signed_area < 0.0)
      throw contour_error(pieces, {&contours[c]},
                          "the outer contour made of " + names(contours[c]) +
                              " runs clockwise; it must run counterclockwise, with the domain on the left of each "
                              "boundary");
    if (contours[c].is_hole && contours[c].signed_area > 0.0)
      throw contour_error(pieces, {&contours[c]},
                          "the hole made of " + names(contours[c]) +
                              " runs counterclockwise; holes must run clockwise, with the domain on the left of each "
                              "boundary");
  }
  return outer;
}

}  // namespace

std::vector<Contour> build_contours(const std::vector<BoundaryPiece>& pieces) {
  if (pieces.empty()) throw GeometryError("the body has no boundary");
  const double scale = geometry_scale(pieces);
  const double tol = 1e-9 * scale;
  check_pieces(pieces, scale, tol);
  const std::vector<int> next = chain_pieces(pieces, tol);
  // Crossings first: a crossing boundary also spoils the areas and orientations below.
  const auto chords = boundary_chords(pieces);
  check_no_crossings(pieces, chords, next, tol);
  std::vector<Contour> contours = trace_contours(pieces, next);
  const std::size_t outer = mark_holes(pieces, contours, tol);
  if (outer != 0) std::swap(contours[0], contours[outer]);
  check_holes_inside(pieces, contours, chords);
  return contours;
}

std::vector<std::string> geometry_warnings(const std::vector<BoundaryPiece>& pieces) {
  std::vector<std::string> warnings;
  const double tol = 1e-9 * geometry_scale(pieces);
  for (const auto& piece : pieces) {
    if (piece.shape == PieceShape::arc) {
      const double degrees = std::abs(arc_sweep(piece)) * 180.0 / std::numbers::pi;
      if (degrees > 180.0 + 1e-9) {
        std::ostringstream text;
        text << piece_text(piece) << " is an arc sweeping " << std::lround(degrees) << " degrees (direction = \""
             << (piece.counterclockwise ? "ccw" : "cw") << "\"); if a " << std::lround(360.0 - degrees)
             << " degree arc was meant, give the other direction";
        warnings.push_back(text.str());
      }
    }
  }
  // A boundary over a thousand times shorter than a neighbour is usually a typing error.
  for (const auto& piece : pieces) {
    const double length = piece_length(piece);
    for (const auto& other : pieces) {
      const bool neighbour = (other.end - piece.start).norm() <= tol || (other.start - piece.end).norm() <= tol;
      if (&other == &piece || !neighbour) continue;
      const double ratio = piece_length(other) / length;
      if (ratio > 1000.0) {
        std::ostringstream text;
        text << piece_text(piece) << " is " << std::lround(ratio) << " times shorter than its neighbour '" << other.name
             << "'; check its end points";
        warnings.push_back(text.str());
        break;
      }
    }
  }
  return warnings;
}

}  // namespace bemcontact::geometry

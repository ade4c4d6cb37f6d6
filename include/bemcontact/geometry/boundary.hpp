#pragma once
// Geometry of a 2D body (section II.5.1.1): boundary pieces (straight segments and
// circular arcs) chained into closed contours. The domain lies to the left of every
// piece: the outer contour runs counterclockwise, holes run clockwise.
#include <string>
#include <vector>

#include "bemcontact/core/error.hpp"
#include "bemcontact/core/types.hpp"

namespace bemcontact::geometry {

enum class PieceShape { line, arc };
enum class RefineToward { start, end };

struct BoundaryPiece {
  std::string name;
  PieceShape shape = PieceShape::line;
  Vec2 start = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  Vec2 center = Vec2::Zero();    // arcs only
  bool counterclockwise = true;  // arcs only: sense of travel from start to end
  int elements = 1;
  // Geometric grading: ratio of the longest to the shortest element (1 = uniform),
  // the short elements toward `refine_toward`.
  double grading = 1.0;
  RefineToward refine_toward = RefineToward::start;
  // Pieces whose conditions differ may carry different tractions at a shared vertex,
  // so the mesher splits the node there (section II.4.4.2).
  std::string condition_signature;
  // Meshed exactly as given (contact zones, interfaces: their nodes are matched with
  // another mesh), never regraded toward a vertex.
  bool fixed_mesh = false;
  // A symmetry line of the body (geometry/symmetry.hpp): no elements, the mirror image instead.
  bool symmetry = false;
  // Element end points as fractions 0 = s_0 < ... < s_n = 1 of the length, when set (an
  // adapted contact zone, contact/zone_refinement.hpp): they replace elements and grading.
  std::vector<double> breakpoints;
  SourceLocation where;
};

// A straight piece with `elements` uniform elements (for pieces built by code).
BoundaryPiece line_piece(const std::string& name, const Vec2& start, const Vec2& end, int elements);

// Arc-length parameter, position and outward normal of a point on a piece.
struct PiecePoint {
  Vec2 position;
  Vec2 outward_normal;  // right of the direction of travel
};

double piece_length(const BoundaryPiece& piece);
// Arcs: signed angle swept from start to end (> 0 counterclockwise), and the radius.
double arc_sweep(const BoundaryPiece& piece);
double arc_radius(const BoundaryPiece& piece);
// Point at fraction s in [0, 1] of the piece's length.
PiecePoint point_on_piece(const BoundaryPiece& piece, double s);
// Fractions 0 = s_0 < s_1 < ... < s_n = 1 of the element end points, graded as asked (the
// piece's own breakpoints when it has them).
std::vector<double> element_breakpoints(const BoundaryPiece& piece);
// Arc length from the piece's start to the point of the piece nearest to `point`.
double arc_length_at(const BoundaryPiece& piece, const Vec2& point);
// Breakpoints (fractions) of a piece of length `length` with elements of at most `size` on
// the stretch [from, to] (arc lengths) and, on either side of it, elements growing by the
// factor `growth` each up to `coarsest`; each side's sequence is scaled down to fit, and a
// side shorter than one fine element joins the stretch.
std::vector<double> zone_breakpoints(double length, double from, double to, double size, double growth,
                                     double coarsest);
// The same with the end elements no longer than `cap_start` / `cap_end` (lengths; infinity
// for none): the element length grows from the cap by the factor `growth` per element until
// it meets the piece's own grading (size function min(h_piece(x), cap + (growth - 1) x),
// elements placed at equal steps of its integral of dx / h).
std::vector<double> transition_breakpoints(const BoundaryPiece& piece, double cap_start, double cap_end,
                                           double growth);

// Closed contours found by chaining pieces end to start: indices into the piece list, in
// order of travel. Throws GeometryError (naming pieces and vertices) for an open contour,
// a zero-length piece, an arc whose end is off its circle, crossing pieces, or a contour
// with the wrong orientation.
struct Contour {
  std::vector<int> pieces;
  double signed_area = 0.0;  // > 0 counterclockwise
  bool is_hole = false;
};
std::vector<Contour> build_contours(const std::vector<BoundaryPiece>& pieces);

// Geometry that is valid but likely unintended, one message per finding naming the
// boundary: an arc sweeping more than 180 degrees (a wrong `direction` turns a quarter
// circle into a 270 degree lobe), a boundary over 1000 times shorter than a neighbour.
std::vector<std::string> geometry_warnings(const std::vector<BoundaryPiece>& pieces);

// A length scale of the geometry (bounding-box diagonal) for relative tolerances.
double geometry_scale(const std::vector<BoundaryPiece>& pieces);

}  // namespace bemcontact::geometry

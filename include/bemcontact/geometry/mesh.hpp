#pragma once
// Boundary mesh (section II.5.1.2): straight elements carrying constant or linear
// interpolation of u and p. Where the traction may jump (a corner, or a change of
// boundary condition) the node is split: each side gets its own node, moved a fraction
// `corner_shift` of the element length into its element (semi-discontinuous element).
// Every node then has its own collocation point at a smooth point of the boundary, so
// any pair of conditions on the two sides gives a regular system.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "bemcontact/geometry/boundary.hpp"
#include "bemcontact/geometry/symmetry.hpp"

namespace bemcontact::geometry {

struct MeshOptions {
  Interpolation interpolation = Interpolation::linear;
  double corner_shift = 0.2;          // fraction of the element length
  // Corner-adapted grading: where the end elements of two pieces meeting at a vertex differ
  // in length by more than a factor max(2, corner_transition), the coarser piece is graded
  // toward the vertex, its elements growing by this factor from the finer one's length
  // (0: off). The pieces' own element counts are then minimums.
  double corner_transition = 1.2;
  double split_angle_radians = 1e-6;  // smaller turns count as smooth
  // Axisymmetry: straight pieces lying on the axis r = 0 close the meridian section but
  // are not part of the boundary; they carry no elements. (Also names the analysis for the
  // symmetry lines, which must then be perpendicular to the axis.)
  bool skip_axis_pieces = false;
  // Discontinuous elements: every element gets its own end nodes, moved `corner_shift`
  // into it (collocation inside the element; docs/corners.md). With the Gauss points of
  // the element as the shift (discontinuous_node_fraction) linear elements converge at
  // second order for displacements on polygons, where continuous ones reach 1.6.
  bool discontinuous = false;
};

// Fraction of the element where the end nodes of a discontinuous element go by default:
// the Gauss-Legendre points, (1 - 1/sqrt 3) / 2 for linear elements and (1 - sqrt(3/5)) / 2
// for quadratic ones (whose middle node stays at 1/2).
double discontinuous_node_fraction(Interpolation interpolation);
// Switches `options` to discontinuous elements with their nodes at those points.
void use_discontinuous_elements(MeshOptions& options);

// True for a straight piece lying on the axis r = 0 (within tolerance).
bool lies_on_axis(const BoundaryPiece& piece, double tolerance);

struct BoundaryNode {
  Vec2 position;
  Vec2 normal;      // outward unit normal of the true geometry at the node
  int piece = -1;   // piece that owns the node (the first one at a shared vertex)
  bool shifted = false;  // a split-corner node moved into its element
};

inline constexpr int kMaxElementNodes = 3;

struct BoundaryElement {
  Vec2 start, end;   // end points; the chord from start to end
  double length = 0.0;  // of the chord
  Vec2 tangent;      // (end - start) / length
  Vec2 normal;       // outward normal of the chord: tangent rotated clockwise
  // Quadratic elements follow their piece exactly: on an arc, the circle of `radius`
  // about `center` from angle `angle_start` through `angle_span` (signed: > 0 ccw).
  // Constant and linear elements are the straight chords (arc = false).
  bool arc = false;
  Vec2 center = Vec2::Zero();
  double radius = 0.0, angle_start = 0.0, angle_span = 0.0;
  int piece = -1;
  int node_count = 2;  // 1 (constant), 2 (linear) or 3 (quadratic: start, end, middle)
  std::array<Index, kMaxElementNodes> nodes{-1, -1, -1};
  // Node positions along the element as fractions f in [0, 1] of its parameter.
  std::array<double, kMaxElementNodes> node_fraction{0.0, 1.0, 0.5};

  // Shape function a at fraction f (Lagrange through the element's nodes, extrapolated
  // beyond shifted nodes; 1 for constant elements), and its derivative d/df.
  double shape(int a, double f) const {
    if (node_count == 1) return 1.0;
    double value = 1.0;
    for (int b = 0; b < node_count; ++b)
      if (b != a) value *= (f - node_fraction[b]) / (node_fraction[a] - node_fraction[b]);
    return value;
  }
  double shape_derivative(int a, double f) const;
  // Geometry at fraction f: the point, the outward unit normal, and |dy/df| (constant:
  // the arc length of the element).
  Vec2 point(double f) const;
  Vec2 normal_at(double f) const;
  double jacobian() const { return arc ? radius * std::abs(angle_span) : length; }
};

// A straight element from start to end (chord, tangent and normal filled; two nodes at
// fractions 0 and 1, no node indices).
BoundaryElement straight_element(const Vec2& start, const Vec2& end);

// A geometric vertex where two pieces meet.
struct MeshVertex {
  Vec2 position;
  int piece_in = -1, piece_out = -1;   // piece ending here, piece starting here
  Index element_in = -1, element_out = -1;
  Vec2 normal_in = Vec2::Zero(), normal_out = Vec2::Zero();  // outward normals of the two pieces here
  bool split = false;
};

struct BoundaryMesh {
  std::vector<BoundaryNode> nodes;
  std::vector<BoundaryElement> elements;
  std::vector<MeshVertex> vertices;
  std::vector<Contour> contours;
  std::vector<std::vector<Index>> piece_elements;  // elements of each piece, in order
  std::vector<std::vector<Index>> piece_nodes;     // nodes of each piece, in order
  std::vector<bool> piece_skipped;                 // axis and symmetry pieces without elements
  // The body's images across its symmetry lines (geometry/symmetry.hpp; empty: none): every
  // element also acts through image_element(element, images[k]).
  std::vector<ImageMap> images;
  // The symmetry pieces as straight elements without nodes: with the elements they close the
  // body's boundary, and their images close each image body's (bem/assembly.hpp uses that).
  std::vector<BoundaryElement> symmetry_segments;
  std::vector<std::string> piece_names;            // for messages
  // Pieces graded toward a vertex by the corner transition.
  struct GradedPiece {
    int piece = -1;
    std::string name;
    int elements_asked = 0, elements = 0;
  };
  std::vector<GradedPiece> transitions;
  double scale = 1.0;                              // geometry length scale

  Index node_count() const { return static_cast<Index>(nodes.size()); }
  Index element_count() const { return static_cast<Index>(elements.size()); }
};

BoundaryMesh mesh_boundary(const std::vector<BoundaryPiece>& pieces, const MeshOptions& options);

// Neighbouring elements (along a piece or across a vertex) whose lengths differ by more
// than `ratio`: one message per boundary or vertex, naming it, with the worst ratio and
// where. A coarse element next to a fine one spoils the fine side's nodes near it.
std::vector<std::string> mesh_quality_warnings(const BoundaryMesh& mesh, double ratio = 3.0);

// The straight pieces with element end points also at those of `points` that lie on the
// mesh's elements (within `tolerance`): each piece's breakpoints are the mesh's own (its grading and
// corner transitions) with those points added. An end point nearer to a new point than
// `snap` of its element's length moves onto it instead (never a piece's end, nor an end point
// that already moved), and a new point nearer than that to one already placed is left out,
// so no element shorter than about `snap` of its neighbours appears (0.35: neighbours of
// equal elements stay within the mesh-quality warning's factor 3). Arcs and pieces without
// elements are returned as they are (a node added on an arc lies off the chord the point
// was on: the polygon of the new chords would cut slivers off cells made on the old one).
std::vector<BoundaryPiece> pieces_with_nodes_at(const BoundaryMesh& mesh, std::vector<BoundaryPiece> pieces,
                                                const std::vector<Vec2>& points, double tolerance,
                                                double snap = 0.35);

// Node at `point` within `tolerance`, or -1.
Index find_node_at(const BoundaryMesh& mesh, const Vec2& point, double tolerance);
// Vertex at `point` within `tolerance`, or -1.
Index find_vertex_at(const BoundaryMesh& mesh, const Vec2& point, double tolerance);

}  // namespace bemcontact::geometry

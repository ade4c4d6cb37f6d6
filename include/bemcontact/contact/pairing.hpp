#pragma once
// Pairs on the potential contact zones (section V.2.2.1), between independently meshed
// zones, or between a zone and a rigid body's contour: each node of body 1's zone is projected along the pair normal (V.2) onto body 2's
// zone (node-to-segment); body 2's displacement there is interpolated from the nodes of
// the element it meets, and the pair's force goes to those nodes with the same weights
// (consistent force transfer). A body-1 node that faces no part of body 2's zone, or
// faces it with a normal that is not opposite, forms no pair: the zones may be declared
// larger than the contact. The initial gap d of the pair (V.3) is measured along the pair
// normal to the true surface of body 2.
#include <array>
#include <string>
#include <vector>

#include "bemcontact/contact/contact_problem.hpp"

namespace bemcontact::contact {

struct ContactPair {
  Index node1 = -1;  // mesh node of body 1
  // Body 2: the element met and the interpolation there, as indices into
  // PreparedContact::zone_nodes2 and the shape function values (summing to 1).
  int count2 = 0;
  std::array<Index, geometry::kMaxElementNodes> zone2{-1, -1, -1};
  std::array<double, geometry::kMaxElementNodes> shape2{0.0, 0.0, 0.0};
  // Body 1's node (on its true surface: a split-corner node of a linear element on an arc
  // stands for the arc point at its parameter) and the point it faces on body 2.
  Vec2 position1, position2;
  Vec2 normal;    // common normal (V.2), pointing out of body 1 toward body 2
  Vec2 tangent;   // (-n_y, n_x)
  double gap = 0.0;     // d = <x2 - x1, n> (V.3) plus the prescribed initial gap
  double interference = 0.0;  // the contact's (applied by its amplitude: ContactModel's loads)
  double weight = 0.0;  // integral of the node's shape function over body 1's zone (2 pi r in axisymmetry)
  bool on_axis = false; // axisymmetric pair on r = 0: no tangential traction by symmetry

  // The pair's frames: w = frame() [u] (rows n, t), and the traction on side 1 from the
  // unknowns x = (lambda_n, tau), p = traction_frame() x (columns -n, t).
  Mat2 frame() const {
    Mat2 q;
    q.row(0) = normal.transpose();
    q.row(1) = tangent.transpose();
    return q;
  }
  Mat2 traction_frame() const {
    Mat2 r;
    r.col(0) = -normal;
    r.col(1) = tangent;
    return r;
  }
};

// One elastic region as meshed for the contact solve: its contact zones and any platen
// marked (nodes split at their ends).
struct PreparedRegion {
  int body = 0, region = 0;       // in ContactProblem::bodies
  std::string label;              // "body 'b'" or "region 'r' of body 'b'", for messages
  bem::BodyDefinition definition;
  geometry::BoundaryMesh mesh;
};

// An end of a contact zone where the boundary runs on smoothly into the next one, with the
// pair next to it: a contact reaching it is clipped by the zone (contact/zone_ends.hpp).
struct SmoothZoneEnd {
  int side = 1;      // the zone of side 1 or side 2
  Index pair = -1;   // the outermost pair at this end (index in the interface's pairs)
  Vec2 position;     // the zone's end vertex
  std::string zone;  // "boundary 'contact' of body 'ball'"
  std::string next;  // the boundary the zone runs on into
};

// The pairs of one contact interface.
struct PreparedInterface {
  int region1 = -1;               // side 1: index into PreparedContact::regions
  std::vector<int> pieces1;       // its zone's pieces, joined end to start (BoundaryRef)
  int region2 = -1;               // side 2 when elastic
  std::vector<int> pieces2;
  int rigid_body = -1;            // side 2 when rigid: index into ContactProblem::bodies
  std::vector<ContactPair> pairs;                    // in the order of body 1's zone
  int unpaired_nodes1 = 0;                           // side-1 zone nodes facing no part of side 2
  std::vector<Index> zone_nodes2;                    // the nodes of side 2's zone, in order
  std::vector<double> zone_weights2;                 // their integration weights
  // Consistent (mortar-type) traction transfer: body 2's nodal tractions are the L2
  // projection of the pairs' tractions onto its zone, t2 = -transfer p with
  // transfer = M22^-1 M21, M21(a, i) = int over body 1's zone of N2_a(y') N1_i(y) (y' the
  // point y faces on body 2) and M22(a, b) = int over body 2's zone of N2_a N2_b (2 pi r
  // in axisymmetry). Matching meshes give the identity; a constant pressure passes as a
  // constant traction whatever the meshes (collocating the forces at body 1's nodes would
  // alias it). Empty for a rigid side 2.
  Matrix transfer;                                   // zone_nodes2 x pairs
  // Mortar pairing (ContactInterface::pairing, elastic side 2; empty otherwise): pair j's
  // jump is the weighted one, w_j = Q_j (u1_j - sum_a mortar(a, j) u2_a), mortar(a, j) =
  // int psi_j N2_a / int psi_j, with psi_j side 1's dual shape function of node j: D =
  // diag(int N1_j) and the constraint D u1 - M^T u2 of the mortar method with dual
  // multipliers [Wohlmuth2000], [Popp2010, weighted gap]; the gap stays the node's. Integrated
  // segment by segment over the overlaps of the two meshes. On matching meshes mortar is
  // the identity (node-to-segment); a field linear along side 1's elements is weighed to
  // its nodal values. A node whose elements leave side 2's zone keeps the collocation.
  Matrix mortar;                                     // zone_nodes2 x pairs
  std::vector<SmoothZoneEnd> smooth_ends;            // zone ends a contact must not reach
};

struct PreparedContact {
  std::vector<PreparedRegion> regions;               // every elastic region, body by body
  std::vector<std::vector<int>> body_regions;        // per body: its indices in regions (none if rigid)
  std::vector<PreparedInterface> contacts;           // as ContactProblem::contacts
  // Body 1's zone much finer than body 2's where they face: more pressure unknowns than
  // body 2's nodes can carry, and the pressures oscillate (Hertz ball, 30 elements against
  // 19: profile 7.7 %, axis pair -12 %; against 25: 0.8 %). Reported, with the remedy.
  std::vector<std::string> warnings;
  // Boundaries under force loads (rigid platens), and the platen of each force load (-1
  // for a force on a rigid body).
  struct Platen {
    int region = -1, piece = -1;
    std::vector<Index> nodes;     // nodes of the boundary
    std::vector<double> weights;  // their integration weights
  };
  std::vector<Platen> platens;
  std::vector<int> platen_of_force;
};

// Meshes and pairs. Throws GeometryError naming the boundaries or the node when no node of
// a side-1 zone faces its side 2, or the bodies initially overlap; InputError for
// references out of range.
PreparedContact prepare_contact(const ContactProblem& problem);

// The nodes and elements of a zone of joined pieces, in order (a node the pieces share
// once).
std::vector<Index> zone_nodes(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces);
std::vector<Index> zone_elements(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces);
// "boundary 'a' of body 'b'", "boundaries 'a', 'c' of region 'r' of body 'b'", for messages.
std::string zone_name(const PreparedRegion& region, const std::vector<int>& pieces);

// Whether the pairs face sideways (every pair normal closer to the x1 axis): their
// abscissa along the zone is then x2 (y, z), otherwise x1 (x, r).
bool zone_faces_sideways(const std::vector<ContactPair>& pairs);

// Integral of each node's shape function over the given pieces' elements, times 2 pi r
// in axisymmetry (4-point Gauss per element on its true geometry: exact for polynomial
// shape functions times r on straight elements).
std::vector<double> node_weights(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces,
                                 const std::vector<Index>& nodes, AnalysisType type);

}  // namespace bemcontact::contact

#pragma once
// Facing node pairs on the potential contact zone (section V.2.2.1). The contact boundary
// of body 1 is cut into one-element pieces at its own element ends; the contact boundary
// of body 2 is cut where the common normals (V.2) through those points meet it, so the
// mesher places facing nodes on the two sides and the user does not hand-match meshes.
// Each node of body 1's zone is then paired with the body-2 node met along the common
// normal; the initial gap d of the pair (V.3) is measured along that normal between the
// actual nodes.
#include <array>
#include <string>
#include <vector>

#include "bemcontact/contact/contact_problem.hpp"

namespace bemcontact::contact {

struct ContactPair {
  Index node1 = -1, node2 = -1;  // mesh nodes of body 1 and body 2
  Vec2 position1, position2;
  Vec2 normal;    // common normal (V.2), pointing out of body 1 toward body 2
  Vec2 tangent;   // (-n_y, n_x)
  double gap = 0.0;     // d = <x2 - x1, n> (V.3), >= 0 when the bodies do not overlap
  double weight = 0.0;  // integral of the node's shape function over body 1's zone (2 pi r in axisymmetry)
  bool on_axis = false; // axisymmetric pair on r = 0: no tangential traction by symmetry
};

struct PreparedContact {
  std::array<bem::BodyDefinition, 2> bodies;         // with the contact boundaries cut
  std::array<geometry::BoundaryMesh, 2> meshes;
  std::array<std::vector<int>, 2> contact_pieces;    // the cut pieces of each zone
  std::vector<ContactPair> pairs;                    // in the order of body 1's zone
  int force_piece = -1;                              // piece of the force load after cutting
  std::vector<Index> loaded_nodes;                   // nodes of the force-loaded boundary
  std::vector<double> loaded_weights;                // their integration weights
};

// Cuts, meshes and pairs. Throws GeometryError naming the boundaries or the node when the
// contact boundaries do not face each other, a node has no facing partner, or the bodies
// initially overlap.
PreparedContact prepare_contact(const ContactProblem& problem);

// Integral of each node's shape function over the given pieces' elements, times 2 pi r
// in axisymmetry (4-point Gauss per element: exact for the linear x linear integrand).
std::vector<double> node_weights(const geometry::BoundaryMesh& mesh, const std::vector<int>& pieces,
                                 const std::vector<Index>& nodes, AnalysisType type);

}  // namespace bemcontact::contact

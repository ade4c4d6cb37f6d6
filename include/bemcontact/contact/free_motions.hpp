#pragma once
// Bodies held only by their contacts (a roller between two plates): the rigid motions that
// a body's own conditions leave free (prescribed displacements, point constraints, a
// force-loaded platen) become unknowns of the contact problem, each pinned by a point
// constraint whose value is the unknown and whose reaction must vanish (the body's
// equilibrium). A free motion that no contact can hold either (no pair normal has a
// component along it: a frictionless roller's rotation) is an error naming the body and
// the motion.
//
// The pins' values are displacements of the nodes they hold, which carry some of the
// body's deformation. What is reported (motions.csv) is the body's rigid motion instead:
// in its free modes, the one nearest to its boundary displacement in least squares.
#include <string>
#include <vector>

#include "bemcontact/contact/pairing.hpp"

namespace bemcontact::contact {

struct FreeMotionConstraint {
  int region = -1;                 // index into PreparedContact::regions
  bem::PointConstraint constraint; // one component, value 0 (the unknown is the variable datum)
};

// The free rigid motions of one body. Modes: translation x, translation y, rotation about
// `centre` (plane); translation z (axisymmetry).
struct FreeBody {
  int body = -1;             // index into ContactProblem::bodies
  std::vector<int> regions;  // its regions (PreparedContact::regions)
  Vec2 centre = Vec2::Zero();  // mean of its boundary nodes
  double scale = 1.0;        // the rotation mode moves a point by (r / scale) per unit
  Matrix free;               // modes x f: orthonormal basis of the modes its conditions leave free
  // The f modes reported (ascending), one per free motion: those that fix a motion of the
  // free space best. A body free in x, y and rotation reports all three; one held in x at a
  // point off its centre reports y and the rotation (x follows from the rotation).
  std::vector<Index> reported;
};

struct FreeMotions {
  std::vector<FreeMotionConstraint> pins;  // one per free motion, body after body
  std::vector<FreeBody> bodies;            // the bodies with free motions, in the problem's order
};

// Throws SolverError naming the body and the motion (translation x / y, rotation; the
// axial translation z in axisymmetry) when a free motion is not held by any contact.
FreeMotions free_motions(const ContactProblem& problem, const PreparedContact& prepared,
                         const std::vector<ContactPair>& pairs, const std::vector<Index>& pair_offsets);

// A mode for messages ("translation x", "rotation") and for output names ("x", "rotation";
// "z" in axisymmetry).
const char* mode_name(Index mode, AnalysisType type);
const char* mode_direction(Index mode, AnalysisType type);

// The reported motions of a free body (FreeBody::reported: translations of its centre,
// rotations in radians, counter-clockwise) from the boundary displacement of each of its
// regions (`displacements[k]` per node of `meshes[k]`): the rigid motion u = modes(x) v,
// v in the span of `free`, minimising the integral over its boundary of |u_h - u|^2 (ds,
// or r ds in axisymmetry; nodal weights: the integrals of the shape functions).
Vector rigid_motion(const FreeBody& body, const std::vector<const geometry::BoundaryMesh*>& meshes,
                    const std::vector<const std::vector<Vec2>*>& displacements, AnalysisType type);

}  // namespace bemcontact::contact

#pragma once
// Bodies held only by their contacts (a roller between two plates): the rigid motions that
// a body's own conditions leave free (prescribed displacements, point constraints, a
// force-loaded platen) become unknowns of the contact problem, each pinned by a point
// constraint whose value is the unknown and whose reaction must vanish (the body's
// equilibrium). A free motion that no contact can hold either (no pair normal has a
// component along it: a frictionless roller's rotation) is an error naming the body and
// the motion.
#include <vector>

#include "bemcontact/contact/pairing.hpp"

namespace bemcontact::contact {

struct FreeMotionConstraint {
  int region = -1;                 // index into PreparedContact::regions
  bem::PointConstraint constraint; // one component, value 0 (the unknown is the variable datum)
};

// Throws SolverError naming the body and the motion (translation x / y, rotation; the
// axial translation z in axisymmetry) when a free motion is not held by any contact.
std::vector<FreeMotionConstraint> free_motion_constraints(const ContactProblem& problem, const PreparedContact& prepared,
                                                          const std::vector<ContactPair>& pairs,
                                                          const std::vector<Index>& pair_offsets);

}  // namespace bemcontact::contact

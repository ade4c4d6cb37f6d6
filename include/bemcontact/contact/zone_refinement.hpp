#pragma once
// Adaptive contact zones (docs/contact.md, "Candidate surfaces"): after a pass over the
// load history, where the contact touched and how finely its edges were resolved, and the
// meshes of the two candidate boundaries for the next pass.
#include <vector>

#include "bemcontact/contact/contact_problem.hpp"
#include "bemcontact/contact/contact_solver.hpp"

namespace bemcontact::contact {

// A side's boundaries joined end to start (BoundaryRef), measured along them as one.
struct SideChain {
  explicit SideChain(std::vector<const geometry::BoundaryPiece*> joined);
  std::vector<const geometry::BoundaryPiece*> pieces;
  std::vector<double> offsets;  // where each piece starts, and the total length last
  double length() const { return offsets.back(); }
  double arc_length_at(const Vec2& point) const;  // of the nearest point
  Vec2 point_at(double arc_length) const;
  // Breakpoints along the whole chain (fractions of its length) as each piece's own.
  std::vector<std::vector<double>> split(const std::vector<double>& breakpoints) const;
  int elements() const;
  double coarsest_element() const;  // the longest element, the size refinement grows back to
};

// Along side 1's boundaries (arc length): the stretch in contact over the whole history and
// the open pairs bracketing it. An end with no open pair beyond it (the zone reaches the
// boundary's end: an axis, a symmetry line, a corner, or the end of side 2) is no edge.
struct ZoneFound {
  bool touched = false;
  double first = 0.0, last = 0.0;            // the outermost pairs in contact
  double before = -1.0, after = -1.0;        // the open pairs bracketing them (-1: no edge)
  double width = 0.0;                        // the widest step's zone, to the edges' midpoints
  int pairs_in_widest = 0;                   // its pairs in contact
  double edge_spacing() const;
};
ZoneFound find_zone(const SideChain& side1, const ContactInterfaceResult& result);

// The pass's record, and the next meshes of the two sides when the pass is not resolved
// (per boundary of the side; empty otherwise, breakpoints2 also empty for a rigid side 2). `declared` is the
// problem as given (its meshes set the coarsest elements), `current` the pass's.
struct ZoneAssessment {
  ZonePass pass;
  std::vector<std::vector<double>> breakpoints1, breakpoints2;
};
ZoneAssessment assess_zone(const ContactProblem& declared, const ContactProblem& current, int contact,
                           const ContactInterfaceResult& result);

// Gives the contact's two sides these meshes, one per boundary (meshed as given: fixed_mesh);
// a side given a different number of meshes than it has boundaries is left as it is.
void set_zone_meshes(ContactProblem& problem, int contact, const std::vector<std::vector<double>>& breakpoints1,
                     const std::vector<std::vector<double>>& breakpoints2);
// A side's meshes as they stand (element end points of each boundary as fractions).
std::vector<std::vector<double>> side_breakpoints(const ContactProblem& problem, const BoundaryRef& side);

}  // namespace bemcontact::contact

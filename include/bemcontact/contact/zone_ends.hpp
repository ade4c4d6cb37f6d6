#pragma once
// The guard against contacts clipped by their declared zones. A zone is where the solver
// pairs nodes; outside it nothing stops the surfaces from interpenetrating. When the pair at
// an end of a zone is in contact and the boundary runs on smoothly past that end, the
// contact would have spread further: the end acts as the edge of a flat punch (a pressure
// singularity, a contact half-width that stops at the zone) and the answer is wrong. A
// zone ending at a corner (a punch's edge, a symmetry line), on the axis of an
// axisymmetric body, or in a bilateral contact (declared bonded) is not clipped.
#include <string>
#include <vector>

#include "bemcontact/contact/pairing.hpp"

namespace bemcontact::contact {

// A zone end turning by less than this into the next boundary continues smoothly (a
// polygonal surface of 10-degree facets still does); at a sharper turn the contact edge
// sits at the corner.
inline constexpr double kZoneCornerDegrees = 30.0;

// The ends of the interface's zones that continue smoothly and have a pair next to them
// (PreparedInterface::smooth_ends). Side 2's outermost pair at an end is the pair facing
// the zone's end element. An end facing a corner of the other side is not among them: the
// contact stops at that corner (a flat punch's edge over a longer support zone).
std::vector<SmoothZoneEnd> smooth_zone_ends(const ContactProblem& problem, const PreparedInterface& contact,
                                            const std::vector<PreparedRegion>& regions);

// Whether side 1's zone starts on a symmetry line x1 = 0 (a straight boundary along it
// with u_n = 0, t_t = 0) or, in axisymmetry, on the axis: the contact is half of one
// symmetric about x1 = 0 (its stick zone's half-width is measured from there).
bool zone_starts_on_symmetry_line(const ContactProblem& problem, const PreparedInterface& contact,
                                  const std::vector<PreparedRegion>& regions);

// Warnings for roller lines (u_n = 0, t_t = 0 on a straight boundary) that meet a contact
// zone at an end: declared symmetry lines are exact there (geometry/symmetry.hpp).
std::vector<std::string> roller_line_warnings(const ContactInterface& contact, const PreparedInterface& prepared,
                                              const std::vector<PreparedRegion>& regions);

// The message (empty when no end is clipped) for a contact whose pairs `in_contact` (per
// pair of the interface) close some smooth end, at load step `step` and pseudo-time `time`;
// `coordinate(i)` is pair i's abscissa along the zone, `axis` its name ("x", "r", "y", "z").
std::string clipped_zone_message(const std::string& contact_name, const PreparedInterface& contact,
                                 const std::vector<bool>& in_contact, const std::vector<double>& coordinate,
                                 const std::string& axis, int step, double time);

}  // namespace bemcontact::contact

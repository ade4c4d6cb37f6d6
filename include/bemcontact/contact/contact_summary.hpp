#pragma once
// The scalars of one contact at one load step, from its pairs: the zone in contact, the
// stick zone (its two ends located between pairs, its half-width and offset), the
// pressures and forces (docs/contact.md, "Contact and stick zones").
#include <vector>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/pairing.hpp"

namespace bemcontact::contact {

// `half_model`: the zone starts on a symmetry line or the axis at coordinate 0
// (zone_starts_on_symmetry_line): the contact and stick zones are then symmetric about 0, and
// the half-width c is measured from there. `previous`: the same contact's summary at the
// previous step (null at the first), for the law of each stick edge. `edge_power`: how the
// pressure vanishes at the contact's edge, p^edge_power linear in the distance to it (2
// unilateral, 1 / m_n under normal compliance). Iterations, residual, time and approach are
// left to the caller.
ContactSummary summarise_pairs(const std::vector<ContactPair>& geometry, const std::vector<PairResult>& pairs,
                               bool half_model, const ContactSummary* previous, double edge_power = 2.0);

// The contact spots: maximal runs of pairs in contact (stick or slip), consecutive in
// `order` (the pairs' indices sorted by coordinate).
int count_spots(const std::vector<PairResult>& pairs, const std::vector<std::size_t>& order);

// Where a stick zone ends beyond its outermost stick pair, at coordinate `outer` =
// inner[0], before the slipping pair at `limit`, from the slip margins m = 1 - |p_t| /
// (beta |p_n|) of the stick pairs at `inner` (from the outermost inward). Near a stick edge
// m vanishes like a power of the distance to it, set by how the edge moves:
//  - receding (slip invades the stick zone: Cattaneo-Mindlin, Mindlin-Deresiewicz,
//    Nowell-Hills): m ~ (c - x)^(1/2), the square-root term of Cattaneo's traction
//    [Johnson1985, 7.2]; m^2 is fitted by a parabola through 4 pairs (a line through 3);
//  - advancing (the stick zone overtakes slip: Spence's growing normal load): the traction is
//    smooth at the edge, m ~ (c - x)^(3/2) (Annex E); m^(2/3) by a line through 2 pairs.
// The fit's zero beyond `outer` is kept before `limit`; without one (too few pairs): midway.
double stick_edge(const std::vector<double>& inner, const std::vector<double>& margins, double limit,
                  StickEdgeLaw law);

}  // namespace bemcontact::contact

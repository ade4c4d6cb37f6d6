#pragma once
// Archard's wear law on the pairs of a contact [Archard1953; McCollDingLeen2004, (1)-(2)]:
// in each load step the worn depth of side s at a pair grows by
//   dh_s = k_s p_n |ds|,
// p_n the pair's pressure at the end of the step and ds its slip increment (the change of
// the tangential jump [u_t] over the step: zero while the pair sticks). The depths add to
// the pair's gap d from the next step on. Small slip: a pair keeps its partner, so side 2's
// depth is that of the point the pair faces.
//
// Cycle jumping [McCollDingLeen2004, section 3]: the part of the history from cycle_start to
// end_time is one load cycle; after a computed cycle, the wear of ΔN - 1 more cycles is
// extrapolated from it (forward Euler in the cycle count) and the next cycle is computed on
// the worn gap. Two rules bound ΔN:
//  - stability: per cycle the depths grow by dh = k S p(h) (S a pair's slip path over the
//    cycle), and a gap change moves the pressures of the pairs in contact by
//    d lambda = -M_cc^-1 dh (M_cc the normal block of the condensed flexibility over them; a
//    force load only removes a uniform part). Forward Euler in N is free of oscillation
//    while ΔN Lambda <= 1, Lambda the largest eigenvalue of M_cc^-1 diag(k S) (the stiffest
//    mode alternates from pair to pair: it is what a too long jump excites first), so
//    ΔN <= 1 / Lambda (cycle_jump_bound);
//  - accuracy (adaptive ΔN): the largest pressure change between the ends of two computed
//    cycles stays within max_pressure_change of the peak pressure; a jump that exceeds it is
//    undone and halved, one that changed them by less than half of it doubles ΔN.
#include <vector>

#include "bemcontact/contact/pairing.hpp"
#include "bemcontact/core/types.hpp"

namespace bemcontact::contact {

// Per pair: Archard's coefficient k of each side (0: that side does not wear).
struct WearCoefficients {
  Vector side1, side2;
  bool any() const { return side1.size() > 0 && (side1.maxCoeff() > 0.0 || side2.maxCoeff() > 0.0); }
};

// Per pair: the worn depth of each side so far.
struct WearDepths {
  Vector side1, side2;
  Vector total() const { return side1 + side2; }
};

// One step's wear: h_s += k_s lambda_n |w_t - w_t(previous step)| per pair, from the step's
// unknowns x = (lambda_n, tau) and jump w = (w_n, w_t) per pair.
void add_step_wear(const WearCoefficients& k, const Vector& x, const Vector& w, const Vector& previous_tangential_jump,
                   WearDepths& depths);

// The worn volume sum_i weight_i h_i over pairs [first, last) (area per unit thickness in
// plane problems; the weights carry 2 pi r in axisymmetry).
double worn_volume(const std::vector<ContactPair>& pairs, const Vector& depth, Index first, Index last);

// The largest pressure change between two solutions x = (lambda_n, tau) per pair, relative
// to the earlier peak pressure (0 when nothing presses).
double relative_pressure_change(const Vector& before, const Vector& after);

// 1 / Lambda: the longest stable jump (see above) for the flexibility M (2N x 2N, rows and
// columns (w_n, w_t) per pair), the solution x = (lambda_n, tau) per pair (the pairs with
// lambda_n > 0 are in contact) and each pair's wear rate k S per unit pressure; infinity
// when nothing in contact wears. Inverse power iteration on M_cc^-1 diag(k S).
double cycle_jump_bound(const Matrix& M, const Vector& x, const Vector& wear_rate);

// Adaptive cycle jumping: after a jump of `jump` cycles that changed the pressures by
// `change` (relative), whether to undo it, and the next jump.
struct CycleJumpControl {
  long max_jump = 1;
  double max_pressure_change = 0.05;
  bool reject(long jump, double change) const { return jump > 1 && change > max_pressure_change; }
  long next(long jump, double change) const;
};

}  // namespace bemcontact::contact

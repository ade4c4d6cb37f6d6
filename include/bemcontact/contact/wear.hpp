#pragma once
// Archard's wear law on the pairs of a contact [Archard1953] (the form of [McCollDingLeen2004]):
// in each load step the worn depth of side s at a pair grows by
//   dh_s = k_s p_n |ds|,
// p_n the pair's pressure at the end of the step and ds its slip increment (the change of
// the tangential jump [u_t] over the step: zero while the pair sticks). The depths add to
// the pair's gap d from the next step on. Small slip: a pair keeps its partner, so side 2's
// depth is that of the point the pair faces.
//
// Cycle jumping [McCollDingLeen2004]: the part of the history from cycle_start to
// end_time is one load cycle; after a computed cycle, the wear of tau = ΔN - 1 more cycles
// is extrapolated from it and the next cycle is computed on the worn gap. Per cycle the
// depths grow by r(h) ~ D p(h) (D = k S, S a pair's slip path over the cycle), and a gap
// change moves the pressures of the pairs in contact by dp = G dh, G the normal block of the
// inverse of the condensed problem bordered by its motions (pressure_response: a force
// load's approach follows, so a uniform wear under a force leaves the pressures alone). The
// explicit jump dh = tau r is stable only while tau |eig(D G)| <= 1, which the stiffest,
// pair-to-pair alternating mode limits to tens of cycles on fine meshes; the jump is
// linearly implicit instead (Rosenbrock-Euler),
//   (I - tau D G) dh = tau r,
// stable for every ΔN and first order in it like the explicit one. ΔN then follows accuracy
// (adaptive ΔN): the largest pressure change between the ends of two computed cycles stays
// within max_pressure_change of the peak pressure; a jump that exceeds it is undone and
// halved, one that changed them by less than half of it doubles ΔN.
#include <vector>

#include "bemcontact/contact/pairing.hpp"
#include "bemcontact/core/types.hpp"

namespace bemcontact::contact {

// Per pair: Archard's coefficient k of each side (0: that side does not wear).
struct WearCoefficients {
  Vector side1, side2;
  bool any() const { return side1.size() > 0 && (side1.maxCoeff() > 0.0 || side2.maxCoeff() > 0.0); }
};

// Per pair: the worn depth of each side so far, and the slip path sum |ds| since it was last
// reset (the current cycle's S; empty: not kept).
struct WearDepths {
  Vector side1, side2;
  Vector slip_path;
  Vector total() const { return side1 + side2; }
};

// One step's wear: h_s += k_s lambda_n |w_t - w_t(previous step)| per pair, from the step's
// unknowns x = (lambda_n, tau) and jump w = (w_n, w_t) per pair; the slip path grows by |ds|.
void add_step_wear(const WearCoefficients& k, const Vector& x, const Vector& w, const Vector& previous_tangential_jump,
                   WearDepths& depths);

// The worn volume sum_i weight_i h_i over pairs [first, last) (area per unit thickness in
// plane problems; the weights carry 2 pi r in axisymmetry).
double worn_volume(const std::vector<ContactPair>& pairs, const Vector& depth, Index first, Index last);

// The largest pressure change between two solutions x = (lambda_n, tau) per pair, relative
// to the earlier peak pressure (0 when nothing presses).
double relative_pressure_change(const Vector& before, const Vector& after);

// G (above) at the solution x = (lambda_n, tau) per pair of the condensed problem: the pairs
// with lambda_n > 0 are in contact; the tangential tractions are held.
struct PressureResponse {
  std::vector<Index> closed;  // the pairs in contact
  Matrix G;                   // d lambda_closed / d gap_closed
};
PressureResponse pressure_response(const Matrix& M, const Matrix& b, const Matrix& f, const Matrix& f_delta,
                                   const Vector& x);

// The linearly implicit jump (above): per pair, the extra depth of tau more cycles from the
// last computed cycle's wear r and the wear rate D = k S per unit pressure.
Vector implicit_jump(const PressureResponse& response, const Vector& wear_rate, const Vector& cycle_wear, double tau);

// The jump of tau cycles after the computed cycle that began at `at_cycle_start`: r its wear,
// D = (k_1 + k_2) S from its slip path, the extra depth shared between the sides as their
// coefficients.
void add_cycle_jump(const WearCoefficients& k, const PressureResponse& response, const WearDepths& at_cycle_start,
                    double tau, WearDepths& depths);

// Adaptive cycle jumping: after a jump of `jump` cycles that changed the pressures by
// `change` (relative), whether to undo it, and the next jump.
struct CycleJumpControl {
  long max_jump = 1;
  double max_pressure_change = 0.05;
  bool reject(long jump, double change) const { return jump > 1 && change > max_pressure_change; }
  long next(long jump, double change) const;
};

}  // namespace bemcontact::contact

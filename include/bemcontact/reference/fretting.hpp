#pragma once
// Partial slip of a cylinder on a half-plane (plane problems, elastically similar bodies so
// that the normal and tangential problems uncouple): a normal force P (Hertz line contact,
// half-width a, peak p0), then a tangential force Q with Coulomb friction mu.
//  - Cattaneo-Mindlin, Q raised monotonically: stick zone |x| < c, c/a = sqrt(1 - Q/(mu P)),
//      q(x) = mu p0 sqrt(1 - x^2/a^2) - mu p0 (c/a) sqrt(1 - x^2/c^2) [|x| < c]
//    (Johnson, Contact Mechanics, section 7.2).
//  - Mindlin-Deresiewicz, Q raised to Q* then lowered to Q: a reversal slip zone
//    c' < |x| < a with c'/a = sqrt(1 - (Q* - Q)/(2 mu P)),
//      q(x) = q_C(x; c*) - 2 q_C(x; c'),   q_C(x; c) the Cattaneo distribution above.
//  - The energy dissipated per cycle of Q between +Q* and -Q* (derived in docs/contact.md):
//      E = (32 mu^2 P^2 / (pi^2 E*)) I(c*/a),
//      I(g) = int_g^1 sqrt(1 - s^2) [s sqrt(s^2 - g^2) - g^2 acosh(s/g)] ds,
//    per unit length, E* the plane contact modulus of the pair.
// Shear tractions are those on the body the force Q pushes (q > 0 opposes a positive Q).
#include "bemcontact/reference/hertz.hpp"

namespace bemcontact::reference {

struct PartialSlipLine {
  HertzLineContact hertz;
  double friction = 0.3;

  double stick_ratio(double Q) const;                          // c/a
  double shear(double x, double Q) const;                      // monotone loading to Q
  double reversal_stick_ratio(double Q_star, double Q) const;  // c'/a
  double unloading_shear(double x, double Q_star, double Q) const;
  double dissipated_energy_per_cycle(double Q_star) const;
};

}  // namespace bemcontact::reference

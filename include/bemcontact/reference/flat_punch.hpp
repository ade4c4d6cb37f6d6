#pragma once
// Rigid flat punch of half-width a pressed without friction on an elastic half-plane
// (Sadowsky; [Johnson1985, (2.64)]), plane problem, load P per unit length:
//   p(x) = P / (pi sqrt(a^2 - x^2))  for |x| < a, 0 outside (integrable edge singularity).
// Frame: x1 along the surface from the centre of the punch; the half-plane lies below its
// surface, depth into it. The punch face stays flat: the indentation (normal displacement
// into the body) is uniform under the punch, and outside it falls by
//   indentation(0) - indentation(x) = 2 P / (pi E') acosh(|x| / a),   |x| >= a,
// with E' = E/(1 - nu^2) in plane strain and E in plane stress (contact_modulus(body, type)).
// The absolute indentation of a half-plane is defined only up to a constant (logarithmic
// far field), hence the relative form.
// With a moment M about the centre (M = int p x dx: the pressure larger at +x), while the
// whole face stays in contact (|M| <= P a / 2):
//   p(x) = (P + 2 M x / a^2) / (pi sqrt(a^2 - x^2)),
// and the face tilts by eps = 4 M / (pi a^2 E') (down at +x). Derivation: p = A x /
// sqrt(a^2 - x^2) has moment A pi a^2 / 2, and in the half-plane's surface equation
// du_n/dx = -(2 / (pi E')) PV int p(s) / (x - s) ds the integral of s / ((x - s)
// sqrt(a^2 - s^2)) over (-a, a) is -pi for |x| < a, so the slope is the constant 2 A / E'.
#include "bemcontact/core/types.hpp"

namespace bemcontact::reference {

struct FlatPunchPlane {
  double load = 1.0;        // P per unit length
  double half_width = 1.0;  // a
  double plane_modulus = 1.0;  // E' of the half-plane
  double moment = 0.0;         // M about the centre

  double pressure(double x) const;
  // indentation(0) - indentation(x): 0 under the punch, 2P/(pi E') acosh(|x|/a) outside.
  double indentation_drop(double x) const;  // (without a moment)
  double tilt() const;                      // eps = 4 M / (pi a^2 E')
};

}  // namespace bemcontact::reference

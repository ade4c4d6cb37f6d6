#pragma once
// Rigid flat punch of half-width a pressed without friction on an elastic half-plane
// (Sadowsky; Johnson (2.64)), plane problem, load P per unit length:
//   p(x) = P / (pi sqrt(a^2 - x^2))  for |x| < a, 0 outside (integrable edge singularity).
// Frame: x1 along the surface from the centre of the punch; the half-plane lies below its
// surface, depth into it. The punch face stays flat: the indentation (normal displacement
// into the body) is uniform under the punch, and outside it falls by
//   indentation(0) - indentation(x) = 2 P / (pi E') acosh(|x| / a),   |x| >= a,
// with E' = E/(1 - nu^2) in plane strain and E in plane stress (contact_modulus(body, type)).
// The absolute indentation of a half-plane is defined only up to a constant (logarithmic
// far field), hence the relative form.
#include "bemcontact/core/types.hpp"

namespace bemcontact::reference {

struct FlatPunchPlane {
  double load = 1.0;        // P per unit length
  double half_width = 1.0;  // a
  double plane_modulus = 1.0;  // E' of the half-plane

  double pressure(double x) const;
  // indentation(0) - indentation(x): 0 under the punch, 2P/(pi E') acosh(|x|/a) outside.
  double indentation_drop(double x) const;
};

}  // namespace bemcontact::reference

#pragma once
// Spence's partial-slip solution for a frictional indentation under a monotonically
// increasing normal load (Annex E, [CON 13]). The contact of radius a splits into a central
// stick region r < c a and an outer slip ring; c depends only on the friction coefficient
// beta and on the bimaterial constant gamma, not on the load. Relation (E.1):
//   beta = gamma / (2 c K1(c)) ln((1 + c) / (1 - c)),   K1(c) = K(sqrt(1 - c^2)),
// K the complete elliptic integral of the first kind (modulus convention K(k)). Since
// K(sqrt(1 - c^2)) = pi / (2 AGM(1, c)), beta = gamma AGM(1, c) ln((1+c)/(1-c)) / (pi c),
// which increases strictly from 0 (c -> 0) to infinity (c -> 1): one root for beta > 0.
//
// Scope: (E.1) is Spence's AXISYMMETRIC result (Annex E: "un demi-espace et un indenteur
// axisymetrique"); it holds for a flat circular punch and for the Hertzian sphere alike
// (the same c for both: "valable pour un indenteur plat ou de forme elliptique"). The normal
// pressure is the frictionless one: per [thesis.md, Spence's (E.1)], (E.1) neglects the coupling of
// the shear traction into the normal displacement, and a computation that keeps it gives
// c = 0.513 instead of 0.530 in the thesis case. It is not a plane (2D strip) result: with
// the plane-stress gamma = 0.26 of the thesis' rigid punch (V.5.1) it would give c = 0.29 at
// beta = 0.1, far from the stick zone found there (3.87 of a half-width near 5).
// Thesis case (V.5.2.4): gamma = 0.18908 gives c = 0.530 for beta = 0.1 and 0.9999 for 0.6.
#include "bemcontact/core/types.hpp"

namespace bemcontact::reference {

// Bimaterial constant (E.2), Dundurs' beta:
//   gamma = [ (1 - 2 nu1)/(2 G1) - (1 - 2 nu2)/(2 G2) ] / [ (1 - nu1)/G1 + (1 - nu2)/G2 ].
// Signed (it changes sign with the order of the bodies; only |gamma| enters (E.1)). A rigid
// body (E = infinity) gives (E.3): |gamma| = (1 - 2nu)/(2(1 - nu)). Plane stress uses
// nu/(1+nu) in place of nu (the plane-strain form of the plane-stress Hooke law, II.3.1).
// Thesis: E = 432000 and 72000, nu = 0.32 both: gamma = -0.18908 (ball first).
double spence_gamma(const Material& body1, const Material& body2,
                    AnalysisType type = AnalysisType::axisymmetric);

// K1(c) = K(sqrt(1 - c^2)) for 0 < c <= 1, by the arithmetic-geometric mean.
double complementary_elliptic_k(double c);

// Right-hand side of (E.1): the friction coefficient for which c is the stick ratio.
double spence_friction_coefficient(double stick_ratio, double gamma);

// Stick ratio c = (stick radius)/(contact radius) solving (E.1) for beta > 0 and
// 0 < |gamma| <= 1/2, by bracketed bisection (geometric near 0 and 1, so that roots like
// 1 - 1e-4 or 1e-30 are found to full precision). Returns 0 or the largest double below 1
// when the root is not representable. Throws bemcontact::Error for invalid arguments.
double spence_stick_ratio(double friction_coefficient, double gamma);

}  // namespace bemcontact::reference

#pragma once
// A rigid wavy surface pressed without friction on an elastic half-plane (plane problem),
// Westergaard's solution [Westergaard1939], [Johnson1985, §13.2]. The gap before loading is
//   g(x) = Delta (1 - cos(2 pi x / lambda))   (amplitude Delta, crests at x = k lambda),
// and the mean pressure p_bar (load per wavelength / lambda) and the half-width a of each
// crest's contact are related by
//   p_bar = p* sin^2(pi a / lambda),   p* = pi E' Delta / lambda,
// p* being the mean pressure of complete contact (p = p* (1 + cos(2 pi x / lambda))). The
// pressure under a crest, |x| <= a:
//   p(x) = (2 p_bar / sin^2(pi a / lambda)) cos(pi x / lambda) sqrt(sin^2(pi a / lambda) -
//          sin^2(pi x / lambda)).
// (Equation numbers are not cited: they could not be checked here.) Checks: p(x) integrates
// to p_bar lambda over the crest; for a << lambda the crest has curvature 1/R =
// 4 pi^2 Delta / lambda^2 and the load per wave p_bar lambda = pi^3 E' Delta a^2 / lambda^2
// is 2D Hertz's pi a^2 E' / (4 R).
// E' = E/(1 - nu^2) in plane strain (contact_modulus(body, type)).
namespace bemcontact::reference {

struct WavyContact {
  double wavelength = 1.0;     // lambda
  double amplitude = 1.0;      // Delta (half the peak-to-valley height)
  double plane_modulus = 1.0;  // E'

  double full_contact_pressure() const;            // p*
  double mean_pressure(double half_width) const;   // p_bar(a), a in [0, lambda / 2]
  double half_width(double mean_pressure) const;   // a(p_bar), p_bar in [0, p*]
  double pressure(double x, double half_width) const;  // p(x) of the crest at 0 (0 outside |x| <= a)
};

}  // namespace bemcontact::reference

#pragma once
// A rigid cylinder of radius R pressed into a Winkler foundation (plane problem): an
// interface whose pressure follows its local interpenetration alone, p = c_n pen^m (normal
// compliance [OdenMartins1985] on a rigid substrate, or on a body much stiffer than the
// interface). With the approach delta and the circle's gap g(x) = R - sqrt(R^2 - x^2),
//   pen(x) = delta - g(x),   p(x) = c_n pen(x)^m on |x| < a,   a = sqrt(2 R delta - delta^2),
//   P = 2 int_0^a p dx.
// With the parabolic gap x^2 / 2R the load has the closed form P = c_n delta^m a' B(1/2, m + 1)
// (a' = sqrt(2 R delta), B Euler's beta; m = 1: 4/3 c_n a' delta), which this takes as the
// first guess; the circle's gap differs from it by x^4 / 8R^3 (0.24 % of delta at a = 0.1 R),
// more than a fine mesh's error, so P(delta) is integrated (composite Simpson, 4096 panels
// with x = a (1 - s^2) clustering them at the edge, where pen^m has its kink) and solved for
// delta by bisection.
namespace bemcontact::reference {

struct WinklerCylinder {
  double load = 1.0;       // P per unit length
  double radius = 1.0;     // R
  double stiffness = 1.0;  // c_n
  double exponent = 1.0;   // m >= 1

  double approach() const;          // delta
  double half_width() const;        // a
  double pressure(double x) const;  // p(x), 0 outside |x| < a
  double max_pressure() const { return pressure(0.0); }
  double load_at(double approach) const;  // P(delta)
};

}  // namespace bemcontact::reference

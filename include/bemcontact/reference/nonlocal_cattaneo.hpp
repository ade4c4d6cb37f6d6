#pragma once
// Cattaneo's partial slip of two cylinders of the same material (plane, half-planes: the
// pressure is Hertz's whatever the shear) under a tangential force Q < mu P applied after P,
// with the non-local Coulomb law of Oden and Pires [OdenPires1983]: in the slip zones c <
// |x| < a the shear is mu (omega * p)(x), the Hertz pressure p0 sqrt(1 - x^2/a^2) (0 outside
// the contact) mollified by the unit-integral C-infinity bump of radius rho (the whole-line
// kernel, contact/nonlocal_friction.hpp); in the stick zone |x| < c the tangential surface
// strain vanishes:
//   (1/pi) PV int_{-a}^{a} q(t) / (x - t) dt = 0,   |x| < c.
// Solved without the boundary elements: q = f + r with f = mu (omega * p) on [-a, a] and r on
// [-c, c]; then (1/pi) PV int r / (x - t) = -h(x), h the same transform of f, whose bounded
// solution is r(c tau) = sum_n b_n sqrt(1 - tau^2) U_{n-1}(tau) when -h(c xi) = sum_n b_n
// T_n(xi) [Erdogan, Gupta & Cook 1973; (1/pi) PV int sqrt(1 - t^2) U_{n-1}(t) / (x - t) dt =
// T_n(x)], the b_n by Gauss-Chebyshev projection. Q = int f + (pi / 2) c b_1 fixes c
// (bisection). rho -> 0 gives Cattaneo's q = mu p0 (sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2))
// and Q / mu P = 1 - c^2 / a^2 [Johnson1985, (7.13)].
#include <vector>

namespace bemcontact::reference {

class NonlocalCattaneo {
 public:
  // a: the contact half-width; p0: Hertz's peak pressure; mu: the friction coefficient; rho:
  // the kernel radius (0: the local law); q_over_mu_p: Q / (mu P) in [0, 1).
  NonlocalCattaneo(double a, double p0, double mu, double rho, double q_over_mu_p);

  double stick_half_width() const { return c_; }
  double shear(double x) const;          // q(x) on |x| <= a (0 outside)
  double mollified_pressure(double x) const;  // (omega * p)(x)

 private:
  double slip_shear(double x) const { return mu_ * mollified_pressure(x); }  // f
  double transform(double x) const;      // h(x) = (1/pi) PV int_{-a}^{a} f(t) / (x - t) dt
  void solve_stick(double c);            // b_n for the stick zone [-c, c]
  double force(double c);                // Q(c)

  double a_, p0_, mu_, rho_;
  double kernel_norm_ = 1.0;
  double c_ = 0.0;
  std::vector<double> b_;  // b_1, b_2, ... (odd n only are non-zero)
  std::vector<double> nodes_, weights_, slip_values_;  // quadrature of [-a, a], f there
  double slip_integral_ = 0.0;                          // int_{-a}^{a} f
};

}  // namespace bemcontact::reference

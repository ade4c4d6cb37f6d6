#pragma once
// The one-parameter family of integrals behind every axisymmetric ring kernel (Annex B).
//
// A source point x = (R, 0, Z) and the circle of field points y(theta) = (r cos t, r sin t, z)
// are at distance rho with
//   rho^2 = s^2 + 4 r R u,   u = (1 - cos theta)/2,   s^2 = (r - R)^2 + (z - Z)^2,
// and with theta = pi - 2 psi (so u = cos^2 psi), A = (r + R)^2 + (z - Z)^2, m = 4 r R / A,
// m1 = 1 - m = s^2 / A:   rho^2 = A (1 - m sin^2 psi). Every ring integral of a 3D Kelvin
// kernel is then a sum of
//   int_0^{2 pi} u^j rho^{-(2p+1)} dtheta = 4 A^{-(p+1/2)} H(p, j),
//   H(p, j) = int_0^{pi/2} cos^{2j} psi (1 - m sin^2 psi)^{-(p+1/2)} dpsi
//           = (1/2) B(1/2, j+1/2) 2F1(p+1/2, 1/2; j+1; m),
// for p = 0..3 (rho^-1 ... rho^-7) and j = 0..p+1 (the kernels' numerators, written as
// polynomials in u, never have a higher degree).
//
// For m >= 0.2 (0.45 when p = 3 is asked) the H come from K(m), E(m) by exact recurrences;
// below, where those recurrences divide by powers of m, from the trapezoidal rule in psi
// (spectrally accurate: the integrand is periodic and analytic). Both to ~1e-13 relative.
//
// As m -> 1 (field point close to the source) H(p, j) = H_reg + H_log ln(1/m1), with H_log
// analytic in m1 and H_reg analytic apart from a pole m1^{j-p} when j < p
// [AbramowitzStegun1972, 15.3.10-12]. ring_integral_log_parts returns the H_log, from their power series.
#include <array>

namespace bemcontact::kernels {

constexpr int kRingMaxP = 3;

struct RingIntegrals {
  std::array<std::array<double, kRingMaxP + 2>, kRingMaxP + 1> h{};  // h[p][j]
};

// 0 <= m < 1, m1 = 1 - m > 0 formed without cancellation; p = 0..max_p (max_p <= 3).
void ring_integrals(double m, double m1, int max_p, RingIntegrals& out);

// Coefficients H_log(p, j) of ln(1/m1), for 0 < m1 <= 0.5.
void ring_integral_log_parts(double m1, int max_p, RingIntegrals& out);

}  // namespace bemcontact::kernels

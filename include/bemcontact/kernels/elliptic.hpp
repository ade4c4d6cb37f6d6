#pragma once
// Complete elliptic integrals of the first and second kind (Annex B), in the parameter
// m = k^2:
//   K(m) = int_0^{pi/2} (1 - m sin^2 a)^{-1/2} da,   E(m) = int_0^{pi/2} (1 - m sin^2 a)^{1/2} da,
// by the arithmetic-geometric mean, to full double precision for 0 <= m < 1.
//
// Near m = 1 (a ring kernel whose field point approaches the source) K grows like
// ln(4 / sqrt(1 - m)) (section II.4.4.1). The complementary parameter m1 = 1 - m is then
// passed in separately, formed without cancellation by the caller (m1 = s^2 / A for the ring
// kernels), so K and E keep their relative precision however close m is to 1.
namespace bemcontact::kernels {

struct CompleteElliptic {
  double K = 0.0;
  double E = 0.0;
};

// m in [0, 1), m1 = 1 - m in (0, 1]; m + m1 = 1 up to rounding.
CompleteElliptic complete_elliptic(double m, double m1);
inline double elliptic_k(double m) { return complete_elliptic(m, 1.0 - m).K; }
inline double elliptic_e(double m) { return complete_elliptic(m, 1.0 - m).E; }

// Logarithmic split as m -> 1:
//   K(m) = K_reg + K_log ln(1/m1),   E(m) = E_reg + E_log ln(1/m1),
// with K_log = K(m1)/pi, E_log = (K(m1) - E(m1))/pi and K_reg, E_reg analytic in m1 at 0
// (K_reg(0) = ln 4, E_reg(0) = 1). This is the subtraction of section II.4.4.1 done exactly
// (the thesis subtracts only the leading -ln s of K). For 0 < m1 <= 1/2.
struct EllipticLogSplit {
  double K_reg = 0.0, K_log = 0.0;
  double E_reg = 0.0, E_log = 0.0;
};
EllipticLogSplit elliptic_log_split(double m, double m1);

}  // namespace bemcontact::kernels

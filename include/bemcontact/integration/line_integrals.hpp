#pragma once
// Closed-form integrals along a straight element in its local frame (Annex C, re-derived).
// The source x projects on the element's line at xi = 0; the field point is
// y = x + xi t + h n with xi in [xi1, xi2] and rho^2 = xi^2 + h^2 (h = signed distance).
// Every Kelvin-kernel integrand with a linear shape function reduces to
//   int xi^p h^q / rho^(2m) dxi   and   int xi^k ln(rho^2) dxi,
// written here with the subtended angle theta = int h / rho^2 = atan2(h L, xi1 xi2 + h^2)
// and differences of rational terms in factored form, so that h -> 0 (collinear sources),
// near sources and far sources stay accurate. Names: x<p>h<q>_r<2m> = int xi^p h^q / rho^2m.
// Internal header of the plane integrator; tested in tests/unit/integration.
#include <algorithm>
#include <cmath>

namespace bemcontact::integration::detail {

// Integrals for the displacement (U) and traction (T) kernels, m <= 2, p + 1 <= 3.
struct LineIntegrals {
  double length = 0.0;   // xi2 - xi1
  double h = 0.0;
  double theta = 0.0;    // x0h1_r2 = int h / rho^2 (subtended angle)
  double lambda = 0.0;   // x1h0_r2 = int xi / rho^2 = ln(rho2 / rho1)
  double log0 = 0.0;     // int ln rho^2
  double log1 = 0.0;     // int xi ln rho^2
  double x2_r2 = 0.0;    // int xi^2 / rho^2
  double x3_r2 = 0.0;    // int xi^3 / rho^2
  double x2h1_r4 = 0.0;  // int h xi^2 / rho^4
  double x0h3_r4 = 0.0;  // int h^3 / rho^4
  double x1h2_r4 = 0.0;  // int h^2 xi / rho^4
  double x3h1_r4 = 0.0;  // int h xi^3 / rho^4
  double x1h3_r4 = 0.0;  // int h^3 xi / rho^4
  double x2h2_r4 = 0.0;  // int h^2 xi^2 / rho^4
  // Raw pieces reused by the stress integrals.
  double q1 = 0.0, q2 = 0.0;   // rho^2 at the ends
  double xi1 = 0.0, xi2 = 0.0;
  double xi_sum = 0.0;         // xi1 + xi2
  double xi_product = 0.0;     // xi1 xi2
  double q_product = 0.0;      // q1 q2
};

// Odd series for |x| <= 0.1: atanh(x) = x + x^3/3 + ..., atan(x) = x - x^3/3 + ...; nine
// terms leave a truncation below x^19/19 < 1e-19 |x|. For a source more than ~10 element
// lengths away both arguments below are that small, and two short polynomials replace
// log1p and atan (~45 ns of the ~100 ns budget of one element integral). Estrin's scheme
// keeps the dependency chain short (the build has no FMA).
inline double odd_series(double x, double s) {  // s = +1: atanh, s = -1: atan
  const double y = s * x * x, y2 = y * y, y4 = y2 * y2;
  const double p01 = 1.0 + y * (1.0 / 3), p23 = 1.0 / 5 + y * (1.0 / 7);
  const double p45 = 1.0 / 9 + y * (1.0 / 11), p67 = 1.0 / 13 + y * (1.0 / 15);
  const double p = (p01 + y2 * p23) + y4 * ((p45 + y2 * p67) + y4 * (1.0 / 17));
  return x * p;
}
inline double atanh_small(double x) { return odd_series(x, 1.0); }
inline double atan_small(double x) { return odd_series(x, -1.0); }
constexpr double kSeriesLimit = 0.1;

// Off the element (rho > 0 on [xi1, xi2]). `length` must be xi2 - xi1 as computed by the
// caller (not a separately stored element length: the formulas mix both, and a mismatch of
// one rounding acts like a gap at the end near the source). A source on an end point is a
// misuse (the T integrals diverge); rho^2 is then floored at (1e-30 L)^2 so that every
// result, down to the (q1 q2)^-2 of the stress integrals, stays finite.
[[gnu::always_inline]] inline LineIntegrals line_integrals(double xi1, double xi2, double h,
                                                           double length) {
  LineIntegrals r;
  r.length = length;
  r.h = h;
  r.xi1 = xi1;
  r.xi2 = xi2;
  const double floor = 1e-60 * length * length;
  const double h2 = h * h;
  const double q1 = std::max(xi1 * xi1 + h2, floor);
  const double q2 = std::max(xi2 * xi2 + h2, floor);
  const double sum = xi1 + xi2, product = xi1 * xi2;
  const double dq = length * sum;  // q2 - q1, exact in factored form
  r.q1 = q1;
  r.q2 = q2;
  r.xi_sum = sum;
  r.xi_product = product;
  r.q_product = q1 * q2;

  // theta = atan2(h L, xi1 xi2 + h^2): tan(theta2 - theta1) with theta_i = atan(xi_i / h).
  const double h_length = h * length, denominator = product + h2;
  if (denominator > 0.0) {
    const double z = h_length / denominator;
    r.theta = std::abs(z) <= kSeriesLimit ? atan_small(z) : std::atan(z);
  } else {
    r.theta = std::atan2(h_length, denominator);  // projection on the element, |theta| > pi/2
  }
  // lambda = ln(rho2 / rho1) = 2 atanh((q2 - q1) / (q2 + q1)), by the series when the ratio
  // is near 1 (far sources); otherwise |lambda| > 0.1 and the log of the ratio is accurate.
  const double y = dq / (q1 + q2);
  r.lambda = std::abs(y) <= kSeriesLimit ? atanh_small(y) : 0.5 * std::log(q2 / q1);
  // The log integrals are written around the log of the larger rho^2 so that no two terms of
  // size R ln R cancel for a far source (R >> L) and q ln q -> 0 at a near end:
  //   [xi ln q] = L ln q2 + 2 xi1 lambda = L ln q1 + 2 xi2 lambda,
  //   [q ln q] / 2 = q1 lambda + dq ln q2 / 2 = q2 lambda + dq ln q1 / 2.
  const double h_theta = h * r.theta;
  double xi_log_jump, q_log_half_jump;
  if (q2 >= q1) {
    const double l2 = std::log(q2);
    xi_log_jump = length * l2 + 2.0 * xi1 * r.lambda;
    q_log_half_jump = q1 * r.lambda + 0.5 * dq * l2;
  } else {
    const double l1 = std::log(q1);
    xi_log_jump = length * l1 + 2.0 * xi2 * r.lambda;
    q_log_half_jump = q2 * r.lambda + 0.5 * dq * l1;
  }
  r.log0 = xi_log_jump - 2.0 * length + 2.0 * h_theta;  // [xi ln rho^2 - 2 xi + 2 h atan(xi/h)]
  r.log1 = q_log_half_jump - 0.5 * dq;                   // [(rho^2 ln rho^2 - rho^2) / 2]
  r.x2_r2 = length - h_theta;
  r.x3_r2 = 0.5 * dq - h2 * r.lambda;

  const double inv_qq = 1.0 / r.q_product;
  const double jump_h_xi_r2 = h * length * (h2 - product) * inv_qq;  // [h xi / rho^2]
  r.x2h1_r4 = 0.5 * (r.theta - jump_h_xi_r2);                         // by parts
  r.x0h3_r4 = 0.5 * (r.theta + jump_h_xi_r2);                         // theta - x2h1_r4
  r.x1h2_r4 = 0.5 * h2 * dq * inv_qq;                                 // [-h^2 / (2 rho^2)]
  r.x3h1_r4 = h * r.lambda - h * r.x1h2_r4;
  r.x1h3_r4 = h * r.x1h2_r4;
  r.x2h2_r4 = h * r.x2h1_r4;
  return r;
}

// Additional integrals for the interior-stress kernels D and S. The S kernel components are
// O(1/rho^2); integrated one by one they are O(1/h) while their sums are O(1/L) (the
// leading parts cancel, as a uniform displacement on an infinite line gives no stress), so
// S is integrated per component combination, whose primitives are rational (plus theta or
// lambda) with no 1/h: with xi = h tan(phi), dxi / rho^2 = dphi / h and e.g.
// int (1/rho^2 - 8 h^2 xi^2/rho^6) dxi = int cos(4 phi) dphi / h = [xi (h^2 - xi^2) / rho^4].
struct StressLineIntegrals {
  double x3_r4 = 0.0;  // int xi^3 / rho^4
  double x4_r4 = 0.0;  // int xi^4 / rho^4
  // S combinations and their first moments (the same integrand times xi):
  double tt0 = 0.0, tt1 = 0.0;        // 2 xi h / rho^4 - 8 xi^3 h / rho^6
  double cross0 = 0.0, cross1 = 0.0;  // 1 / rho^2 - 8 xi^2 h^2 / rho^6
  double odd0 = 0.0, odd1 = 0.0;      // 2 xi h / rho^4 - 8 xi h^3 / rho^6
  double nn0 = 0.0, nn1 = 0.0;        // 1 / rho^2 + 4 h^2 / rho^4 - 8 h^4 / rho^6
};

inline StressLineIntegrals stress_line_integrals(const LineIntegrals& b) {
  StressLineIntegrals s;
  const double h = b.h, h2 = h * h;
  s.x3_r4 = b.lambda - b.x1h2_r4;
  s.x4_r4 = b.x2_r2 - h * b.x2h1_r4;  // int xi^2 (rho^2 - h^2) / rho^4

  // Primitives F (checked by differentiation; tests compare with quadrature):
  //   tt: [h (h^2 + 3 xi^2) / rho^4],            xi tt: [2 h xi (h^2 + 2 xi^2) / rho^4] - 2 theta
  //   cross: [xi (h^2 - xi^2) / rho^4],          xi cross: [2 h^2 (h^2 + 2 xi^2) / rho^4] + lambda
  //   odd: [h (h^2 - xi^2) / rho^4],             xi odd: [-2 h xi^3 / rho^4]
  //   nn: [-xi (3 h^2 + xi^2) / rho^4],          xi nn: [-2 h^2 xi^2 / rho^4] + lambda
  // Each jump F(xi2) - F(xi1) is evaluated in factored form L poly / (q1 q2)^2, with
  // P = xi1 xi2, S = xi1 + xi2, S2 = xi1^2 + xi2^2, so that a far point does not cancel
  // two O(1/R) end values into an O(L/R^2) result.
  const double L = b.length, P = b.xi_product, S = b.xi_sum;
  const double S2 = b.xi1 * b.xi1 + b.xi2 * b.xi2;
  const double h4 = h2 * h2, P2 = P * P;
  const double w = 1.0 / (b.q_product * b.q_product);
  const double lw = L * w;
  s.tt0 = h * S * (h4 - h2 * S2 - 3.0 * P2) * lw;
  s.tt1 = 2.0 * h * (h4 * h2 + 2.0 * h4 * S2 - h2 * P * S2 + 3.0 * h2 * P2 - 2.0 * P2 * P) * lw -
          2.0 * b.theta;
  const double pm = P - h2;
  s.cross0 = (h2 + P) * (pm * pm - h2 * S * S) * lw;
  s.cross1 = -2.0 * h2 * S * (h2 * S2 + 2.0 * P2) * lw + b.lambda;
  s.odd0 = h * S * (P2 - h2 * S2 - 3.0 * h4) * lw;
  s.odd1 = 2.0 * h * (P2 * P - 2.0 * h2 * P2 - h4 * (S2 + P)) * lw;
  s.nn0 = (P2 * P + h2 * P2 + 3.0 * h2 * P * S2 + 5.0 * h4 * P - h4 * S2 - 3.0 * h4 * h2) * lw;
  s.nn1 = 2.0 * h2 * S * (P2 - h4) * lw + b.lambda;
  return s;
}

}  // namespace bemcontact::integration::detail

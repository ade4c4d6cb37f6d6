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

// Off the element (rho > 0 on [xi1, xi2]). `length` must be xi2 - xi1 as computed by the
// caller (not a separately stored element length: the formulas mix both, and a mismatch of
// one rounding acts like a gap at the end near the source). A source on an end point is a
// misuse (the T integrals diverge); rho^2 is then floored at (1e-30 L)^2 so that every
// result, down to the (q1 q2)^-2 of the stress integrals, stays finite.
inline LineIntegrals line_integrals(double xi1, double xi2, double h, double length) {
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

  r.theta = std::atan2(h * length, product + h2);
  // lambda = ln(rho2 / rho1): log1p of the exact difference when the ratio is near 1 (far
  // sources), the log of the ratio otherwise (a source close to one end).
  const double ratio = q2 / q1;
  r.lambda = 0.5 * ((ratio > 0.5 && ratio < 2.0) ? std::log1p(dq / q1) : std::log(ratio));
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

// Additional integrals for the interior-stress kernels D and S (m <= 3, p + 1 <= 5).
struct StressLineIntegrals {
  double x0_r2 = 0.0;    // int 1 / rho^2 = theta / h (finite as h -> 0 off the element)
  double x1h1_r4 = 0.0;  // int h xi / rho^4
  double x0h2_r4 = 0.0;  // int h^2 / rho^4
  double x4_r4 = 0.0;    // int xi^4 / rho^4
  double x3_r4 = 0.0;    // int xi^3 / rho^4
  double x3h1_r6 = 0.0;  // int h xi^3 / rho^6
  double x4h1_r6 = 0.0;  // int h xi^4 / rho^6
  double x2h2_r6 = 0.0;  // int h^2 xi^2 / rho^6
  double x3h2_r6 = 0.0;  // int h^2 xi^3 / rho^6
  double x1h3_r6 = 0.0;  // int h^3 xi / rho^6
  double x2h3_r6 = 0.0;  // int h^3 xi^2 / rho^6
  double x0h4_r6 = 0.0;  // int h^4 / rho^6
  double x1h4_r6 = 0.0;  // int h^4 xi / rho^6
};

// atan(z) / z, smooth at z = 0.
inline double atan_ratio(double z) { return z == 0.0 ? 1.0 : std::atan(z) / z; }

inline StressLineIntegrals stress_line_integrals(const LineIntegrals& b) {
  StressLineIntegrals s;
  const double h = b.h, h2 = h * h, length = b.length;
  const double product = b.xi_product, q1 = b.q1, q2 = b.q2;
  const double inv_qq = 1.0 / b.q_product;

  // int 1/rho^2 = theta / h. When the projection falls outside the element (xi1 xi2 + h^2 > 0)
  // theta = atan(z), z = h L / (xi1 xi2 + h^2), and theta / h = L / (xi1 xi2 + h^2) atan(z)/z
  // has no 0/0 at h = 0; otherwise |h| is the distance to the element, which is > 0.
  const double denominator = product + h2;
  if (denominator > 0.0) {
    s.x0_r2 = length / denominator * atan_ratio(h * length / denominator);
  } else {
    const double safe_h = std::max(std::abs(h), 1e-30 * length);
    s.x0_r2 = b.theta / (h < 0.0 ? -safe_h : safe_h);
  }

  const double jump_xi_r2 = length * (h2 - product) * inv_qq;  // [xi / rho^2]
  const double x1_r4 = 0.5 * length * b.xi_sum * inv_qq;       // int xi / rho^4 = [-1/(2 rho^2)]
  s.x1h1_r4 = h * x1_r4;
  s.x0h2_r4 = 0.5 * (jump_xi_r2 + s.x0_r2);                     // int h^2/rho^4
  const double x2_r4 = s.x0_r2 - s.x0h2_r4;                     // int xi^2/rho^4
  s.x3_r4 = b.lambda - b.x1h2_r4;
  s.x4_r4 = b.x2_r2 - h2 * x2_r4;

  // rho^-6 family. [xi / rho^4] = L (h^4 - 2 h^2 P - P (xi1^2 + xi2^2 + P)) / (q1 q2)^2.
  const double xi_sq_sum = b.xi1 * b.xi1 + b.xi2 * b.xi2;
  const double jump_xi_r4 =
      length * (h2 * h2 - 2.0 * h2 * product - product * (xi_sq_sum + product)) * inv_qq * inv_qq;
  const double x1_r6 = 0.25 * length * b.xi_sum * (q1 + q2) * inv_qq * inv_qq;  // [-1/(4 rho^4)]
  s.x0h4_r6 = 0.25 * h2 * jump_xi_r4 + 0.75 * s.x0h2_r4;  // reduction formula m = 2 -> 3
  const double x2h2_r6 = s.x0h2_r4 - s.x0h4_r6;           // h^2 (int xi^2/rho^6)
  s.x2h2_r6 = x2h2_r6;
  const double x3_r6 = x1_r4 - h2 * x1_r6;                // int xi^3/rho^6
  s.x3h1_r6 = h * x3_r6;
  s.x4h1_r6 = b.x2h1_r4 - h * x2h2_r6;
  s.x3h2_r6 = h2 * x3_r6;
  s.x1h3_r6 = h * h2 * x1_r6;
  s.x2h3_r6 = h * x2h2_r6;
  s.x1h4_r6 = h2 * h2 * x1_r6;
  return s;
}

}  // namespace bemcontact::integration::detail

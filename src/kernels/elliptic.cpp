#include "bemcontact/kernels/elliptic.hpp"

#include <cmath>
#include <numbers>

namespace bemcontact::kernels {

// AGM (Abramowitz & Stegun 17.6): a_0 = 1, b_0 = sqrt(m1), c_0^2 = m;
// a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n), c_{n+1} = (a_n - b_n)/2;
// K = pi / (2 a_inf),  E = K (1 - sum_n 2^{n-1} c_n^2).
// The loop stops once c_{n+1} < 1e-9 a: the next c is below 1e-18 a, so a_{n+1} equals the
// limit and the omitted terms of the sum are below 1e-17 (quadratic convergence; 4 to 8
// passes for m1 down to 1e-300).
CompleteElliptic complete_elliptic(double m, double m1) {
  double a = 1.0, b = std::sqrt(m1);
  double weight = 0.5;
  double sum = weight * m;
  for (int pass = 0; pass < 64; ++pass) {
    const double c = 0.5 * (a - b);
    const double a_next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = a_next;
    weight *= 2.0;
    sum += weight * c * c;
    if (c < 1e-9 * a) break;
  }
  CompleteElliptic result;
  result.K = 0.5 * std::numbers::pi / a;
  result.E = result.K * (1.0 - sum);
  return result;
}

EllipticLogSplit elliptic_log_split(double m, double m1) {
  const CompleteElliptic direct = complete_elliptic(m, m1);
  const CompleteElliptic complement = complete_elliptic(m1, m);
  const double log_term = std::log(1.0 / m1);
  EllipticLogSplit split;
  split.K_log = complement.K / std::numbers::pi;
  split.E_log = (complement.K - complement.E) / std::numbers::pi;
  split.K_reg = direct.K - split.K_log * log_term;
  split.E_reg = direct.E - split.E_log * log_term;
  return split;
}

}  // namespace bemcontact::kernels

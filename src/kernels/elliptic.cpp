#include "bemcontact/kernels/elliptic.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace bemcontact::kernels {
namespace {

constexpr double half_pi = 0.5 * std::numbers::pi;

// AGM [AbramowitzStegun1972, 17.6]: a_0 = 1, b_0 = sqrt(m1), c_0^2 = m;
// a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n), c_{n+1} = (a_n - b_n)/2 = c_n^2 / (4 a_{n+1});
//   K = pi / (2 a_inf),   K - E = K sum_n 2^{n-1} c_n^2,   a_inf = a_{n+1} - sum_{k>n+1} c_k.
// Convergence is quadratic: once c_{n+1} < 1e-4 a_{n+1}, c_{n+2} = c_{n+1}^2 / (4 a) is taken in
// closed form instead of another square root, and c_{n+3} < 2e-18 a is dropped (4 passes for
// m = 0.9, 6 for m1 = 1e-15). K - E comes out as a sum of positive terms, without
// cancellation, which matters when m is small.
struct Agm {
  double K;
  double K_minus_E;
};

Agm agm(double m, double m1) {
  double a = 1.0, b = std::sqrt(m1);
  double weight = 0.5;
  double sum = weight * m;
  for (int pass = 0; pass < 64; ++pass) {
    const double c = 0.5 * (a - b);
    const double a_next = 0.5 * (a + b);
    weight *= 2.0;
    sum += weight * c * c;
    if (c < 1e-4 * a_next) {
      const double c_next = c * c / (4.0 * a_next);
      a = a_next - c_next;
      sum += 2.0 * weight * c_next * c_next;
      break;
    }
    b = std::sqrt(a * b);
    a = a_next;
  }
  const double K = half_pi / a;
  return {K, K * sum};
}

}  // namespace

CompleteElliptic complete_elliptic(double m, double m1) {
  if (m1 <= 0.0) return {std::numeric_limits<double>::infinity(), 1.0};
  const Agm direct = agm(m, m1);
  if (m1 >= 0.01) return {direct.K, direct.K - direct.K_minus_E};
  // Close to m = 1, E = K - (K - E) cancels (E/K -> 0 and K/E reaches 20 at m1 = 1e-15).
  // Legendre's relation E K' + E' K - K K' = pi/2 gives instead
  //   E = (pi/2 + K (K' - E')) / K'   with K' = K(m1), E' = E(m1),
  // a sum of positive terms (K' - E' ~ pi m1 / 4 comes from the AGM sum).
  const Agm complement = agm(m1, m);
  return {direct.K, (half_pi + direct.K * complement.K_minus_E) / complement.K};
}

EllipticLogSplit elliptic_log_split(double m, double m1) {
  const CompleteElliptic direct = complete_elliptic(m, m1);
  const Agm complement = agm(m1, m);
  const double log_term = std::log(1.0 / m1);
  EllipticLogSplit split;
  split.K_log = complement.K / std::numbers::pi;
  split.E_log = complement.K_minus_E / std::numbers::pi;
  split.K_reg = direct.K - split.K_log * log_term;
  split.E_reg = direct.E - split.E_log * log_term;
  return split;
}

}  // namespace bemcontact::kernels

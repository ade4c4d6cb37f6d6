#include "bemcontact/kernels/ring_integrals.hpp"

#include <cmath>
#include <numbers>

#include "bemcontact/kernels/elliptic.hpp"

namespace bemcontact::kernels {
namespace {

using std::numbers::pi;
constexpr int kMaxJ = kRingMaxP + 1;

// beta_j = int_0^{pi/2} cos^{2j} psi dpsi = (pi/2) (2j-1)!! / (2j)!!  (the value of H at m = 0).
constexpr double beta(int j) {
  double value = 0.5 * pi;
  for (int i = 1; i <= j; ++i) value *= (2.0 * i - 1.0) / (2.0 * i);
  return value;
}

// Below this m the K, E recurrences lose digits (each level of j divides by m: about
// m^-(p+1) ulp overall, 6e-14 at m = 0.2 for p <= 2, 1e-13 at m = 0.3 for p = 3); the
// trapezoidal rule is cheap there because the integrand is far from singular.
constexpr double recurrence_min_m(int max_p) { return max_p <= 2 ? 0.2 : 0.45; }

// Trapezoidal rule on [0, pi/2] with n intervals = 2n points per period pi of an even,
// pi-periodic analytic integrand. The poles of Delta^{-q} sit at sin^2 psi = 1/m,
// Im psi = y = acosh(1/sqrt m), so its Fourier coefficients in 2 psi decay like e^{-2yk};
// u^j = cos^{2j} psi shifts them by j, and the rule aliases mode 2n onto 0: the error is
// about e^{-2y(2n - j)}. n is the smallest with 2y(2n - j_max) >= 40 (the margin over
// 36 = ln 1e-16 covers the algebraic growth of the coefficients of Delta^{-7/2}).
constexpr int kMaxIntervals = 16;
struct TrapezoidTables {
  std::array<std::array<double, kMaxIntervals + 1>, kMaxIntervals + 1> sin2{}, cos2{};
  std::array<std::array<double, kMaxIntervals + 1>, kRingMaxP + 2> max_m{};  // [j_max][n]
  TrapezoidTables() {
    for (int n = 1; n <= kMaxIntervals; ++n)
      for (int i = 0; i <= n; ++i) {
        const double psi = 0.5 * pi * i / n;
        sin2[n][i] = std::sin(psi) * std::sin(psi);
        cos2[n][i] = std::cos(psi) * std::cos(psi);
      }
    for (int j_max = 1; j_max <= kRingMaxP + 1; ++j_max)
      for (int n = 1; n <= kMaxIntervals; ++n) {
        if (2 * n <= j_max) continue;  // max_m = 0: never enough
        const double c = std::cosh(20.0 / (2 * n - j_max));
        max_m[j_max][n] = 1.0 / (c * c);
      }
  }
};
const TrapezoidTables kTrapezoid;

template <int MaxP>
void ring_integrals_trapezoid(double m, RingIntegrals& out) {
  constexpr int j_max = MaxP + 1;
  int n = 1;
  while (n < kMaxIntervals && m > kTrapezoid.max_m[j_max][n]) ++n;
  for (int p = 0; p <= MaxP; ++p) out.h[p].fill(0.0);
  const double weight = 0.5 * pi / n;
  for (int i = 0; i <= n; ++i) {
    const double w = (i == 0 || i == n) ? 0.5 * weight : weight;
    const double delta = 1.0 - m * kTrapezoid.sin2[n][i];
    const double u = kTrapezoid.cos2[n][i];
    const double inverse = 1.0 / delta;
    double power = w / std::sqrt(delta);  // w delta^{-(p+1/2)}
    for (int p = 0; p <= MaxP; ++p) {
      double term = power;
      for (int j = 0; j <= p + 1; ++j) {
        out.h[p][j] += term;
        term *= u;
      }
      power *= inverse;
    }
  }
}

// J_q = int (1 - m sin^2)^{-q}: J_{-1/2} = E, J_{1/2} = K and, by parts,
//   2q m1 J_{q+1} = (2q - 1)(1 + m1) J_q - (2q - 2) J_{q-1}.
// Then u = cos^2 psi = (Delta - m1)/m with Delta = 1 - m sin^2 psi gives, column by column,
//   H(p, j) = (H(p-1, j-1) - m1 H(p, j-1)) / m,   H(-1, 0) = E.
template <int MaxP>
void ring_integrals_elliptic(double m, double m1, RingIntegrals& out) {
  const CompleteElliptic ke = complete_elliptic(m, m1);
  const double inverse_m1 = 1.0 / m1, inverse_m = 1.0 / m;
  double previous = ke.E, current = ke.K;  // J_{q-1}, J_q for q = 1/2
  for (int p = 0; p <= MaxP; ++p) {
    out.h[p][0] = current;
    const double q = p + 0.5;  // the division by 2q folds into a constant
    const double next = ((2 * q - 1) * (1 + m1) * current - (2 * q - 2) * previous) * (inverse_m1 * (1.0 / (2 * q)));
    previous = current;
    current = next;
  }
  out.h[0][1] = (ke.E - m1 * out.h[0][0]) * inverse_m;
  for (int p = 1; p <= MaxP; ++p)
    for (int j = 1; j <= p + 1; ++j) out.h[p][j] = (out.h[p - 1][j - 1] - m1 * out.h[p][j - 1]) * inverse_m;
}

template <int MaxP>
void ring_integrals_for(double m, double m1, RingIntegrals& out) {
  if (m <= 0.0) {  // source or field point on the axis: rho is constant on the ring
    for (int p = 0; p <= MaxP; ++p)
      for (int j = 0; j <= p + 1; ++j) out.h[p][j] = beta(j);
  } else if (m < recurrence_min_m(MaxP)) {
    ring_integrals_trapezoid<MaxP>(m, out);
  } else {
    ring_integrals_elliptic<MaxP>(m, m1, out);
  }
}

// Log coefficients from A&S 15.3.11 (N = j - p >= 0) and 15.3.12 (N < 0) applied to
// H = beta_j 2F1(a, 1/2; j+1; m), a = p + 1/2, c - a - b = N:
//   H_log = beta_j (-1)^N Gamma(j+1) / (Gamma(a - N-) Gamma(1/2 - N-)) m1^{N+}
//           sum_n (a + N+)_n (1/2 + N+)_n / (n! (n + |N|)!) m1^n,
// N+ = max(N, 0), N- = max(-N, 0). The series has positive terms (no cancellation).
struct LogSeriesTables {
  std::array<std::array<double, kMaxJ + 1>, kRingMaxP + 1> prefactor{};
  LogSeriesTables() {
    for (int p = 0; p <= kRingMaxP; ++p)
      for (int j = 0; j <= p + 1; ++j) {
        const int N = j - p;
        const int negative = N < 0 ? -N : 0;
        const int absolute = N < 0 ? -N : N;
        double value = beta(j) * ((absolute % 2) ? -1.0 : 1.0) * std::tgamma(j + 1.0) /
                       (std::tgamma(p + 0.5 - negative) * std::tgamma(0.5 - negative));
        value /= std::tgamma(absolute + 1.0);  // first term 1/|N|!
        prefactor[p][j] = value;
      }
  }
};
const LogSeriesTables kLogSeries;

}  // namespace

void ring_integrals(double m, double m1, int max_p, RingIntegrals& out) {
  switch (max_p) {
    case 0: return ring_integrals_for<0>(m, m1, out);
    case 1: return ring_integrals_for<1>(m, m1, out);
    case 2: return ring_integrals_for<2>(m, m1, out);
    default: return ring_integrals_for<3>(m, m1, out);
  }
}

void ring_integral_log_parts(double m1, int max_p, RingIntegrals& out) {
  for (int p = 0; p <= max_p; ++p)
    for (int j = 0; j <= p + 1; ++j) {
      const int N = j - p;
      const int positive = N > 0 ? N : 0;
      const int absolute = N < 0 ? -N : N;
      const double a = p + 0.5 + positive, b = 0.5 + positive;
      double term = 1.0, sum = 1.0;
      for (int n = 0; n < 200; ++n) {
        term *= m1 * (a + n) * (b + n) / ((n + 1.0) * (n + absolute + 1.0));
        sum += term;
        if (term < 1e-17 * sum) break;
      }
      double power = 1.0;
      for (int k = 0; k < positive; ++k) power *= m1;
      out.h[p][j] = kLogSeries.prefactor[p][j] * power * sum;
    }
}

}  // namespace bemcontact::kernels

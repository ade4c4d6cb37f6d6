#include "bemcontact/reference/nonlocal_cattaneo.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bemcontact/quadrature/gauss_legendre.hpp"

namespace bemcontact::reference {
namespace {

constexpr double kPi = std::numbers::pi;
// Gauss-Chebyshev nodes of the stick zone's projection, and the panels of the integrals.
constexpr int kChebyshevNodes = 64;
constexpr int kPanels = 64;
constexpr int kPanelPoints = 12;

double bump(double r, double rho) {
  const double t = r / rho;
  return std::abs(t) < 1.0 ? std::exp(-1.0 / (1.0 - t * t)) : 0.0;
}

// Nodes and weights of int_lo^hi by Gauss-Legendre panels in s, t = lo + (hi - lo) (1 -
// cos(pi s)) / 2: crowded at both ends, where the integrands behave like square roots.
void clustered_rule(double lo, double hi, int panels, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.clear();
  weights.clear();
  if (!(hi > lo)) return;
  const auto& rule = quadrature::gauss_legendre(kPanelPoints);
  for (int k = 0; k < panels; ++k) {
    const double s0 = static_cast<double>(k) / panels, s1 = static_cast<double>(k + 1) / panels;
    for (int i = 0; i < rule.size(); ++i) {
      const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * rule.nodes[static_cast<std::size_t>(i)];
      nodes.push_back(lo + 0.5 * (hi - lo) * (1.0 - std::cos(kPi * s)));
      weights.push_back(rule.weights[static_cast<std::size_t>(i)] * 0.5 * (hi - lo) * kPi * std::sin(kPi * s) * 0.5 *
                        (s1 - s0));
    }
  }
}

template <class Function>
double integrate(const Function& g, double lo, double hi, int panels) {
  std::vector<double> nodes, weights;
  clustered_rule(lo, hi, panels, nodes, weights);
  double sum = 0.0;
  for (std::size_t k = 0; k < nodes.size(); ++k) sum += weights[k] * g(nodes[k]);
  return sum;
}

}  // namespace

NonlocalCattaneo::NonlocalCattaneo(double a, double p0, double mu, double rho, double q_over_mu_p)
    : a_(a), p0_(p0), mu_(mu), rho_(rho) {
  if (rho_ > 0.0) kernel_norm_ = integrate([&](double r) { return bump(r, rho_); }, -rho_, rho_, kPanels);
  // f at the nodes of [-a, a], once: the transform h and int f reuse them.
  clustered_rule(-a_, a_, kPanels, nodes_, weights_);
  slip_values_.resize(nodes_.size());
  slip_integral_ = 0.0;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    slip_values_[k] = slip_shear(nodes_[k]);
    slip_integral_ += weights_[k] * slip_values_[k];
  }
  const double target = q_over_mu_p * mu_ * kPi * a_ * p0_ / 2.0;  // Q = (Q / mu P) mu P, P = pi a p0 / 2
  // Q(c) falls from int f at c = 0 toward c = a: bisection on c.
  double lo = 0.0, hi = a_;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (force(mid) > target ? lo : hi) = mid;
  }
  c_ = 0.5 * (lo + hi);
  solve_stick(c_);
}

double NonlocalCattaneo::mollified_pressure(double x) const {
  const auto hertz = [&](double t) { return std::abs(t) < a_ ? p0_ * std::sqrt(1.0 - t * t / (a_ * a_)) : 0.0; };
  if (rho_ <= 0.0) return hertz(x);
  const double lo = std::max(-a_, x - rho_), hi = std::min(a_, x + rho_);
  return integrate([&](double t) { return bump(x - t, rho_) * hertz(t); }, lo, hi, 16) / kernel_norm_;
}

double NonlocalCattaneo::transform(double x) const {
  // h(x) = (1/pi) [int (f(t) - f(x)) / (x - t) dt + f(x) ln((a + x) / (a - x))], |x| < a: the
  // first integrand is smooth (f' at t = x), so the fixed nodes serve every x.
  const double fx = slip_shear(x);
  double regular = 0.0;
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    if (std::abs(x - nodes_[k]) > 1e-14 * a_) regular += weights_[k] * (slip_values_[k] - fx) / (x - nodes_[k]);
  return (regular + fx * std::log((a_ + x) / (a_ - x))) / kPi;
}

void NonlocalCattaneo::solve_stick(double c) {
  // -h(c xi) = sum_n b_n T_n(xi): b_n = (2/N) sum_k -h(c xi_k) T_n(xi_k), xi_k = cos theta_k.
  const int N = kChebyshevNodes;
  std::vector<double> values(static_cast<std::size_t>(N));
  for (int k = 0; k < N; ++k) values[static_cast<std::size_t>(k)] = -transform(c * std::cos((2.0 * k + 1.0) * kPi / (2.0 * N)));
  b_.assign(static_cast<std::size_t>(N), 0.0);
  for (int n = 1; n < N; ++n) {
    double sum = 0.0;
    for (int k = 0; k < N; ++k) sum += values[static_cast<std::size_t>(k)] * std::cos(n * (2.0 * k + 1.0) * kPi / (2.0 * N));
    b_[static_cast<std::size_t>(n)] = 2.0 * sum / N;
  }
}

double NonlocalCattaneo::force(double c) {
  if (c <= 0.0) return slip_integral_;
  solve_stick(c);
  return slip_integral_ + 0.5 * kPi * c * b_[1];
}

double NonlocalCattaneo::shear(double x) const {
  if (std::abs(x) >= a_) return 0.0;
  double q = slip_shear(x);
  if (std::abs(x) < c_) {
    // r(c tau) = sum_n b_n sqrt(1 - tau^2) U_{n-1}(tau), U_{n-1}(cos th) = sin(n th) / sin(th).
    const double tau = x / c_, theta = std::acos(tau);
    double r = 0.0;
    for (std::size_t n = 1; n < b_.size(); ++n) r += b_[n] * std::sin(static_cast<double>(n) * theta);
    q += r;  // sqrt(1 - tau^2) U_{n-1}(tau) = sin(n theta)
  }
  return q;
}

}  // namespace bemcontact::reference

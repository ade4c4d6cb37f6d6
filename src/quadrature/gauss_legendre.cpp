#include "bemcontact/quadrature/gauss_legendre.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace bemcontact::quadrature {
namespace {

using Real = long double;  // the rules are built in extended precision, stored in double

// Gauss-Legendre by Newton iteration on P_n from the asymptotic first guess; weights
// 2 / ((1 - x^2) P_n'(x)^2).
Rule build_gauss_legendre(int n) {
  Rule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    Real x = std::cos(std::numbers::pi_v<Real> * (i + 0.75L) / (n + 0.5L));
    Real derivative = 1.0L;
    for (int iteration = 0; iteration < 100; ++iteration) {
      Real p0 = 1.0L, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const Real p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0L);
      const Real step = p1 / derivative;
      x -= step;
      if (std::abs(step) <= 1e-19L) break;
    }
    const Real weight = 2.0L / ((1.0L - x * x) * derivative * derivative);
    // x decreases with i: fill from both ends so the nodes come out increasing.
    rule.nodes[n - 1 - i] = static_cast<double>(x);
    rule.nodes[i] = static_cast<double>(-x);
    rule.weights[n - 1 - i] = rule.weights[i] = static_cast<double>(weight);
  }
  if (n % 2 == 1) rule.nodes[n / 2] = 0.0;
  return rule;
}

// Gauss rule for the weight ln(1/t) on [0, 1] (Gautschi, "Orthogonal polynomials:
// computation and approximation", 2004, example 2.27): the modified Chebyshev algorithm
// with the monic shifted Legendre polynomials, whose modified moments are known in closed
// form,
//   m_0 = 1,  m_k = int_0^1 p_k(t) ln(1/t) dt = (-1)^k (k!)^2 / (k (k+1) (2k)!),
// gives the recurrence coefficients of the log-weight orthogonal polynomials stably; the
// nodes and weights then come from the Jacobi matrix (Golub-Welsch).
Rule build_gauss_log(int n) {
  const int moments = 2 * n;
  std::vector<Real> m(moments), a(moments, 0.5L), b(moments, 0.0L);
  m[0] = 1.0L;
  Real factorial_ratio = 1.0L;  // (k!)^2 / (2k)!
  for (int k = 1; k < moments; ++k) {
    factorial_ratio *= static_cast<Real>(k) * k / ((2.0L * k - 1.0L) * (2.0L * k));
    m[k] = ((k % 2) ? -1.0L : 1.0L) * factorial_ratio / (static_cast<Real>(k) * (k + 1));
    b[k] = static_cast<Real>(k) * k / (4.0L * (4.0L * k * k - 1.0L));  // shifted Legendre
  }
  std::vector<Real> alpha(n), beta(n);
  std::vector<Real> sigma_previous(moments, 0.0L), sigma(m), sigma_next(moments, 0.0L);
  alpha[0] = a[0] + m[1] / m[0];
  beta[0] = m[0];
  for (int k = 1; k < n; ++k) {
    for (int l = k; l < moments - k; ++l) {
      sigma_next[l] = sigma[l + 1] - (alpha[k - 1] - a[l]) * sigma[l] -
                      beta[k - 1] * sigma_previous[l] + b[l] * sigma[l - 1];
    }
    alpha[k] = a[k] + sigma_next[k + 1] / sigma_next[k] - sigma[k] / sigma[k - 1];
    beta[k] = sigma_next[k] / sigma[k - 1];
    sigma_previous.swap(sigma);
    sigma.swap(sigma_next);
  }
  using JacobiMatrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  JacobiMatrix jacobi = JacobiMatrix::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    jacobi(k, k) = alpha[k];
    if (k + 1 < n) jacobi(k, k + 1) = jacobi(k + 1, k) = std::sqrt(beta[k + 1]);
  }
  Eigen::SelfAdjointEigenSolver<JacobiMatrix> solver(jacobi);
  Rule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i) {  // eigenvalues come out increasing
    const Real first = solver.eigenvectors()(0, i);
    rule.nodes[i] = static_cast<double>(solver.eigenvalues()[i]);
    rule.weights[i] = static_cast<double>(beta[0] * first * first);
  }
  return rule;
}

// Orders up to kTabled are cached in a fixed table with one once_flag each (a lock-free
// read after the first call); larger orders go to a map behind a mutex.
constexpr int kTabled = 128;

class RuleCache {
 public:
  explicit RuleCache(Rule (*build)(int)) : build_(build) {}
  const Rule& get(int n) {
    if (n < 1) throw std::invalid_argument("quadrature order must be >= 1, got " + std::to_string(n));
    if (n <= kTabled) {
      std::call_once(flags_[n], [&] { rules_[n] = build_(n); });
      return rules_[n];
    }
    std::lock_guard<std::mutex> lock(mutex_);
    auto& slot = large_[n];
    if (!slot) slot = std::make_unique<Rule>(build_(n));
    return *slot;
  }

 private:
  Rule (*build_)(int);
  std::array<std::once_flag, kTabled + 1> flags_;
  std::array<Rule, kTabled + 1> rules_;
  std::mutex mutex_;
  std::map<int, std::unique_ptr<Rule>> large_;
};

}  // namespace

const Rule& gauss_legendre(int n) {
  static RuleCache cache(&build_gauss_legendre);
  return cache.get(n);
}

const Rule& gauss_log(int n) {
  static RuleCache cache(&build_gauss_log);
  return cache.get(n);
}

}  // namespace bemcontact::quadrature

#include "bemcontact/reference/pin_in_hole.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Dense>

#include "bemcontact/core/error.hpp"

namespace bemcontact::reference {
namespace {

using std::numbers::pi;

// Coefficients of exp(+i n theta) and exp(-i n theta) in S = s_rr - i s_rt and in
// U = 2 mu (u_r + i u_t) at one radius, for one potential term with a unit coefficient.
struct ModeCoefficients {
  double s_plus = 0.0, s_minus = 0.0, u_plus = 0.0, u_minus = 0.0;
};

enum class TermKind { phi_power, psi_power, log_pair, translation };

struct Term {
  TermKind kind;
  int power = 0;
  double scale = 1.0;  // rho: the term is A (z / rho)^k, bounded in the annulus
};

class ModeEvaluator {
 public:
  ModeEvaluator(int n, double kappa) : n_(n), kappa_(kappa) {}

  // Muskhelishvili: s_rr - i s_rt = phi' + conj(phi') - e^(2 i theta) [conj(z) phi'' + psi'],
  // 2 mu (u_r + i u_t) = e^(-i theta) [kappa phi - z conj(phi') - conj(psi)].
  ModeCoefficients at(const Term& term, double r) const {
    ModeCoefficients c;
    const double x = r / term.scale;
    switch (term.kind) {
      case TermKind::phi_power: {  // phi = (z / rho)^k
        const int k = term.power;
        add_s(c, k - 1, k * (2.0 - k) * std::pow(x, k - 1) / term.scale);
        add_s(c, 1 - k, k * std::pow(x, k - 1) / term.scale);
        add_u(c, k - 1, kappa_ * std::pow(x, k));
        add_u(c, 1 - k, -k * std::pow(x, k));
        break;
      }
      case TermKind::psi_power: {  // psi = (z / rho)^m
        const int m = term.power;
        add_s(c, m + 1, -m * std::pow(x, m - 1) / term.scale);
        add_u(c, -(m + 1), -std::pow(x, m));
        break;
      }
      case TermKind::log_pair:  // phi = log z, psi = -kappa log z
        add_s(c, 1, (1.0 + kappa_) / r);
        add_s(c, -1, 2.0 / r);
        add_u(c, -1, 2.0 * kappa_ * std::log(r));
        add_u(c, 1, -1.0);
        break;
      case TermKind::translation:  // 2 mu (u_x + i u_y) = 1
        add_u(c, -1, 1.0);
        break;
    }
    return c;
  }

 private:
  void add_s(ModeCoefficients& c, int exponent, double value) const {
    if (exponent == n_) c.s_plus += value;
    else if (exponent == -n_) c.s_minus += value;
  }
  void add_u(ModeCoefficients& c, int exponent, double value) const {
    if (exponent == n_) c.u_plus += value;
    else if (exponent == -n_) c.u_minus += value;
  }
  int n_;
  double kappa_;
};

// Fourier coefficient f_n of the hat function of grid node j (width h; node 0 is the half
// hat of an even function), with f(theta) = f_0 + sum f_n cos(n theta).
double hat_coefficient(int n, int j, double h) {
  if (n == 0) return (j == 0 ? 0.5 * h : h) / pi;
  const double m = n;
  const double integral = (1.0 - std::cos(m * h)) / (m * m * h);  // int_0^h (1 - s/h) cos(ns) ds
  return 2.0 / pi * (j == 0 ? integral : 2.0 * std::cos(m * j * h) * integral);
}

}  // namespace

double PinInHole::mode_compliance(int n) const {
  const double nu = material.poisson_ratio;
  const double kappa = analysis == AnalysisType::plane_stress ? (3.0 - nu) / (1.0 + nu) : 3.0 - 4.0 * nu;
  const double mu = material.shear_modulus();
  const double a = hole_radius, b = outer_radius;
  std::vector<Term> terms;
  if (n == 0) terms = {{TermKind::phi_power, 1, b}, {TermKind::psi_power, -1, a}};
  else if (n == 1)
    terms = {{TermKind::phi_power, 2, b}, {TermKind::translation, 0, 1.0}, {TermKind::log_pair, 0, 1.0},
             {TermKind::psi_power, -2, a}};
  else
    terms = {{TermKind::phi_power, n + 1, b}, {TermKind::phi_power, 1 - n, a}, {TermKind::psi_power, n - 1, b},
             {TermKind::psi_power, -n - 1, a}};
  const ModeEvaluator mode(n, kappa);
  const Eigen::Index size = static_cast<Eigen::Index>(terms.size());
  Eigen::MatrixXd system(size, size);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  std::vector<ModeCoefficients> on_hole;
  for (Eigen::Index t = 0; t < size; ++t) {
    const auto& hole = on_hole.emplace_back(mode.at(terms[static_cast<std::size_t>(t)], a));
    const auto outer = mode.at(terms[static_cast<std::size_t>(t)], b);
    if (n == 0) {  // s_rr(a) = -1, u_r(b) = 0 (the shear and u_t vanish by symmetry)
      system(0, t) = hole.s_plus;
      system(1, t) = outer.u_plus;
    } else {  // s_rr = s cos, s_rt = t sin: s = S+ + S-, t = S- - S+; u_r, u_t alike
      system(0, t) = hole.s_plus + hole.s_minus;
      system(1, t) = hole.s_minus - hole.s_plus;
      system(2, t) = outer.u_plus + outer.u_minus;
      system(3, t) = outer.u_plus - outer.u_minus;
    }
  }
  rhs(0) = -1.0;
  const Eigen::VectorXd coefficients = system.fullPivLu().solve(rhs);
  double u = 0.0;
  for (Eigen::Index t = 0; t < size; ++t) {
    const auto& hole = on_hole[static_cast<std::size_t>(t)];
    u += coefficients(t) * (n == 0 ? hole.u_plus : hole.u_plus + hole.u_minus);
  }
  return u / (2.0 * mu);
}

PinInHole::Solution PinInHole::solve(double force) const {
  if (!(pin_radius > 0.0 && pin_radius < hole_radius && hole_radius < outer_radius))
    throw Error("pin in hole: needs 0 < pin radius < hole radius < outer radius");
  const double h = max_angle / grid_intervals;
  if (!(max_angle > 0.0 && max_angle < 0.5 * pi) || grid_intervals < 4 || !(modes * h >= 25.0) || !(force > 0.0))
    throw Error("pin in hole: needs 0 < max_angle < pi/2, >= 4 grid intervals, modes x grid step >= 25 (the hat "
                "functions' Fourier series converged), a force > 0");
  const int nodes = grid_intervals + 1;
  // Influence of the nodal pressures on u_r at the nodes: K_ij = sum_n G_n f_nj cos(n t_i).
  // A full hat's coefficient is b_n cos(n t_j) (b_n its value at t_j = 0, twice the half
  // hat's), so K_ij = (S(i - j) + S(i + j)) / 2 for j >= 1 and K_i0 = S(i) / 2, with
  // S(m) = sum_n G_n b_n cos(n m h): 2 x intervals sums over the modes instead of a product.
  std::vector<double> sums(static_cast<std::size_t>(2 * grid_intervals + 1), 0.0);
  for (int n = 0; n <= modes; ++n) {
    const double weight = mode_compliance(n) * 2.0 * hat_coefficient(n, 0, h);
    for (std::size_t m = 0; m < sums.size(); ++m) sums[m] += weight * std::cos(static_cast<double>(n) * m * h);
  }
  Eigen::MatrixXd influence(nodes, nodes);
  Eigen::RowVectorXd first_mode(nodes);
  for (int i = 0; i < nodes; ++i)
    for (int j = 0; j < nodes; ++j)
      influence(i, j) = j == 0 ? 0.5 * sums[static_cast<std::size_t>(i)]
                               : 0.5 * (sums[static_cast<std::size_t>(std::abs(i - j))] + sums[static_cast<std::size_t>(i + j)]);
  for (int j = 0; j < nodes; ++j) first_mode(j) = hat_coefficient(1, j, h);
  // The pressures' resultant along the force: P = pi Rh f_1.
  const Eigen::RowVectorXd resultant = pi * hole_radius * first_mode;
  const double e = hole_radius - pin_radius;
  Eigen::VectorXd gap(nodes), direction(nodes);
  for (int j = 0; j < nodes; ++j) {
    const double t = j * h;
    gap(j) = hole_radius - (e * std::cos(t) + std::sqrt(pin_radius * pin_radius - e * e * std::sin(t) * std::sin(t)));
    direction(j) = std::cos(t);
  }
  // Active set: gap + K p - delta cos = 0 on it, p = 0 off it, resultant = force.
  std::vector<bool> active(static_cast<std::size_t>(nodes), false);
  active[0] = true;
  Eigen::VectorXd p = Eigen::VectorXd::Zero(nodes);
  double delta = 0.0;
  for (int iteration = 0;; ++iteration) {
    if (iteration > 200) throw Error("pin in hole: the active set did not settle");
    std::vector<int> set;
    for (int j = 0; j < nodes; ++j)
      if (active[static_cast<std::size_t>(j)]) set.push_back(j);
    const Eigen::Index m = static_cast<Eigen::Index>(set.size());
    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(m + 1, m + 1);
    Eigen::VectorXd rhs(m + 1);
    for (Eigen::Index r = 0; r < m; ++r) {
      for (Eigen::Index c = 0; c < m; ++c) system(r, c) = influence(set[r], set[c]);
      system(r, m) = -direction(set[r]);
      system(m, r) = resultant(set[r]);
      rhs(r) = -gap(set[r]);
    }
    rhs(m) = force;
    const Eigen::VectorXd x = system.partialPivLu().solve(rhs);
    p.setZero();
    for (Eigen::Index r = 0; r < m; ++r) p(set[r]) = x(r);
    delta = x(m);
    // Primal-dual active set: drop every negative pressure and add every penetrating node;
    // settled when neither happens (a few iterations: the zone grows from the first node).
    const Eigen::VectorXd opening = gap + influence * p - delta * direction;
    const double tolerance = 1e-14 * gap.cwiseAbs().maxCoeff();
    bool changed = false;
    for (int j = 0; j < nodes; ++j) {
      const bool in = active[static_cast<std::size_t>(j)];
      const bool keep = in ? p(j) >= 0.0 : opening(j) < -tolerance;
      if (keep != in) active[static_cast<std::size_t>(j)] = keep, changed = true;
    }
    if (!changed) break;
  }
  Solution out;
  out.approach = delta;
  out.peak_pressure = p(0);
  int last = 0;
  for (int j = 0; j < nodes; ++j) {
    out.angle.push_back(j * h);
    out.pressure.push_back(p(j));
    if (p(j) > 0.0) last = j;
  }
  if (last + 1 >= nodes) throw Error("pin in hole: the contact reaches the grid's end; raise max_angle");
  // p^2 linear in theta at a smooth edge: extrapolated to zero, kept within [last, last + h].
  out.half_angle = last * h;
  if (last > 0 && p(last - 1) > p(last))
    out.half_angle = std::min(last * h + h * p(last) * p(last) / (p(last - 1) * p(last - 1) - p(last) * p(last)),
                              (last + 1) * h);
  return out;
}

}  // namespace bemcontact::reference

// Semi-smooth Newton (primal-dual active set) for one load step; see step_solvers.hpp.
#include <algorithm>
#include <cmath>
#include <set>

#include "bemcontact/contact/step_solvers.hpp"

namespace bemcontact::contact {
namespace {

double penalty_scale(const CondensedProblem& p) {
  double sum = 0.0;
  for (Index k = 0; k < p.M.rows(); ++k) sum += std::abs(p.M(k, k));
  return sum > 0.0 ? p.M.rows() / sum : 1.0;
}

double threshold(const StepInput& in, double lambda_n) {
  return in.friction * (in.kind == ContactKind::unilateral ? std::max(lambda_n, 0.0) : std::abs(lambda_n));
}

}  // namespace

Vector relative_displacement(const StepInput& in, const Vector& x, double delta) {
  const auto& p = *in.problem;
  Vector w = in.load * p.a + p.M * x;
  if (p.has_force) w += delta * p.b;
  return w;
}

double complementarity_residual(const StepInput& in, const Vector& x, double delta) {
  const auto& p = *in.problem;
  const double c = penalty_scale(p);
  const Vector w = relative_displacement(in, x, delta);
  double scale = 0.0, worst = 0.0;
  for (Index i = 0; i < p.pairs; ++i) scale = std::max(scale, std::abs(x[2 * i]));
  if (scale == 0.0) scale = 1.0;
  for (Index i = 0; i < p.pairs; ++i) {
    const double lambda = x[2 * i], tau = x[2 * i + 1];
    const double normal_gap = p.gap[i] - w[2 * i];
    const double cn = in.kind == ContactKind::unilateral ? lambda - std::max(0.0, lambda - c * normal_gap)
                                                         : c * normal_gap;
    const double g = threshold(in, lambda);
    const double slip = w[2 * i + 1] - in.previous_tangential_jump[i];
    const double ct = p.on_axis[i] ? tau : tau - std::clamp(tau - c * slip, -g, g);
    worst = std::max({worst, std::abs(cn) / scale, std::abs(ct) / scale});
  }
  if (p.has_force) {
    const double target = in.load * (p.force - p.F0);
    const double mismatch = p.f.dot(x) + p.f_delta * delta - target;
    worst = std::max(worst, std::abs(mismatch) / std::max(std::abs(in.load * p.force), 1e-300));
  }
  return worst;
}

StepOutput solve_step_newton(const StepInput& in, const SolverOptions& options) {
  const auto& p = *in.problem;
  const Index n = p.pairs;
  const Index size = 2 * n + (p.has_force ? 1 : 0);
  const double c = penalty_scale(p);
  StepOutput out;
  Vector x = in.x_start.size() == 2 * n ? in.x_start : Vector::Zero(2 * n);
  double delta = in.delta_start;
  double residual = complementarity_residual(in, x, delta);
  std::set<std::vector<int>> seen;
  bool damped = false;
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    out.newton_iterations = iteration;
    const Vector w = relative_displacement(in, x, delta);
    // Active sets from the current iterate.
    std::vector<int> state(2 * n, 0);
    bool any_active = false;
    for (Index i = 0; i < n; ++i) {
      const double lambda = x[2 * i];
      const bool active = in.kind == ContactKind::bilateral || lambda - c * (p.gap[i] - w[2 * i]) > 0.0;
      state[2 * i] = active ? 1 : 0;
      any_active = any_active || active;
    }
    if (!any_active && p.has_force) {  // a force needs a contact to go through
      Index closest = 0;
      for (Index i = 1; i < n; ++i)
        if (p.gap[i] - w[2 * i] < p.gap[closest] - w[2 * closest]) closest = i;
      state[2 * closest] = 1;
    }
    for (Index i = 0; i < n; ++i) {
      const double lambda = x[2 * i], tau = x[2 * i + 1];
      if (p.on_axis[i] || in.friction == 0.0 || state[2 * i] == 0) {
        state[2 * i + 1] = 0;  // tau = 0
        continue;
      }
      const double g = threshold(in, lambda);
      const double z = tau - c * (w[2 * i + 1] - in.previous_tangential_jump[i]);
      if (std::abs(z) < g) state[2 * i + 1] = 1;  // stick
      else state[2 * i + 1] = z >= 0.0 ? 2 : 3;   // slip, tau = +g or -g
    }
    if (!damped && !seen.insert(state).second && iteration > 2) damped = true;  // the sets cycle

    Matrix J = Matrix::Zero(size, size);
    Vector rhs = Vector::Zero(size);
    for (Index i = 0; i < n; ++i) {
      const Index rn = 2 * i, rt = 2 * i + 1;
      if (state[rn] == 1) {  // w_n = d
        J.row(rn).head(2 * n) = p.M.row(rn);
        if (p.has_force) J(rn, 2 * n) = p.b[rn];
        rhs[rn] = p.gap[i] - in.load * p.a[rn];
      } else {
        J(rn, rn) = 1.0;  // lambda_n = 0
      }
      if (state[rt] == 0) {
        J(rt, rt) = 1.0;
      } else if (state[rt] == 1) {  // no slip increment
        J.row(rt).head(2 * n) = p.M.row(rt);
        if (p.has_force) J(rt, 2 * n) = p.b[rt];
        rhs[rt] = in.previous_tangential_jump[i] - in.load * p.a[rt];
      } else {  // tau = +-beta lambda_n (sign of lambda_n in bilateral contact)
        const double s = state[rt] == 2 ? 1.0 : -1.0;
        const double sigma = in.kind == ContactKind::bilateral && x[rn] < 0.0 ? -1.0 : 1.0;
        J(rt, rt) = 1.0;
        J(rt, rn) = -in.friction * s * sigma;
      }
    }
    if (p.has_force) {
      J.row(2 * n).head(2 * n) = p.f.transpose();
      J(2 * n, 2 * n) = p.f_delta;
      rhs[2 * n] = in.load * (p.force - p.F0);
    }
    const Eigen::PartialPivLU<Matrix> lu(J);
    Vector y = lu.solve(rhs);
    if (!y.allFinite() || (J * y - rhs).norm() > 1e-6 * (rhs.norm() + 1e-300) + 1e-12 * J.norm() * y.norm()) {
      out.failure = "the Newton system of iteration " + std::to_string(iteration) +
                    " is singular (no pair in contact can carry the load?)";
      break;
    }
    Vector x_new = y.head(2 * n);
    double delta_new = p.has_force ? y[2 * n] : 0.0;
    double new_residual = complementarity_residual(in, x_new, delta_new);
    if (damped && new_residual >= residual) {  // backtrack along the Newton direction
      const Vector dx = x_new - x;
      const double dd = delta_new - delta;
      double alpha = 1.0;
      for (int k = 0; k < 30 && new_residual >= residual; ++k) {
        alpha *= 0.5;
        x_new = x + alpha * dx;
        delta_new = delta + alpha * dd;
        new_residual = complementarity_residual(in, x_new, delta_new);
      }
    }
    x = x_new;
    delta = delta_new;
    residual = new_residual;
    if (residual <= options.tolerance) {
      out.converged = true;
      break;
    }
  }
  out.x = x;
  out.delta = delta;
  out.w = relative_displacement(in, x, delta);
  out.residual = residual;
  if (!out.converged && out.failure.empty())
    out.failure = "the semi-smooth Newton method did not converge in " + std::to_string(options.max_iterations) +
                  " iterations";
  return out;
}

}  // namespace bemcontact::contact

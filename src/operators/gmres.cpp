#include "bemcontact/operators/gmres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bemcontact/core/error.hpp"

namespace bemcontact::operators {

const char* to_string(GmresStatus status) {
  switch (status) {
    case GmresStatus::converged: return "converged";
    case GmresStatus::max_iterations: return "max_iterations";
    case GmresStatus::stagnated: return "stagnated";
    case GmresStatus::breakdown: return "breakdown";
  }
  return "unknown";
}

namespace {

std::string number_text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

// Givens rotation (c, s) with [c s; -s c] [a; b] = [r; 0].
void givens(double a, double b, double& c, double& s) {
  if (b == 0.0) {
    c = 1.0;
    s = 0.0;
  } else {
    const double r = std::hypot(a, b);
    c = a / r;
    s = b / r;
  }
}

}  // namespace

GmresResult gmres(const LinearOperator& A, const Vector& b, const GmresOptions& options, const Vector& x0,
                  const GmresMonitor& monitor, const LinearOperator* right_preconditioner) {
  const Index n = A.rows();
  if (A.cols() != n || b.size() != n) throw Error("gmres: the operator must be square and match the right-hand side");
  if (options.restart < 1) throw Error("gmres: the restart length m must be >= 1");
  if (!(options.tolerance > 0.0)) throw Error("gmres: the tolerance must be > 0");
  if (right_preconditioner && (right_preconditioner->rows() != n || right_preconditioner->cols() != n))
    throw Error("gmres: the preconditioner must be square and match the operator");
  const int m = static_cast<int>(std::min<Index>(options.restart, std::max<Index>(n, 1)));

  GmresResult result;
  result.x = x0.size() == n ? x0 : Vector::Zero(n);
  Vector r(n), w(n), z(n);
  // A M^-1 on a Krylov vector: right preconditioning keeps the residual the true one.
  const auto apply_preconditioned = [&](const Vector& v, Vector& out) {
    if (!right_preconditioner) return A.apply(v, out);
    right_preconditioner->apply(v, z);
    A.apply(z, out);
  };
  A.apply(result.x, w);
  r = b - w;
  const double r00 = r.norm();
  result.initial_residual = r00;
  result.residual_history.push_back(r00 > 0.0 ? 1.0 : 0.0);
  if (!(r00 > 0.0)) {
    result.status = GmresStatus::converged;
    result.relative_residual = 0.0;
    result.message = "the initial residual is zero";
    return result;
  }
  if (!std::isfinite(r00)) throw SolverError("gmres: the right-hand side or the operator is not finite");

  Matrix V(n, m + 1);
  Matrix H = Matrix::Zero(m + 1, m);
  Vector cs(m), sn(m), g(m + 1);
  double previous = 1.0;  // relative residual at the start of the cycle
  int stagnant = 0;
  const double eps = std::numeric_limits<double>::epsilon();

  while (true) {
    const double beta = r.norm();
    V.col(0) = r / beta;
    H.setZero();
    g.setZero();
    g[0] = beta;
    int steps = 0;
    bool invariant = false;
    for (int j = 0; j < m && result.iterations < options.max_iterations; ++j) {
      apply_preconditioned(V.col(j), w);
      ++result.iterations;
      const double w_norm = w.norm();
      if (!std::isfinite(w_norm)) throw SolverError("gmres: the operator returned a non-finite vector");
      for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
        const double h = V.col(i).dot(w);
        H(i, j) = h;
        w -= h * V.col(i);
      }
      if (w.norm() < 0.7 * w_norm) {  // cancellation: one more pass keeps V orthogonal
        for (int i = 0; i <= j; ++i) {
          const double h = V.col(i).dot(w);
          H(i, j) += h;
          w -= h * V.col(i);
        }
      }
      const double h_next = w.norm();
      H(j + 1, j) = h_next;
      invariant = !(h_next > 10.0 * eps * std::max(w_norm, 1e-300));
      if (!invariant) V.col(j + 1) = w / h_next;
      for (int i = 0; i < j; ++i) {  // previous rotations on the new column
        const double a = H(i, j), c = H(i + 1, j);
        H(i, j) = cs[i] * a + sn[i] * c;
        H(i + 1, j) = -sn[i] * a + cs[i] * c;
      }
      givens(H(j, j), H(j + 1, j), cs[j], sn[j]);
      H(j, j) = cs[j] * H(j, j) + sn[j] * H(j + 1, j);
      H(j + 1, j) = 0.0;
      g[j + 1] = -sn[j] * g[j];
      g[j] = cs[j] * g[j];
      steps = j + 1;
      const double estimate = std::abs(g[j + 1]) / r00;
      result.residual_history.push_back(estimate);
      if (monitor) monitor(result.iterations, estimate);
      if (estimate < options.tolerance || invariant) break;
    }
    if (steps == 0) break;  // no step left in the budget

    // y = R^{-1} g. A zero pivot at k means the operator is singular on the Krylov space:
    // the minimal-residual correction then lies in the first k directions, and the solver
    // stops with status breakdown after applying it.
    const double pivot_floor = 1e-14 * H.topLeftCorner(steps, steps).cwiseAbs().maxCoeff();
    int usable = steps;
    for (int k = 0; k < steps; ++k)
      if (!(std::abs(H(k, k)) > pivot_floor)) {
        usable = k;
        break;
      }
    const bool singular = usable < steps;
    if (usable > 0) {
      const Vector y = H.topLeftCorner(usable, usable).triangularView<Eigen::Upper>().solve(g.head(usable));
      if (right_preconditioner) {
        right_preconditioner->apply(V.leftCols(usable) * y, z);
        result.x += z;
      } else {
        result.x += V.leftCols(usable) * y;
      }
    }
    A.apply(result.x, w);
    r = b - w;
    const double relative = r.norm() / r00;
    result.residual_history.back() = relative;
    if (relative < options.tolerance) {
      result.status = GmresStatus::converged;
      result.message = "converged in " + std::to_string(result.iterations) + " iterations (relative residual " +
                       number_text(relative) + ")";
      break;
    }
    if (singular) {
      result.status = GmresStatus::breakdown;
      result.message = "breakdown: the operator is singular on the Krylov space after " +
                       std::to_string(result.iterations) + " iterations; relative residual " + number_text(relative);
      break;
    }
    if (invariant) {
      result.status = GmresStatus::breakdown;
      result.message = "breakdown: the Krylov space is invariant after " + std::to_string(result.iterations) +
                       " iterations but the relative residual is " + number_text(relative) +
                       " (the operator is singular or rounding dominates)";
      break;
    }
    if (result.iterations >= options.max_iterations) {
      result.status = GmresStatus::max_iterations;
      result.message = "not converged: " + std::to_string(result.iterations) +
                       " iterations (the maximum) left the relative residual at " + number_text(relative) +
                       " > " + number_text(options.tolerance);
      break;
    }
    stagnant = relative > (1.0 - options.stagnation_reduction) * previous ? stagnant + 1 : 0;
    if (stagnant >= options.stagnation_cycles) {
      result.status = GmresStatus::stagnated;
      result.message = "not converged: GMRES(" + std::to_string(m) + ") stagnated, " +
                       std::to_string(options.stagnation_cycles) + " restart cycles in a row cut the residual by less than " +
                       number_text(100.0 * options.stagnation_reduction) + " %; relative residual " +
                       number_text(relative) + " after " + std::to_string(result.iterations) +
                       " iterations (a larger restart length m may converge)";
      break;
    }
    previous = relative;
    ++result.restarts;
  }
  if (result.message.empty()) {  // budget exhausted before a step of the last cycle
    result.status = GmresStatus::max_iterations;
    result.message = "not converged: the iteration budget (" + std::to_string(options.max_iterations) +
                     ") is exhausted";
  }
  A.apply(result.x, w);
  result.relative_residual = (b - w).norm() / r00;
  return result;
}

}  // namespace bemcontact::operators

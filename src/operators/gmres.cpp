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

void check_arguments(const LinearOperator& A, const Vector& b, const GmresOptions& options,
                     const LinearOperator* right_preconditioner) {
  const Index n = A.rows();
  if (A.cols() != n || b.size() != n) throw Error("gmres: the operator must be square and match the right-hand side");
  if (options.restart < 1) throw Error("gmres: the restart length m must be >= 1");
  if (!(options.tolerance > 0.0)) throw Error("gmres: the tolerance must be > 0");
  if (right_preconditioner && (right_preconditioner->rows() != n || right_preconditioner->cols() != n))
    throw Error("gmres: the preconditioner must be square and match the operator");
}

// One solve: the iterate, the residual and the Krylov space of the current restart cycle.
class RestartedGmres {
 public:
  RestartedGmres(const LinearOperator& A, const Vector& b, const GmresOptions& options, const GmresMonitor& monitor,
                 const LinearOperator* right_preconditioner)
      : A_(A), b_(b), options_(options), monitor_(monitor), preconditioner_(right_preconditioner), n_(A.rows()),
        m_(static_cast<int>(std::min<Index>(options.restart, std::max<Index>(n_, 1)))), r_(n_), w_(n_), z_(n_) {}

  GmresResult solve(const Vector& x0) {
    result_.x = x0.size() == n_ ? x0 : Vector::Zero(n_);
    if (!start()) return result_;
    V_.resize(n_, m_ + 1);
    H_ = Matrix::Zero(m_ + 1, m_);
    cs_.resize(m_);
    sn_.resize(m_);
    g_.resize(m_ + 1);
    double previous = 1.0;  // relative residual at the start of the cycle
    int stagnant = 0;
    while (true) {
      bool invariant = false;
      const int steps = arnoldi_cycle(invariant);
      if (steps == 0) break;  // no step left in the budget
      const bool singular = !add_correction(steps);
      A_.apply(result_.x, w_);
      r_ = b_ - w_;
      const double relative = r_.norm() / r00_;
      result_.residual_history.back() = relative;
      if (stopped(relative, singular, invariant)) break;
      stagnant = relative > (1.0 - options_.stagnation_reduction) * previous ? stagnant + 1 : 0;
      if (stagnant >= options_.stagnation_cycles) {
        stagnated(relative);
        break;
      }
      previous = relative;
      ++result_.restarts;
    }
    if (result_.message.empty()) {  // budget exhausted before a step of the last cycle
      result_.status = GmresStatus::max_iterations;
      result_.message = "not converged: the iteration budget (" + std::to_string(options_.max_iterations) +
                        ") is exhausted";
    }
    A_.apply(result_.x, w_);
    result_.relative_residual = (b_ - w_).norm() / r00_;
    return result_;
  }

 private:
  // A M^-1 on a Krylov vector: right preconditioning keeps the residual the true one.
  void apply_preconditioned(const Vector& v, Vector& out) {
    if (!preconditioner_) return A_.apply(v, out);
    preconditioner_->apply(v, z_);
    A_.apply(z_, out);
  }

  // The first residual r_00; false when it is zero (x0 solves the system).
  bool start() {
    A_.apply(result_.x, w_);
    r_ = b_ - w_;
    r00_ = r_.norm();
    result_.initial_residual = r00_;
    result_.residual_history.push_back(r00_ > 0.0 ? 1.0 : 0.0);
    if (!(r00_ > 0.0)) {
      result_.status = GmresStatus::converged;
      result_.relative_residual = 0.0;
      result_.message = "the initial residual is zero";
      return false;
    }
    if (!std::isfinite(r00_)) throw SolverError("gmres: the right-hand side or the operator is not finite");
    return true;
  }

  // The Arnoldi steps of one cycle from r, until the residual estimate meets the tolerance,
  // the space is invariant, m steps or the iteration budget; returns the steps taken.
  int arnoldi_cycle(bool& invariant) {
    const double beta = r_.norm();
    V_.col(0) = r_ / beta;
    H_.setZero();
    g_.setZero();
    g_[0] = beta;
    int steps = 0;
    for (int j = 0; j < m_ && result_.iterations < options_.max_iterations; ++j) {
      apply_preconditioned(V_.col(j), w_);
      ++result_.iterations;
      invariant = arnoldi_step(j);
      rotate_column(j);
      steps = j + 1;
      const double estimate = std::abs(g_[j + 1]) / r00_;
      result_.residual_history.push_back(estimate);
      if (monitor_) monitor_(result_.iterations, estimate);
      if (estimate < options_.tolerance || invariant) break;
    }
    return steps;
  }

  // w = A M^-1 v_j orthogonalised against v_0..v_j into column j of H, and v_{j+1} from what
  // is left. True when nothing is left: the Krylov space is invariant.
  bool arnoldi_step(int j) {
    const double eps = std::numeric_limits<double>::epsilon();
    const double w_norm = w_.norm();
    if (!std::isfinite(w_norm)) throw SolverError("gmres: the operator returned a non-finite vector");
    for (int i = 0; i <= j; ++i) {  // modified Gram-Schmidt
      const double h = V_.col(i).dot(w_);
      H_(i, j) = h;
      w_ -= h * V_.col(i);
    }
    if (w_.norm() < 0.7 * w_norm) {  // cancellation: one more pass keeps V orthogonal
      for (int i = 0; i <= j; ++i) {
        const double h = V_.col(i).dot(w_);
        H_(i, j) += h;
        w_ -= h * V_.col(i);
      }
    }
    const double h_next = w_.norm();
    H_(j + 1, j) = h_next;
    const bool invariant = !(h_next > 10.0 * eps * std::max(w_norm, 1e-300));
    if (!invariant) V_.col(j + 1) = w_ / h_next;
    return invariant;
  }

  // Column j of H through the previous rotations, then the new one that zeroes H(j+1, j),
  // applied to g too.
  void rotate_column(int j) {
    for (int i = 0; i < j; ++i) {  // previous rotations on the new column
      const double a = H_(i, j), c = H_(i + 1, j);
      H_(i, j) = cs_[i] * a + sn_[i] * c;
      H_(i + 1, j) = -sn_[i] * a + cs_[i] * c;
    }
    givens(H_(j, j), H_(j + 1, j), cs_[j], sn_[j]);
    H_(j, j) = cs_[j] * H_(j, j) + sn_[j] * H_(j + 1, j);
    H_(j + 1, j) = 0.0;
    g_[j + 1] = -sn_[j] * g_[j];
    g_[j] = cs_[j] * g_[j];
  }

  // x += M^-1 V y, y = R^{-1} g. A zero pivot at k means the operator is singular on the
  // Krylov space: the minimal-residual correction then lies in the first k directions, and
  // the solver stops with status breakdown after applying it. False when singular.
  bool add_correction(int steps) {
    const double pivot_floor = 1e-14 * H_.topLeftCorner(steps, steps).cwiseAbs().maxCoeff();
    int usable = steps;
    for (int k = 0; k < steps; ++k)
      if (!(std::abs(H_(k, k)) > pivot_floor)) {
        usable = k;
        break;
      }
    if (usable > 0) {
      const Vector y = H_.topLeftCorner(usable, usable).triangularView<Eigen::Upper>().solve(g_.head(usable));
      if (preconditioner_) {
        preconditioner_->apply(V_.leftCols(usable) * y, z_);
        result_.x += z_;
      } else {
        result_.x += V_.leftCols(usable) * y;
      }
    }
    return usable == steps;
  }

  // Whether the cycle ends the solve (converged, breakdown, budget spent), with its status
  // and message.
  bool stopped(double relative, bool singular, bool invariant) {
    const std::string iterations = std::to_string(result_.iterations);
    if (relative < options_.tolerance) {
      result_.status = GmresStatus::converged;
      result_.message = "converged in " + iterations + " iterations (relative residual " + number_text(relative) + ")";
    } else if (singular) {
      result_.status = GmresStatus::breakdown;
      result_.message = "breakdown: the operator is singular on the Krylov space after " + iterations +
                        " iterations; relative residual " + number_text(relative);
    } else if (invariant) {
      result_.status = GmresStatus::breakdown;
      result_.message = "breakdown: the Krylov space is invariant after " + iterations +
                        " iterations but the relative residual is " + number_text(relative) +
                        " (the operator is singular or rounding dominates)";
    } else if (result_.iterations >= options_.max_iterations) {
      result_.status = GmresStatus::max_iterations;
      result_.message = "not converged: " + iterations + " iterations (the maximum) left the relative residual at " +
                        number_text(relative) + " > " + number_text(options_.tolerance);
    } else {
      return false;
    }
    return true;
  }

  void stagnated(double relative) {
    result_.status = GmresStatus::stagnated;
    result_.message = "not converged: GMRES(" + std::to_string(m_) + ") stagnated, " +
                      std::to_string(options_.stagnation_cycles) +
                      " restart cycles in a row cut the residual by less than " +
                      number_text(100.0 * options_.stagnation_reduction) + " %; relative residual " +
                      number_text(relative) + " after " + std::to_string(result_.iterations) +
                      " iterations (a larger restart length m may converge)";
  }

  const LinearOperator& A_;
  const Vector& b_;
  const GmresOptions& options_;
  const GmresMonitor& monitor_;
  const LinearOperator* preconditioner_;
  const Index n_;
  const int m_;
  GmresResult result_;
  Vector r_, w_, z_;  // residual, Arnoldi vector, preconditioned vector
  double r00_ = 0.0;
  Matrix V_, H_;      // the cycle's Krylov basis; its Hessenberg matrix, rotated to R
  Vector cs_, sn_, g_;  // the Givens rotations; the rotated right-hand side beta e_1
};

}  // namespace

GmresResult gmres(const LinearOperator& A, const Vector& b, const GmresOptions& options, const Vector& x0,
                  const GmresMonitor& monitor, const LinearOperator* right_preconditioner) {
  check_arguments(A, b, options, right_preconditioner);
  return RestartedGmres(A, b, options, monitor, right_preconditioner).solve(x0);
}

}  // namespace bemcontact::operators

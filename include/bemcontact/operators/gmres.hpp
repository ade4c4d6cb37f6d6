#pragma once
// Restarted GMRES(m) ([Kosior1997, Alg IV.3, IV.4]; [SaadSchultz1986]) on a LinearOperator:
// Arnoldi with modified Gram-Schmidt (one re-orthogonalisation pass when cancellation is
// detected), Givens rotations for the small least-squares problem, restart every m steps.
//
// Convergence test of Alg IV.4: ||r_n|| / ||r_00|| < tolerance, r_00 = b - A x_0 the first
// residual. The solver never loops silently: it stops and says why when
//  - max_iterations Arnoldi steps have been taken (status max_iterations),
//  - a whole restart cycle reduced the residual by less than stagnation_reduction, for
//    stagnation_cycles cycles in a row (status stagnated: GMRES(m) with too small an m on
//    an indefinite operator stalls; the residual of GMRES never grows),
//  - the Krylov space became invariant (h_{j+1,j} = 0) while the true residual is still
//    above the tolerance, or the Hessenberg matrix is singular (status breakdown).
#include <functional>
#include <string>
#include <vector>

#include "bemcontact/operators/linear_operator.hpp"

namespace bemcontact::operators {

struct GmresOptions {
  int restart = 20;            // m
  double tolerance = 1e-8;     // on ||r|| / ||r_00||
  int max_iterations = 1000;   // Arnoldi steps (operator applications) over all cycles
  int stagnation_cycles = 5;
  double stagnation_reduction = 1e-3;  // a cycle must cut the residual by this fraction
};

enum class GmresStatus { converged, max_iterations, stagnated, breakdown };
const char* to_string(GmresStatus status);

struct GmresResult {
  Vector x;
  GmresStatus status = GmresStatus::max_iterations;
  int iterations = 0;          // Arnoldi steps
  int restarts = 0;            // completed cycles after the first
  // ||r|| / ||r_00|| after every Arnoldi step (the least-squares estimate), starting with
  // 1 for the initial residual; at each restart the estimate is replaced by the true
  // residual.
  std::vector<double> residual_history;
  double relative_residual = 0.0;  // true ||b - A x|| / ||r_00|| at the end
  double initial_residual = 0.0;   // ||r_00||
  std::string message;             // why it stopped, in words
  bool converged() const { return status == GmresStatus::converged; }
};

// Called after every Arnoldi step with (iteration, relative residual estimate).
using GmresMonitor = std::function<void(int iteration, double relative_residual)>;

// Solves A x = b from x0 (zero when empty). A must be square. With a right preconditioner
// M^-1 the Krylov space is that of A M^-1 and x = x0 + M^-1 (V y): the residual tested and
// reported stays the true ||b - A x||.
GmresResult gmres(const LinearOperator& A, const Vector& b, const GmresOptions& options,
                  const Vector& x0 = Vector(), const GmresMonitor& monitor = {},
                  const LinearOperator* right_preconditioner = nullptr);

// A dense matrix as a LinearOperator (tests, small problems).
class DenseOperator : public LinearOperator {
 public:
  explicit DenseOperator(Matrix matrix) : matrix_(std::move(matrix)) {}
  Index rows() const override { return matrix_.rows(); }
  Index cols() const override { return matrix_.cols(); }
  void apply(const Vector& x, Vector& y) const override { y.noalias() = matrix_ * x; }

 private:
  Matrix matrix_;
};

}  // namespace bemcontact::operators

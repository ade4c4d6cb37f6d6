#include "bemcontact/parallel/session.hpp"

#include <petscksp.h>

#include <cstdio>
#include <string>

#include "bemcontact/core/error.hpp"

namespace bemcontact::parallel {

namespace {

void check(PetscErrorCode code, const char* what) {
  if (code != 0) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    throw SolverError(std::string("PETSc failed in ") + what + (text ? std::string(": ") + text : std::string()));
  }
}

// A PETSc vector's rows of this process <-> the whole vector on every process.
struct ShellContext {
  const operators::LinearOperator* op = nullptr;
  VecScatter to_all = nullptr;
  Vec all = nullptr;
  PetscInt first = 0, last = 0;
  Vector whole, image;
};

PetscErrorCode gather(ShellContext& c, Vec x) {
  PetscCall(VecScatterBegin(c.to_all, x, c.all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(c.to_all, x, c.all, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* values = nullptr;
  PetscCall(VecGetArrayRead(c.all, &values));
  for (Index i = 0; i < c.whole.size(); ++i) c.whole[i] = values[i];
  PetscCall(VecRestoreArrayRead(c.all, &values));
  return 0;
}

PetscErrorCode apply_shell(ShellContext& c, Vec x, Vec y) {
  PetscCall(gather(c, x));
  try {
    c.op->apply(c.whole, c.image);  // sums over the processes itself
  } catch (const std::exception& e) {
    // The other processes are inside the same collective product: end them all.
    std::fprintf(stderr, "bemcontact: solver error: %s\n", e.what());
    MPI_Abort(PETSC_COMM_WORLD, 3);
  }
  PetscScalar* values = nullptr;
  PetscCall(VecGetArray(y, &values));
  for (PetscInt i = c.first; i < c.last; ++i) values[i - c.first] = c.image[i];
  PetscCall(VecRestoreArray(y, &values));
  return 0;
}

PetscErrorCode matrix_product(Mat A, Vec x, Vec y) {
  ShellContext* c = nullptr;
  PetscCall(MatShellGetContext(A, &c));
  return apply_shell(*c, x, y);
}

PetscErrorCode preconditioner_product(PC pc, Vec x, Vec y) {
  ShellContext* c = nullptr;
  PetscCall(PCShellGetContext(pc, &c));
  return apply_shell(*c, x, y);
}

struct MonitorContext {
  const operators::GmresMonitor* monitor = nullptr;
  std::vector<double>* history = nullptr;
  double initial = 0.0;
};

PetscErrorCode record_residual(KSP, PetscInt iteration, PetscReal norm, void* context) {
  auto& m = *static_cast<MonitorContext*>(context);
  const double relative = m.initial > 0.0 ? norm / m.initial : 0.0;
  if (iteration > 0) m.history->push_back(relative);
  if (iteration > 0 && m.monitor && *m.monitor) (*m.monitor)(static_cast<int>(iteration), relative);
  return 0;
}

// Frees PETSc objects on every path out.
struct PetscObjects {
  Vec x = nullptr, b = nullptr, all = nullptr;
  VecScatter to_all = nullptr;
  Mat A = nullptr;
  KSP ksp = nullptr;
  ~PetscObjects() {
    KSPDestroy(&ksp);
    MatDestroy(&A);
    VecScatterDestroy(&to_all);
    VecDestroy(&all);
    VecDestroy(&b);
    VecDestroy(&x);
  }
};

}  // namespace

MpiSession::MpiSession() {
  // The command handles its own signals (io/output_directory.hpp); PETSc's would print a
  // traceback instead.
  PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
  check(PetscInitializeNoArguments(), "PetscInitialize");
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { PetscFinalize(); }

void MpiSession::abort(int code) const {
  std::fflush(stdout);
  std::fflush(stderr);
  MPI_Abort(PETSC_COMM_WORLD, code);
  std::abort();  // (MPI_Abort does not return)
}

dd::ParallelRun MpiSession::decomposition_run() const {
  dd::ParallelRun run;
  run.distribution.rank = rank_;
  run.distribution.size = size_;
  if (size_ == 1) return run;  // one process: exactly the serial path (operators::gmres)
  run.distribution.sum_over_processes = [](double* data, std::size_t count) {
    if (MPI_Allreduce(MPI_IN_PLACE, data, static_cast<int>(count), MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD) !=
        MPI_SUCCESS)
      throw SolverError("MPI_Allreduce failed");
  };
  run.krylov = petsc_gmres;
  return run;
}

operators::GmresResult petsc_gmres(const operators::LinearOperator& K, const Vector& F,
                                   const operators::GmresOptions& options, const operators::GmresMonitor& monitor,
                                   const operators::LinearOperator* right_preconditioner) {
  const PetscInt n = static_cast<PetscInt>(K.rows());
  PetscObjects o;
  check(VecCreateMPI(PETSC_COMM_WORLD, PETSC_DECIDE, n, &o.b), "VecCreateMPI");
  check(VecDuplicate(o.b, &o.x), "VecDuplicate");
  check(VecScatterCreateToAll(o.b, &o.to_all, &o.all), "VecScatterCreateToAll");
  PetscInt first = 0, last = 0;
  check(VecGetOwnershipRange(o.b, &first, &last), "VecGetOwnershipRange");
  {
    PetscScalar* values = nullptr;
    check(VecGetArray(o.b, &values), "VecGetArray");
    for (PetscInt i = first; i < last; ++i) values[i - first] = F[i];
    check(VecRestoreArray(o.b, &values), "VecRestoreArray");
  }
  ShellContext operator_context{&K, o.to_all, o.all, first, last, Vector::Zero(n), Vector()};
  ShellContext preconditioner_context{right_preconditioner, o.to_all, o.all, first, last, Vector::Zero(n), Vector()};
  check(MatCreateShell(PETSC_COMM_WORLD, last - first, last - first, n, n, &operator_context, &o.A), "MatCreateShell");
  check(MatShellSetOperation(o.A, MATOP_MULT, reinterpret_cast<void (*)(void)>(matrix_product)), "MatShellSetOperation");

  check(KSPCreate(PETSC_COMM_WORLD, &o.ksp), "KSPCreate");
  check(KSPSetOperators(o.ksp, o.A, o.A), "KSPSetOperators");
  check(KSPSetType(o.ksp, KSPGMRES), "KSPSetType");
  check(KSPGMRESSetRestart(o.ksp, options.restart), "KSPGMRESSetRestart");
  check(KSPGMRESSetOrthogonalization(o.ksp, KSPGMRESModifiedGramSchmidtOrthogonalization), "KSPGMRESSetOrthogonalization");
  check(KSPSetTolerances(o.ksp, options.tolerance, 1e-300, PETSC_DEFAULT, options.max_iterations), "KSPSetTolerances");
  PC pc = nullptr;
  check(KSPGetPC(o.ksp, &pc), "KSPGetPC");
  if (right_preconditioner) {
    check(PCSetType(pc, PCSHELL), "PCSetType");
    check(PCShellSetContext(pc, &preconditioner_context), "PCShellSetContext");
    check(PCShellSetApply(pc, preconditioner_product), "PCShellSetApply");
  } else {
    check(PCSetType(pc, PCNONE), "PCSetType");
  }
  check(KSPSetPCSide(o.ksp, PC_RIGHT), "KSPSetPCSide");
  check(KSPSetNormType(o.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");

  operators::GmresResult result;
  result.initial_residual = F.norm();  // x0 = 0
  result.residual_history.push_back(result.initial_residual > 0.0 ? 1.0 : 0.0);
  MonitorContext monitor_context{&monitor, &result.residual_history, result.initial_residual};
  check(KSPMonitorSet(o.ksp, record_residual, &monitor_context, nullptr), "KSPMonitorSet");
  check(KSPSolve(o.ksp, o.b, o.x), "KSPSolve");

  PetscInt iterations = 0;
  KSPConvergedReason reason;
  check(KSPGetIterationNumber(o.ksp, &iterations), "KSPGetIterationNumber");
  check(KSPGetConvergedReason(o.ksp, &reason), "KSPGetConvergedReason");
  result.iterations = static_cast<int>(iterations);
  result.restarts = options.restart > 0 ? std::max(0, (result.iterations - 1) / options.restart) : 0;
  check(gather(operator_context, o.x), "VecScatter");
  result.x = operator_context.whole;
  Vector image;
  K.apply(result.x, image);
  result.relative_residual = result.initial_residual > 0.0 ? (F - image).norm() / result.initial_residual : 0.0;
  char relative[32];
  std::snprintf(relative, sizeof relative, "%.3g", result.relative_residual);
  const std::string why = KSPConvergedReasons[reason];
  if (reason > 0) {
    result.status = operators::GmresStatus::converged;
    result.message = "converged in " + std::to_string(result.iterations) + " iterations (relative residual " +
                     relative + "; PETSc GMRES on " + std::to_string(n) + " unknowns)";
  } else if (reason == KSP_DIVERGED_ITS) {
    result.status = operators::GmresStatus::max_iterations;
    result.message = "not converged: " + std::to_string(result.iterations) +
                     " iterations (the maximum) left the relative residual at " + relative + " (PETSc GMRES)";
  } else {
    result.status = operators::GmresStatus::breakdown;
    result.message = "not converged: PETSc GMRES stopped with " + why + " after " +
                     std::to_string(result.iterations) + " iterations; relative residual " + relative;
  }
  return result;
}

}  // namespace bemcontact::parallel

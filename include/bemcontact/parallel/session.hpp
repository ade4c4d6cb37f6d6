#pragma once
// Distributed runs (CMake option BEMCONTACT_WITH_MPI; OpenMPI and PETSc from Debian): the
// command starts one MpiSession for its whole life. Under `mpirun -n P bemcontact run FILE`
// every process reads the same file; a decomposition's subdomains are spread over the P
// processes (dd/distribution.hpp) and its interface problem is solved by PETSc's GMRES on a
// matrix-free shell operator, with the balancing preconditioner as a shell preconditioner.
// Only the root process (rank 0) prints and writes the outputs.
#include "bemcontact/dd/distribution.hpp"

namespace bemcontact::parallel {

class MpiSession {
 public:
  MpiSession();   // PetscInitialize (which starts MPI), without the command's arguments
  ~MpiSession();                        // PetscFinalize
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // This process's place among all, with sums by MPI_Allreduce, and PETSc's Krylov solver;
  // on one process the serial path itself (no sums, operators::gmres).
  dd::ParallelRun decomposition_run() const;
  // Ends every process at once (after a failure on this one that the others cannot see).
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0;
  int size_ = 1;
};

// GMRES(m) from PETSc (KSPGMRES, modified Gram-Schmidt, right preconditioning so that the
// tested residual is the true one, relative to ||F||) on the interface problem: the same
// contract as operators::gmres; K and the preconditioner are applied to the whole vector on
// every process (they sum over processes themselves), each process keeping its own rows.
operators::GmresResult petsc_gmres(const operators::LinearOperator& K, const Vector& F,
                                   const operators::GmresOptions& options, const operators::GmresMonitor& monitor,
                                   const operators::LinearOperator* right_preconditioner);

}  // namespace bemcontact::parallel

#pragma once
// How the subdomains of a decomposition are spread over processes (MPI ranks). The numerics
// never call MPI: they sum their partial results through `sum_over_processes`, which the
// command sets from MPI when it runs under mpirun (parallel/session.hpp) and which is empty
// on one process. Every process holds every mesh and the interface vectors whole; each
// assembles, factors and solves only the subdomains it owns.
#include <cstddef>
#include <functional>
#include <vector>

#include "bemcontact/core/types.hpp"
#include "bemcontact/operators/gmres.hpp"

namespace bemcontact::dd {

struct Distribution {
  int rank = 0;
  int size = 1;
  std::vector<int> owner;  // per subdomain; empty: this process owns all
  // In place, the sum over every process of `count` doubles (identical on every process).
  std::function<void(double* data, std::size_t count)> sum_over_processes;

  bool owns(std::size_t subdomain) const { return owner.empty() || owner[subdomain] == rank; }
  bool root() const { return rank == 0; }
  void sum(double* data, std::size_t count) const {
    if (sum_over_processes) sum_over_processes(data, count);
  }
  void sum(Vector& v) const { sum(v.data(), static_cast<std::size_t>(v.size())); }
  void sum(Matrix& m) const { sum(m.data(), static_cast<std::size_t>(m.size())); }
  // Makes every process hold the root's values, bit for bit (so that decisions taken on them,
  // such as a rank, agree everywhere).
  void broadcast_from_root(Matrix& m) const {
    if (!sum_over_processes) return;
    if (!root()) m.setZero();
    sum(m);
  }
};

// Owner of each subdomain: the costliest first to the least loaded process (longest
// processing time first; ties to the lowest rank, so every process computes the same).
std::vector<int> assign_subdomains(const std::vector<double>& costs, int processes);

// The Krylov solver of the interface problem: operators::gmres on one process, PETSc's
// KSP under MPI. Arguments as operators::gmres (x0 zero).
using InterfaceKrylov = std::function<operators::GmresResult(
    const operators::LinearOperator& K, const Vector& F, const operators::GmresOptions& options,
    const operators::GmresMonitor& monitor, const operators::LinearOperator* right_preconditioner)>;

struct ParallelRun {
  Distribution distribution;
  InterfaceKrylov krylov;  // empty: operators::gmres
};

}  // namespace bemcontact::dd

#include "bemcontact/dd/solver.hpp"

#include <chrono>
#include <cmath>
#include <memory>

#include "bemcontact/bem/resultants.hpp"
#include "bemcontact/bem/assembly.hpp"
#include "bemcontact/bem/postprocess.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/dd/balancing.hpp"
#include "bemcontact/dd/interface_operator.hpp"

namespace bemcontact::dd {

namespace {

class PhaseClock {
 public:
  explicit PhaseClock(bem::PhaseTimings& timings) : timings_(timings) {}
  void lap(const std::string& phase) {
    const auto now = std::chrono::steady_clock::now();
    timings_.add(phase, std::chrono::duration<double>(now - start_).count());
    start_ = now;
  }

 private:
  bem::PhaseTimings& timings_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

double relative(double difference, double a, double b) {
  const double size = std::max(a, b);
  return difference / (size > 1e-300 ? size : 1.0);
}

}  // namespace

std::vector<InterfaceJump> interface_jumps(const Connectivity& connectivity,
                                           const std::vector<SubdomainResult>& subdomains) {
  std::vector<InterfaceJump> jumps;
  for (const auto& interface : connectivity.interfaces) {
    const auto& a = subdomains[interface.subdomain_a].boundary;
    const auto& b = subdomains[interface.subdomain_b].boundary;
    double du = 0, dp = 0, ua = 0, ub = 0, pa = 0, pb = 0;
    InterfaceJump jump;
    jump.name = interface.name;
    for (const auto& pair : interface.pairs) {
      du += (a.displacement[pair.node_a] - b.displacement[pair.node_b]).squaredNorm();
      dp += (a.traction[pair.node_a] + b.traction[pair.node_b]).squaredNorm();
      ua += a.displacement[pair.node_a].squaredNorm();
      ub += b.displacement[pair.node_b].squaredNorm();
      pa += a.traction[pair.node_a].squaredNorm();
      pb += b.traction[pair.node_b].squaredNorm();
      ++jump.pairs;
      if (pair.kind == bem::ConditionKind::displacement) ++jump.displacement_pairs;
    }
    jump.jump_u = relative(std::sqrt(du), std::sqrt(ua), std::sqrt(ub));
    jump.jump_p = relative(std::sqrt(dp), std::sqrt(pa), std::sqrt(pb));
    jumps.push_back(jump);
  }
  return jumps;
}

namespace {

// Boundary displacements and tractions of every subdomain, and the condition estimates,
// summed over the processes (each fills the subdomains it owns).
void share_boundary_solutions(const Distribution& distribution, std::vector<SubdomainResult>& subdomains) {
  if (!distribution.sum_over_processes) return;
  Index size = 0;
  for (const auto& sub : subdomains) size += 4 * sub.mesh.node_count() + 1;
  Vector packed = Vector::Zero(size);
  Index at = 0;
  for (std::size_t s = 0; s < subdomains.size(); ++s) {
    const Index n = subdomains[s].mesh.node_count();
    if (distribution.owns(s)) {
      for (Index i = 0; i < n; ++i) {
        packed.segment<2>(at + 4 * i) = subdomains[s].boundary.displacement[i];
        packed.segment<2>(at + 4 * i + 2) = subdomains[s].boundary.traction[i];
      }
      packed[at + 4 * n] = subdomains[s].reciprocal_condition;
    }
    at += 4 * n + 1;
  }
  distribution.sum(packed);
  at = 0;
  for (auto& sub : subdomains) {
    const Index n = sub.mesh.node_count();
    sub.boundary.displacement.resize(static_cast<std::size_t>(n));
    sub.boundary.traction.resize(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) {
      sub.boundary.displacement[i] = packed.segment<2>(at + 4 * i);
      sub.boundary.traction[i] = packed.segment<2>(at + 4 * i + 2);
    }
    sub.reciprocal_condition = packed[at + 4 * n];
    at += 4 * n + 1;
  }
}

void check_options(const DecompositionProblem& problem) {
  if (problem.subdomains.empty()) throw Error("solve_decomposition: no subdomains");
  if (problem.options.preconditioner == InterfacePreconditioner::balancing &&
      problem.options.method != InterfaceMethod::conforming)
    throw Error("solve_decomposition: the balancing preconditioner is for the conforming method");
}

// The subdomains' owners: the run's, or balanced over its processes by the cost of each
// subdomain's LU, (2 nodes)^3.
Distribution distribute(const ParallelRun& parallel, const std::vector<geometry::BoundaryMesh>& meshes) {
  Distribution distribution = parallel.distribution;
  if (distribution.size > 1 && distribution.owner.empty()) {
    std::vector<double> costs;
    for (const auto& mesh : meshes) costs.push_back(std::pow(2.0 * static_cast<double>(mesh.node_count()), 3));
    distribution.owner = assign_subdomains(costs, distribution.size);
  }
  return distribution;
}

// The interface problem K u = F by GMRES (Alg IV.4), or by the run's own Krylov solver.
operators::GmresResult solve_interface(const DecompositionProblem& problem, const InterfaceOperator& K,
                                       const Vector& F, const BalancingPreconditioner* preconditioner,
                                       const ParallelRun& parallel, const bem::ProgressCallback& progress) {
  operators::GmresResult out;
  operators::GmresOptions options;
  options.restart = effective_restart(problem.options, K.rows());
  options.tolerance = problem.options.tolerance;
  options.max_iterations = problem.options.max_iterations;
  operators::GmresMonitor monitor;
  if (progress)
    monitor = [&](int iteration, double) {
      progress("gmres", std::min(1.0, static_cast<double>(iteration) / std::max(1, options.max_iterations)));
    };
  if (K.rows() > 0) {
    out = parallel.krylov ? parallel.krylov(K, F, options, monitor, preconditioner)
                          : operators::gmres(K, F, options, Vector(), monitor, preconditioner);  // Alg IV.4
  } else {
    out.x = Vector();
    out.status = operators::GmresStatus::converged;
    out.message = "no interface";
    out.residual_history = {0.0};
  }
  if (progress) progress("gmres", 1.0);
  return out;
}

// Every subdomain's boundary solution from the interface unknowns (each process those it
// owns, then shared), with its stresses and resultants, and the jumps across the interfaces.
void recover_subdomains(const DecompositionProblem& problem, const std::vector<geometry::BoundaryMesh>& meshes,
                        const InterfaceOperator& K, const Distribution& distribution, DecompositionResult& result) {
  for (std::size_t s = 0; s < problem.subdomains.size(); ++s) {
    SubdomainResult sub;
    sub.name = problem.subdomains[s].body.name;
    sub.mesh = meshes[s];
    if (distribution.owns(s)) {
      sub.boundary = K.subdomain_solution(s, result.gmres.x);
      sub.reciprocal_condition = K.body(s).reciprocal_condition();
    }
    result.subdomains.push_back(std::move(sub));
  }
  share_boundary_solutions(distribution, result.subdomains);
  for (std::size_t s = 0; s < problem.subdomains.size(); ++s) {
    auto& sub = result.subdomains[s];
    sub.boundary.stress = bem::boundary_stresses(sub.mesh, problem.analysis, problem.subdomains[s].body.material,
                                                 sub.boundary);
    sub.boundary.resultants =
        bem::boundary_resultants(sub.mesh, sub.boundary, problem.subdomains[s].body, problem.analysis);
  }
  result.jumps = interface_jumps(result.connectivity, result.subdomains);
}

// The interior points of every subdomain that lists some; false when none does.
bool add_interior_points(const DecompositionProblem& problem, const bem::ProgressCallback& progress,
                         DecompositionResult& result) {
  bool any_interior = false;
  for (std::size_t s = 0; s < problem.subdomains.size(); ++s) {
    const auto& points = problem.subdomains[s].interior_points;
    if (points.empty()) continue;
    any_interior = true;
    auto& sub = result.subdomains[s];
    const bem::ElementIntegrator integrator(problem.analysis, problem.subdomains[s].body.material);
    auto selection = bem::select_interior_points(sub.mesh, points);
    if (!selection.listed_outside.empty()) {
      const auto& p = *selection.listed_outside.front();
      throw InputError(p.where.file.empty() ? SourceLocation{problem.source_file, 0, "subdomain '" + sub.name + "' interior.points"} : p.where,
                       "point (" + std::to_string(p.position.x()) + ", " + std::to_string(p.position.y()) +
                           ") is not inside subdomain '" + sub.name + "'");
    }
    sub.interior = bem::interior_values(sub.mesh, integrator, sub.boundary, std::move(selection), progress);
  }
  return any_interior;
}

}  // namespace

DecompositionResult solve_decomposition(const DecompositionProblem& problem, const bem::ProgressCallback& progress,
                                        const ParallelRun& parallel) {
  check_options(problem);
  DecompositionResult result;
  result.method = problem.options.method;
  result.preconditioner = problem.options.preconditioner;
  PhaseClock clock(result.timings);
  const std::vector<geometry::BoundaryMesh> meshes = mesh_subdomains(problem);
  result.connectivity = build_connectivity(problem, meshes);
  result.interface_unknowns = result.connectivity.unknowns;
  clock.lap("mesh and interfaces");

  const Distribution distribution = distribute(parallel, meshes);
  result.processes = distribution.size;
  result.owner = distribution.owner.empty() ? std::vector<int>(meshes.size(), 0) : distribution.owner;
  const InterfaceOperator K(problem, meshes, result.connectivity, progress, distribution);
  result.displacement_scale = K.displacement_scale();
  double memory = static_cast<double>(K.memory_bytes());
  distribution.sum(&memory, 1);
  result.factor_memory_bytes = static_cast<std::size_t>(memory);
  clock.lap("assembly and factorisation");

  const Vector F = K.right_hand_side();  // Alg IV.2
  clock.lap("right-hand side");
  std::unique_ptr<BalancingPreconditioner> preconditioner;
  if (problem.options.preconditioner == InterfacePreconditioner::balancing && K.rows() > 0) {
    preconditioner = std::make_unique<BalancingPreconditioner>(K, result.connectivity, problem.analysis);
    result.coarse_dimension = preconditioner->coarse_dimension();
    result.floating_modes = preconditioner->floating_modes();
    clock.lap("preconditioner");
  }
  result.gmres = solve_interface(problem, K, F, preconditioner.get(), parallel, progress);
  clock.lap("gmres");

  recover_subdomains(problem, meshes, K, distribution, result);
  double solves = static_cast<double>(K.solves());
  distribution.sum(&solves, 1);
  result.subdomain_solves = static_cast<long>(solves) + static_cast<long>(problem.subdomains.size());
  clock.lap("recovery and boundary stress");
  if (!distribution.root()) return result;  // the root evaluates the interior points and writes
  if (add_interior_points(problem, progress, result)) clock.lap("interior points");
  return result;
}

}  // namespace bemcontact::dd

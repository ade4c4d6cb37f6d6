#pragma once
// Solving a decomposed body (chapter IV): mesh the subdomains, build the connection table,
// factor each subdomain once, solve the interface problem by GMRES(m) (Alg IV.4; with the
// conforming method preconditioned by balancing, dd/balancing.hpp), then
// recover every subdomain's boundary solution, boundary stresses and interior points.
#include <string>
#include <vector>

#include "bemcontact/bem/progress.hpp"
#include "bemcontact/bem/solution.hpp"
#include "bemcontact/dd/distribution.hpp"
#include "bemcontact/dd/interface.hpp"
#include "bemcontact/operators/gmres.hpp"

namespace bemcontact::dd {

struct SubdomainResult {
  std::string name;
  geometry::BoundaryMesh mesh;
  bem::BoundarySolution boundary;  // displacement, traction, stress per node
  bem::InteriorSolution interior;
  double reciprocal_condition = 0.0;  // of the subdomain's factored system
};

// Continuity measured on one interface, relative to the size of the field there:
//   jump_u = ||u_a - u_b|| / max(||u_a||, ||u_b||),  jump_p = ||p_a + p_b|| / max(||p_a||, ||p_b||)
// (Euclidean norms over all pairs and both components; cf. (IV.20)). A norm below 1e-300
// counts as 1, so a vanishing field gives the absolute jump.
struct InterfaceJump {
  std::string name;
  double jump_u = 0.0;
  double jump_p = 0.0;
  Index pairs = 0;
  Index displacement_pairs = 0;  // pairs in gamma_d
};

struct DecompositionResult {
  InterfaceMethod method = InterfaceMethod::conforming;
  InterfacePreconditioner preconditioner = InterfacePreconditioner::none;
  Index coarse_dimension = 0;      // balancing: rigid modes in the coarse space
  std::vector<int> floating_modes; // balancing: per subdomain, rigid modes its interface map leaves free
  std::vector<SubdomainResult> subdomains;
  Connectivity connectivity;
  std::vector<InterfaceJump> jumps;
  operators::GmresResult gmres;  // status, iterations, residual history
  Index interface_unknowns = 0;
  double displacement_scale = 1.0;
  long subdomain_solves = 0;
  std::size_t factor_memory_bytes = 0;  // over all processes
  int processes = 1;
  std::vector<int> owner;  // per subdomain, its process
  bem::PhaseTimings timings;
  bool converged() const { return gmres.converged(); }
};

// Jumps of u and p on every interface of a solved decomposition.
std::vector<InterfaceJump> interface_jumps(const Connectivity& connectivity,
                                           const std::vector<SubdomainResult>& subdomains);

// The whole solve. GMRES's failure to converge is not an exception: the result carries
// gmres.status and gmres.message (the caller reports it and exits with a solver failure),
// and the subdomain solutions of the last iterate. Input and geometry errors throw
// InputError / GeometryError; a subdomain left free to move by its interface conditions
// throws SolverError naming it and suggesting another method.
//
// With `parallel` spread over several processes (parallel.distribution.size > 1), every
// process calls this with the same problem: subdomains are assigned by their n^3 cost, each
// process factors and solves its own, the interface problem is solved by parallel.krylov,
// and every process ends with every subdomain's boundary solution; interior points are
// evaluated on the root process only (the one that writes the outputs).
DecompositionResult solve_decomposition(const DecompositionProblem& problem,
                                        const bem::ProgressCallback& progress = {},
                                        const ParallelRun& parallel = {});

}  // namespace bemcontact::dd

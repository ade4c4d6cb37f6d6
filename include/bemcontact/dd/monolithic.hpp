#pragma once
// Multi-region boundary elements in one dense system: an independent cross-check of the
// iterative interface solve (it uses neither FactoredBody, nor the interface operator,
// nor GMRES).
//
// Unknowns: per subdomain, the usual unknowns of its system A_l y_l = b_l with its
// interface nodes treated as displacement nodes (so y_l holds their tractions), plus one
// shared displacement per interface pair. Equations: every subdomain's collocation and
// constraint rows, A_l y_l + H_l(:, interface) U = b_l, and equilibrium p_a + p_b = 0 at
// every pair. Dense LU of size sum(2 n_l + constraints) + 2 pairs.
#include <vector>

#include "bemcontact/bem/solution.hpp"
#include "bemcontact/dd/interface.hpp"

namespace bemcontact::dd {

struct MonolithicResult {
  std::vector<bem::BoundarySolution> boundary;  // per subdomain: u and p at its nodes (no stress)
  Index unknowns = 0;
  double reciprocal_condition = 0.0;
};

MonolithicResult solve_monolithic(const DecompositionProblem& problem,
                                  const std::vector<geometry::BoundaryMesh>& meshes,
                                  const Connectivity& connectivity);

}  // namespace bemcontact::dd

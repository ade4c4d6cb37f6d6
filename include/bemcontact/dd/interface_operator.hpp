#pragma once
// The condensed interface problem K Y = F of (IV.6), applied matrix-free.
//
// Every subdomain is assembled and factored once (FactoredBody) with its interface nodes
// as variable nodes: displacement data at the pairs of kind displacement (gamma_d),
// traction data at the pairs of kind traction (gamma_c). One application of K (Alg IV.1)
// is one solve per subdomain with its own data switched off:
//   gamma_d pair (unknown u):  u_a = u_b = u           ->  residual p_a + p_b   (equilibrium)
//   gamma_c pair (unknown p):  p_a = p, p_b = -p       ->  residual u_a - u_b   (compatibility)
// The right-hand side (Alg IV.2) is F = -r(0), r(0) the residual of Y = 0 with the
// subdomains' own data on (a sign convention: (IV.8) prints r(0) itself).
//
// Units: displacement unknowns and compatibility residuals are multiplied by
// displacement_scale = mu / h (mean shear modulus over the mean spacing of interface
// nodes), so that every unknown and every residual is a traction. Without it the mixed
// operator holds blocks of sizes E/h and h/E (10^6 apart in the thesis' plate) and GMRES's
// Euclidean residual ignores one of them. mu / h is the size of S on the finest mode the
// mesh carries; on the strips of IV.5 it gives the fewest iterations of the scales tried
// (mu/L, 0.3, 3 and 10 times mu/h; L the geometry size).
#include <optional>
#include <vector>

#include "bemcontact/bem/factored_body.hpp"
#include "bemcontact/dd/distribution.hpp"
#include "bemcontact/dd/interface.hpp"
#include "bemcontact/operators/linear_operator.hpp"

namespace bemcontact::dd {

class InterfaceOperator : public operators::LinearOperator {
 public:
  // Assembles and factors every subdomain this process owns (the expensive part); progress
  // as "factorisation". Products and residuals are summed over the processes.
  InterfaceOperator(const DecompositionProblem& problem, const std::vector<geometry::BoundaryMesh>& meshes,
                    const Connectivity& connectivity, const bem::ProgressCallback& progress = {},
                    const Distribution& distribution = {});

  Index rows() const override { return connectivity_.unknowns; }
  Index cols() const override { return connectivity_.unknowns; }
  void apply(const Vector& y, Vector& ky) const override;  // Alg IV.1

  Vector right_hand_side() const;  // Alg IV.2
  // Interface residual r(Y) = K Y + r(0) (with_fixed_data) or K Y.
  Vector residual(const Vector& y, bool with_fixed_data) const;
  // The variable data of subdomain s for interface unknowns y (FactoredBody's order).
  Vector subdomain_data(std::size_t s, const Vector& y) const;
  // The full boundary solution of an owned subdomain s for interface unknowns y.
  bem::BoundarySolution subdomain_solution(std::size_t s, const Vector& y) const;
  const Distribution& distribution() const { return distribution_; }

  // Subdomain s's explicit interface map in the units of the unknowns and residuals (the
  // contribution R_s^T K_s R_s of s to K); needs explicit maps.
  Matrix local_operator(std::size_t s) const;

  double displacement_scale() const { return scale_; }
  const bem::FactoredBody& body(std::size_t s) const { return *bodies_[s]; }  // owned only
  std::size_t subdomain_count() const { return bodies_.size(); }
  // Number of subdomain solves done by apply/residual so far on this process (for reports).
  long solves() const { return solves_; }
  // Bytes held by this process's factored subdomains (LU factors, right-hand-side columns
  // and, with explicit_operators, the interface maps).
  std::size_t memory_bytes() const;

 private:
  const Connectivity& connectivity_;
  Distribution distribution_;
  std::vector<std::optional<bem::FactoredBody>> bodies_;  // empty where another process owns it
  // explicit_operators: per subdomain, complementary field = maps_[s] * data + responses_[s]
  // (the response to the subdomain's own data).
  std::vector<Matrix> maps_;
  std::vector<Vector> responses_;
  double scale_ = 1.0;
  mutable long solves_ = 0;
};

}  // namespace bemcontact::dd

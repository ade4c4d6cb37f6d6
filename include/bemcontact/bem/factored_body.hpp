#pragma once
// A body whose boundary element system is assembled and factored once, then solved for
// many right-hand sides in which the data of chosen "variable" nodes change: the
// interface nodes of a domain decomposition (Poincare-Steklov operators S and S^-1,
// section IV.3.1) or the contact nodes of chapter V (B' = S1^-1 + S2^-1).
//
// Variable nodes carry, in global components, either prescribed displacements (the
// solve returns their tractions: Dirichlet-to-Neumann) or prescribed tractions (the
// solve returns their displacements: Neumann-to-Dirichlet). All other nodes keep the
// body's own conditions, whose data can be switched off to get the response to the
// variable data alone.
#include <memory>
#include <vector>

#include <Eigen/Sparse>

#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/bem/problem.hpp"
#include "bemcontact/bem/progress.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::bem {

// Point constraints may be variable too (a free body's rigid motion, the contact model's
// unknown): each such constraint prescribes one displacement component, its value is a
// variable datum after the nodes' (one per constraint) and its complementary value the
// reaction traction it adds at its node.
class FactoredBody {
 public:
  // `choice` as for one body (use_compressed_operator): a plane body from 8 000 unknowns on
  // is held on hierarchical matrices (bem/compressed_system.hpp), factored by H-LU.
  FactoredBody(const geometry::BoundaryMesh& mesh, const BodyDefinition& body, AnalysisType type,
               std::vector<VariableNode> variable_nodes, const ProgressCallback& progress = {},
               std::vector<PointConstraint> variable_constraints = {}, const OperatorChoice& choice = {});
  FactoredBody(FactoredBody&&) noexcept;
  FactoredBody& operator=(FactoredBody&&) noexcept;
  ~FactoredBody();

  const geometry::BoundaryMesh& mesh() const { return mesh_; }
  const std::vector<VariableNode>& variable_nodes() const { return variable_; }
  Index variable_dofs() const { return 2 * static_cast<Index>(variable_.size()) + variable_constraints_; }
  // NaN on compressed operators (no condition estimate of an H-LU).
  double reciprocal_condition() const;
  bool compressed() const { return compressed_ != nullptr; }

  // Full boundary solution for the given data at the variable nodes (2 per node, global
  // components, in the order of variable_nodes()). with_fixed_data = false switches off
  // the body's own prescribed values (loads, imposed displacements, constraint values).
  BoundarySolution solve(const Vector& variable_data, bool with_fixed_data = true) const;

  // The body's own prescribed values split by their load group (BoundaryCondition::
  // load_group; point constraints' values belong to group 0): load_groups() groups, the
  // complementary field of each group's values alone, and the solution with each group
  // scaled by its amplitude.
  int load_groups() const { return static_cast<int>(group_rhs_.size()); }
  Vector group_complementary(int group) const;
  BoundarySolution solve_with_amplitudes(const Vector& variable_data, const std::vector<double>& amplitudes) const;

  // Only the complementary field at the variable nodes: tractions where displacements are
  // prescribed and displacements where tractions are (2 per node).
  Vector complementary(const Vector& variable_data, bool with_fixed_data = true) const;

  // The same for several data vectors at once (columns).
  Matrix complementary_columns(const Matrix& variable_data, bool with_fixed_data) const;
  // The same for sparse data without the body's own (columns, solved in batches): the
  // response to a contact's pair tractions without the flexibility of every datum.
  Matrix complementary_columns(const Eigen::SparseMatrix<double>& variable_data) const;
  // The complementary field of each unit variable datum (variable_dofs() columns): the
  // flexibility (or stiffness) map of the variable nodes, S or S^-1, without forming the
  // identity's product with the right-hand sides.
  Matrix unit_responses() const;

 private:
  Matrix solve_unknowns(const Matrix& variable_data, bool with_fixed_data) const;
  // The right-hand sides of variable data (columns), without the body's own data.
  Matrix variable_rhs(const Matrix& variable_data) const;
  // The complementary rows of solved unknowns y (one column per data vector).
  Matrix complementary_of(const Matrix& y) const;
  BoundarySolution recover(const Vector& y, const Vector& variable_data, bool with_fixed_data) const;
  void build_compressed(const BodyDefinition& body, AnalysisType type, const OperatorChoice& choice,
                        const std::string& what, const ProgressCallback& progress);

  geometry::BoundaryMesh mesh_;
  std::vector<VariableNode> variable_;
  Index variable_constraints_ = 0;  // the last ones of constraints_
  std::vector<NodeCondition> conditions_;
  std::vector<ConstraintEquation> constraints_;
  Vector fixed_rhs_;
  std::vector<Vector> group_rhs_;  // fixed_rhs_ split by load group (they sum to it)
  // Dense path: the right-hand side per unit variable datum (columns). Compressed: empty,
  // applied through the hierarchical blocks (it would be dense in the variable nodes).
  Matrix variable_rhs_;
  std::unique_ptr<operators::DenseLU> lu_;  // dense path
  struct Compressed;       // the mesh copy, integrator and system it refers to
  std::unique_ptr<Compressed> compressed_;
  const operators::Factorization* factors_ = nullptr;  // the one of the two that is factored
};

}  // namespace bemcontact::bem

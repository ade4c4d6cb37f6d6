#include "bemcontact/bem/rigid_modes.hpp"

#include "bemcontact/operators/dense_subspaces.hpp"


namespace bemcontact::bem {

Matrix free_rigid_modes(const geometry::BoundaryMesh& mesh, const std::vector<NodeCondition>& conditions,
                        AnalysisType type) {
  const Index n = mesh.node_count();
  const int mode_count = type == AnalysisType::axisymmetric ? 1 : 3;
  Vec2 centre = Vec2::Zero();
  for (const auto& node : mesh.nodes) centre += node.position;
  centre /= static_cast<double>(n);
  Matrix modes = Matrix::Zero(2 * n, mode_count);
  for (Index i = 0; i < n; ++i) {
    const Mat2 to_frame = conditions[i].frame.transpose();
    if (type == AnalysisType::axisymmetric) {
      modes.block<2, 1>(2 * i, 0) = to_frame * Vec2(0, 1);
    } else {
      const Vec2 r = (mesh.nodes[i].position - centre) / mesh.scale;
      modes.block<2, 1>(2 * i, 0) = to_frame * Vec2(1, 0);
      modes.block<2, 1>(2 * i, 1) = to_frame * Vec2(0, 1);
      modes.block<2, 1>(2 * i, 2) = to_frame * Vec2(-r.y(), r.x());
    }
  }
  // Combinations that vanish on every prescribed displacement component, and that the body's
  // images move as themselves (geometry/symmetry.hpp): a rigid motion of the whole symmetric
  // body. A translation t qualifies when S t = t for every image S; a rotation never does.
  std::vector<Index> prescribed;
  for (Index i = 0; i < n; ++i)
    for (int c = 0; c < 2; ++c)
      if (conditions[i].kind[c] == ConditionKind::displacement) prescribed.push_back(2 * i + c);
  Matrix restricted = Matrix::Zero(static_cast<Index>(prescribed.size()) + 3 * static_cast<Index>(mesh.images.size()), mode_count);
  for (std::size_t k = 0; k < prescribed.size(); ++k) restricted.row(static_cast<Index>(k)) = modes.row(prescribed[k]);
  for (std::size_t k = 0; k < mesh.images.size(); ++k) {
    const Mat2 antisymmetric = Mat2::Identity() - mesh.images[k].matrix;
    const Index row = static_cast<Index>(prescribed.size() + 3 * k);
    if (type == AnalysisType::axisymmetric) {
      restricted.block<2, 1>(row, 0) = antisymmetric * Vec2(0, 1);
    } else {
      restricted.block<2, 2>(row, 0) = antisymmetric;
      restricted(row + 2, 2) = 1.0;
    }
  }
  if (restricted.rows() == 0) return modes;
  return modes * operators::null_space(restricted, 1e-10, 1.0);
}

bool constraints_fix_only_rigid_modes(const Matrix& free_modes, const std::vector<ConstraintEquation>& constraints) {
  const Index k = static_cast<Index>(constraints.size());
  if (k == 0 || free_modes.cols() != k) return false;
  Matrix c(k, k);
  for (Index q = 0; q < k; ++q)
    for (Index m = 0; m < k; ++m) {
      double sum = 0.0;
      for (const auto& [dof, coefficient] : constraints[q].displacement_terms) sum += coefficient * free_modes(dof, m);
      c(q, m) = sum;
    }
  const Vector s = operators::singular_values(c);
  return s[k - 1] > 1e-8 * s[0];
}

Vector rigid_mode_consistent_solution(const operators::Factorization& lu, const Matrix& reaction_columns,
                                      const Vector& y) {
  const Index total = lu.size();
  const Index k = reaction_columns.cols();
  const Index dofs = total - k;
  // Left null vectors of the unconstrained operator: M^T [w; mu] = [0; e_q].
  Matrix left = Matrix::Zero(total, k);
  for (Index q = 0; q < k; ++q) left(dofs + q, q) = 1.0;
  lu.solve_transposed_in_place(left);
  // Replace the reaction columns G_c by W: M' = M + U V^T, U = [W - G_c; 0], V = [0; I].
  Matrix u = Matrix::Zero(total, k);
  u.topRows(dofs) = left.topRows(dofs) - reaction_columns;
  Matrix z = u;
  lu.solve_in_place(z);
  const Matrix capacitance = Matrix::Identity(k, k) + z.bottomRows(k);
  return y - z * capacitance.partialPivLu().solve(y.tail(k));
}

}  // namespace bemcontact::bem

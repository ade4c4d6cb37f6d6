#include "bemcontact/dd/monolithic.hpp"

#include "bemcontact/bem/assembly.hpp"
#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::dd {

MonolithicResult solve_monolithic(const DecompositionProblem& problem,
                                  const std::vector<geometry::BoundaryMesh>& meshes,
                                  const Connectivity& connectivity) {
  const std::size_t count = problem.subdomains.size();
  std::vector<std::vector<bem::NodeCondition>> conditions(count);
  std::vector<std::vector<bem::ConstraintEquation>> constraints(count);
  std::vector<bem::BoundarySystem> systems(count);
  std::vector<Matrix> H(count);
  std::vector<Index> offset(count + 1, 0);
  for (std::size_t s = 0; s < count; ++s) {
    const auto& body = problem.subdomains[s].body;
    conditions[s] = bem::resolve_node_conditions(meshes[s], body, problem.analysis);
    for (const auto& v : connectivity.variable_nodes[s]) {  // interface nodes: displacement unknown, set below
      auto& c = conditions[s][v.node];
      const bool on_axis = c.on_axis;
      c = bem::NodeCondition{};
      c.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
      c.on_axis = on_axis;
    }
    constraints[s] = bem::resolve_point_constraints(meshes[s], body, conditions[s]);
    const bem::ElementIntegrator integrator(problem.analysis, body.material);
    auto matrices = bem::assemble_influence_matrices(meshes[s], integrator);
    systems[s] = bem::build_boundary_system(matrices, conditions[s], constraints[s]);
    H[s] = std::move(matrices.H);  // interface nodes have the global frame: columns unrotated
    offset[s + 1] = offset[s] + systems[s].A.rows();
  }
  const Index u_offset = offset[count];
  // Rows: the subdomains' rows, then equilibrium; columns: the subdomains' unknowns, then U.
  const Index equilibrium_offset = u_offset;
  const Index size = u_offset + connectivity.unknowns;

  Matrix M = Matrix::Zero(size, size);
  Vector rhs = Vector::Zero(size);
  for (std::size_t s = 0; s < count; ++s) {
    const Index m = systems[s].A.rows();
    M.block(offset[s], offset[s], m, m) = systems[s].A;
    rhs.segment(offset[s], m) = systems[s].b;
    const Index dofs = 2 * meshes[s].node_count();
    for (std::size_t k = 0; k < connectivity.slots[s].size(); ++k) {
      const Index node = connectivity.variable_nodes[s][k].node;
      const Index u_col = u_offset + connectivity.unknown_of(connectivity.slots[s][k]);
      for (int c = 0; c < 2; ++c) {
        if (conditions[s][node].on_axis && c == 0) continue;  // u_r = 0 on the axis
        // H u = G p with u = U at the interface node: A y + H(:, node) U = b.
        for (Index row = 0; row < dofs; ++row)
          if (!conditions[s][row / 2].on_axis || row % 2 == 1) M(offset[s] + row, u_col + c) = H[s](row, 2 * node + c);
      }
    }
  }
  for (const auto& interface : connectivity.interfaces) {
    const std::size_t a = interface.subdomain_a, b = interface.subdomain_b;
    for (std::size_t j = 0; j < interface.pairs.size(); ++j) {
      const auto& pair = interface.pairs[j];
      const Index unknown = interface.offset + 2 * static_cast<Index>(j);
      for (int c = 0; c < 2; ++c) {
        const Index row = equilibrium_offset + unknown + c;
        if (c == 0 && conditions[a][pair.node_a].on_axis) {
          M(row, u_offset + unknown) = 1.0;  // U_r = 0; p_r = 0 on both sides already
          continue;
        }
        M(row, offset[a] + 2 * pair.node_a + c) = 1.0;  // p_a + p_b = 0
        M(row, offset[b] + 2 * pair.node_b + c) = 1.0;
      }
    }
  }

  const operators::DenseLU lu(std::move(M), "the multi-region system");
  const Vector y = lu.solve(rhs);
  MonolithicResult result;
  result.unknowns = size;
  result.reciprocal_condition = lu.reciprocal_condition();
  for (std::size_t s = 0; s < count; ++s) {
    auto with_values = conditions[s];
    for (std::size_t k = 0; k < connectivity.slots[s].size(); ++k) {
      const Index node = connectivity.variable_nodes[s][k].node;
      const Index u = u_offset + connectivity.unknown_of(connectivity.slots[s][k]);
      with_values[node].value = {with_values[node].on_axis ? 0.0 : y[u], y[u + 1]};
    }
    result.boundary.push_back(
        bem::recover_boundary_values(y.segment(offset[s], systems[s].A.rows()), with_values, constraints[s]));
  }
  return result;
}

}  // namespace bemcontact::dd

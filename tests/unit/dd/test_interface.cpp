// Connection table of the interfaces (section IV.2).
#include <gtest/gtest.h>

#include "bemcontact/dd/interface.hpp"
#include "bemcontact/dd/interface_operator.hpp"
#include "bemcontact/dd/plate_strips.hpp"
#include "bemcontact/operators/dense_lu.hpp"
#include "bemcontact/operators/gmres.hpp"

namespace bemcontact::dd {
namespace {

TEST(DdInterface, FacingNodesCoincideAndNormalsOppose) {
  const auto problem = plate_strips({3, 6});
  const auto meshes = mesh_subdomains(problem);
  const auto c = build_connectivity(problem, meshes);
  ASSERT_EQ(c.interfaces.size(), 2u);
  for (const auto& interface : c.interfaces) {
    // 12 elements: 11 interior nodes and 2 split end nodes shifted into the elements.
    EXPECT_EQ(interface.pairs.size(), 13u);
    EXPECT_EQ(interface.subdomain_b, interface.subdomain_a + 1);
    for (const auto& pair : interface.pairs) {
      const auto& a = meshes[interface.subdomain_a].nodes[pair.node_a];
      const auto& b = meshes[interface.subdomain_b].nodes[pair.node_b];
      EXPECT_LT((a.position - b.position).norm(), 1e-12);
      EXPECT_NEAR(a.normal.dot(b.normal), -1.0, 1e-12);
    }
  }
  EXPECT_EQ(c.unknowns, 2 * 2 * 13);
  // Strip 2 touches both interfaces: 26 variable nodes; strips 1 and 3 touch one.
  EXPECT_EQ(c.variable_nodes[0].size(), 13u);
  EXPECT_EQ(c.variable_nodes[1].size(), 26u);
  EXPECT_EQ(c.variable_nodes[2].size(), 13u);
}

TEST(DdInterface, MixedMethodSpreadsItsDisplacementNodes) {
  auto problem = plate_strips({2, 6});
  problem.options.method = InterfaceMethod::mixed;
  problem.options.displacement_nodes = 3;
  const auto c = build_connectivity(problem, mesh_subdomains(problem));
  std::vector<double> x;
  for (const auto& pair : c.interfaces[0].pairs)
    if (pair.kind == bem::ConditionKind::displacement) x.push_back(pair.position.x());
  ASSERT_EQ(x.size(), 3u);
  std::sort(x.begin(), x.end());
  // Targets at 1/6, 1/2, 5/6 of the length 2 (from x = 1 going left): x = 2/3, 0, -2/3.
  EXPECT_NEAR(x[0], -2.0 / 3.0, 1e-12);
  EXPECT_NEAR(x[1], 0.0, 1e-12);
  EXPECT_NEAR(x[2], 2.0 / 3.0, 1e-12);
  problem.options.method = InterfaceMethod::hybrid;
  // (The connectivity is kept in a variable: a range-for over a member of a temporary
  // would read it after its end.)
  const auto hybrid = build_connectivity(problem, mesh_subdomains(problem));
  for (const auto& pair : hybrid.interfaces[0].pairs) EXPECT_EQ(pair.kind, bem::ConditionKind::traction);
}

// The matrix-free operator against its own dense form: columns K e_j must make a matrix
// whose LU solution equals the GMRES one, and K must be linear (K(a x + y) = a Kx + Ky).
TEST(DdInterface, MatrixFreeOperatorIsLinearAndMatchesItsDenseForm) {
  const auto problem = plate_strips({3, 6});
  const auto meshes = mesh_subdomains(problem);
  const auto c = build_connectivity(problem, meshes);
  const InterfaceOperator K(problem, meshes, c);
  const Index n = K.rows();
  Matrix dense(n, n);
  Vector column(n);
  for (Index j = 0; j < n; ++j) {
    K.apply(Vector::Unit(n, j), column);
    dense.col(j) = column;
  }
  const Vector x = Vector::LinSpaced(n, -1.0, 2.0), y = Vector::LinSpaced(n, 3.0, 0.5);
  Vector kx(n), ky(n), kxy(n);
  K.apply(x, kx);
  K.apply(y, ky);
  K.apply(2.5 * x + y, kxy);
  EXPECT_LT((kxy - 2.5 * kx - ky).norm(), 1e-10 * kxy.norm());
  EXPECT_LT((dense * x - kx).norm(), 1e-10 * kx.norm());

  const Vector F = K.right_hand_side();
  const Vector direct = operators::DenseLU(dense).solve(F);
  operators::GmresOptions options;
  options.restart = static_cast<int>(n);
  options.tolerance = 1e-12;
  const auto iterative = operators::gmres(K, F, options);
  ASSERT_TRUE(iterative.converged());
  EXPECT_LT((iterative.x - direct).norm(), 1e-9 * direct.norm());
}

}  // namespace
}  // namespace bemcontact::dd

namespace bemcontact::dd {
namespace {

TEST(DdInterface, ExplicitInterfaceMapsGiveTheMatrixFreeOperator) {
  auto problem = plate_strips({3, 6});
  const auto meshes = mesh_subdomains(problem);
  const auto c = build_connectivity(problem, meshes);
  const InterfaceOperator free_op(problem, meshes, c);
  problem.options.explicit_operators = true;
  const InterfaceOperator explicit_op(problem, meshes, c);
  const Vector x = Vector::LinSpaced(free_op.rows(), -2.0, 1.0);
  Vector a, b;
  free_op.apply(x, a);
  explicit_op.apply(x, b);
  EXPECT_LT((a - b).norm(), 1e-11 * a.norm());
  EXPECT_LT((free_op.right_hand_side() - explicit_op.right_hand_side()).norm(),
            1e-11 * free_op.right_hand_side().norm());
}

}  // namespace
}  // namespace bemcontact::dd

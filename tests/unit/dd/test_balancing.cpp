// The balancing Neumann-Neumann preconditioner (dd/balancing.hpp).
#include <gtest/gtest.h>

#include "bemcontact/dd/balancing.hpp"
#include "bemcontact/dd/interface_operator.hpp"
#include "bemcontact/dd/plate_strips.hpp"
#include "bemcontact/dd/solver.hpp"
#include "bemcontact/io/input/decomposition_file.hpp"

namespace bemcontact::dd {
namespace {

DecompositionProblem conforming_strips(int strips, InterfacePreconditioner preconditioner) {
  PlateStripsSpec spec{strips, 6};
  spec.height = strips;  // unit strips
  auto problem = plate_strips(spec);
  problem.options.set_method(InterfaceMethod::conforming);
  problem.options.preconditioner = preconditioner;
  return problem;
}

// M^-1 K w = w for every w in the coarse space: Q K w = w and (I - K Q) K w = 0 (algebra of
// the balanced form), so the coarse modes are solved exactly in one step.
TEST(Balancing, TheCoarseSpaceIsSolvedExactly) {
  const auto problem = conforming_strips(4, InterfacePreconditioner::balancing);
  const auto meshes = mesh_subdomains(problem);
  const auto connectivity = build_connectivity(problem, meshes);
  const InterfaceOperator K(problem, meshes, connectivity);
  const BalancingPreconditioner M(K, connectivity, problem.analysis);
  ASSERT_GT(M.coarse_dimension(), 0);
  for (Index c = 0; c < M.coarse_dimension(); ++c) {
    const Vector w = M.coarse_basis().col(c);
    Vector kw, mkw;
    K.apply(w, kw);
    M.apply(kw, mkw);
    EXPECT_LT((mkw - w).norm(), 1e-8 * w.norm()) << "mode " << c;
  }
}

// Strip 1 is held (u2 = 0 and a point); strips 2-4 carry only tractions and interface data,
// so their Dirichlet-to-Neumann maps are singular on all three plane rigid modes.
TEST(Balancing, FloatingStripsAreFoundWithTheirRigidModes) {
  const auto result = solve_decomposition(conforming_strips(4, InterfacePreconditioner::balancing));
  ASSERT_TRUE(result.converged()) << result.gmres.message;
  EXPECT_EQ(result.floating_modes, (std::vector<int>{0, 3, 3, 3}));
  // 4 x 3 rigid modes on 3 interfaces (18 x 2 dofs): strip 1's modes repeat strip 2's on
  // their shared interface up to the weights, so at most 12 and at least the 9 floating ones.
  EXPECT_GE(result.coarse_dimension, 9);
  EXPECT_LE(result.coarse_dimension, 12);
}

// The preconditioner changes the path, not the answer: both converge to the tolerance on
// the same discrete problem, so their interface unknowns agree to about tolerance x cond.
TEST(Balancing, SameAnswerAsTheUnpreconditionedIteration) {
  const auto plain = solve_decomposition(conforming_strips(6, InterfacePreconditioner::none));
  const auto balanced = solve_decomposition(conforming_strips(6, InterfacePreconditioner::balancing));
  ASSERT_TRUE(plain.converged() && balanced.converged());
  EXPECT_LT((plain.gmres.x - balanced.gmres.x).norm(), 1e-6 * plain.gmres.x.norm());
  EXPECT_LT(balanced.gmres.iterations, plain.gmres.iterations);
}

// Iterations nearly flat in the number of subdomains (condition number bounded by
// C (1 + log(H/h))^2 independently of their count): 32 strips within 2x of 2 strips, where
// the unpreconditioned iteration grows more than 5x.
TEST(Balancing, IterationsStayFlatWithTheNumberOfSubdomains) {
  const auto two = solve_decomposition(conforming_strips(2, InterfacePreconditioner::balancing));
  const auto many = solve_decomposition(conforming_strips(32, InterfacePreconditioner::balancing));
  ASSERT_TRUE(two.converged() && many.converged());
  EXPECT_LE(many.gmres.iterations, 2 * two.gmres.iterations);
  const auto plain_two = solve_decomposition(conforming_strips(2, InterfacePreconditioner::none));
  const auto plain_many = solve_decomposition(conforming_strips(32, InterfacePreconditioner::none));
  EXPECT_GT(plain_many.gmres.iterations, 5 * plain_two.gmres.iterations);
}

// Axisymmetric: the only rigid mode is the axial translation. The two-layer tube's layers
// are both held radially by the pressure field, so nothing floats; the balanced answer
// equals the mixed method's.
TEST(Balancing, AxisymmetricTwoLayerTube) {
  auto file = io::read_decomposition_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/dd_two_layer_tube_axisymmetric.toml");
  auto problem = file.problem;
  const auto mixed = solve_decomposition(problem);
  problem.options.set_method(InterfaceMethod::conforming);
  const auto balanced = solve_decomposition(problem);
  ASSERT_TRUE(mixed.converged() && balanced.converged());
  EXPECT_GT(balanced.coarse_dimension, 0);
  for (std::size_t s = 0; s < mixed.subdomains.size(); ++s) {
    const auto& a = mixed.subdomains[s].boundary.displacement;
    const auto& b = balanced.subdomains[s].boundary.displacement;
    double difference = 0.0, size = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      difference = std::max(difference, (a[i] - b[i]).norm());
      size = std::max(size, a[i].norm());
    }
    EXPECT_LT(difference, 1e-6 * size) << "subdomain " << s;
  }
}

}  // namespace
}  // namespace bemcontact::dd

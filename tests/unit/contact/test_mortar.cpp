// Mortar pairing (pairing.hpp, ContactInterface::pairing = mortar): the dual-weighted
// integrals reduce to node-to-segment on matching meshes, reproduce linear fields through
// non-matching ones, and a uniform pressure passes exactly through non-matching meshes of a
// flat interface (patch test) whichever side is the finer.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/pairing.hpp"
#include "contact_fixtures.hpp"

namespace bemcontact::contact {
namespace {

// Two unit-height blocks [-1, 1] x [0, 1] (body 1) on [-1, 1] x [-1, 0] (body 2), plane
// strain, nu = 0; body 2's base clamped, body 1's top a rigid platen under a force P: the
// exact solution is the uniform stress sigma_yy = -P / 2 (with nu = 0 neither the clamp nor
// the platen restrains the blocks laterally), a linear displacement field.
ContactProblem stacked_blocks(int elements1, int elements2, double grading2, double P) {
  using namespace testing;
  ContactProblem problem = two_body_problem(0, 2);
  problem.analysis = AnalysisType::plane_strain;
  problem.bodies[0].name = "upper";
  auto& upper = problem.elastic(0);
  upper.name = "upper";
  upper.material = {1.0, 0.0};
  add(upper, line("bottom", {-1.0, 0.0}, {1.0, 0.0}, elements1), free_condition());
  add(upper, line("right", {1.0, 0.0}, {1.0, 1.0}, 6), free_condition());
  add(upper, line("top", {1.0, 1.0}, {-1.0, 1.0}, 8), displacement(0.0, 0.0, "top"));
  add(upper, line("left", {-1.0, 1.0}, {-1.0, 0.0}, 6), free_condition());
  problem.bodies[1].name = "lower";
  auto& lower = problem.elastic(1);
  lower.name = "lower";
  lower.material = {3.0, 0.0};
  add(lower, line("base", {-1.0, -1.0}, {1.0, -1.0}, 8), displacement(0.0, 0.0, "clamped"));
  add(lower, line("right", {1.0, -1.0}, {1.0, 0.0}, 6), free_condition());
  add(lower, line("top", {1.0, 0.0}, {-1.0, 0.0}, elements2, grading2), free_condition());
  add(lower, line("left", {-1.0, 0.0}, {-1.0, -1.0}, 6), free_condition());
  problem.contacts.front().law.kind = ContactKind::unilateral;
  problem.contacts.front().pair_normal = PairNormal::body2;
  problem.forces = {platen_force(0, 2, 1, -P)};
  return problem;
}

}  // namespace

TEST(ContactMortar, MatchingMeshesReduceToNodeToSegment) {
  auto problem = stacked_blocks(9, 9, 1.0, 2.0e-3);
  const auto nts = prepare_contact(problem);
  problem.contacts.front().pairing = Pairing::mortar;
  const auto mortar = prepare_contact(problem);
  const auto& a = nts.contacts.front();
  const auto& b = mortar.contacts.front();
  ASSERT_EQ(a.pairs.size(), b.pairs.size());
  EXPECT_EQ(a.mortar.size(), 0);
  const Index m = static_cast<Index>(b.zone_nodes2.size());
  ASSERT_EQ(b.mortar.rows(), m);
  ASSERT_EQ(b.mortar.cols(), static_cast<Index>(b.pairs.size()));
  // The mortar weights are node-to-segment's interpolation (here the facing node: 1).
  for (std::size_t i = 0; i < b.pairs.size(); ++i) {
    Vector nodal = Vector::Zero(m);
    for (int k = 0; k < a.pairs[i].count2; ++k) nodal[a.pairs[i].zone2[k]] += a.pairs[i].shape2[k];
    EXPECT_LT((b.mortar.col(static_cast<Index>(i)) - nodal).cwiseAbs().maxCoeff(), 1e-13) << "pair " << i;
    EXPECT_NEAR(b.pairs[i].gap, a.pairs[i].gap, 1e-15);
  }
  EXPECT_LT((b.transfer - a.transfer).cwiseAbs().maxCoeff(), 1e-13);
  // And the solutions agree to round-off.
  problem.contacts.front().pairing = Pairing::node_to_segment;
  const auto ra = solve_contact(problem);
  problem.contacts.front().pairing = Pairing::mortar;
  const auto rb = solve_contact(problem);
  ASSERT_EQ(ra.pairs.size(), rb.pairs.size());
  for (std::size_t i = 0; i < ra.pairs.size(); ++i)
    EXPECT_NEAR(rb.pairs[i].p_n, ra.pairs[i].p_n, 1e-10 * std::abs(ra.pairs[i].p_n) + 1e-16);
}

TEST(ContactMortar, WeightsReproduceLinearFieldsThroughNonMatchingMeshes) {
  for (const auto& [n1, n2, grading] : {std::tuple{7, 4, 3.0}, std::tuple{4, 11, 2.0}, std::tuple{30, 19, 1.0}}) {
    auto problem = stacked_blocks(n1, n2, grading, 2.0e-3);
    problem.contacts.front().pairing = Pairing::mortar;
    const auto prepared = prepare_contact(problem);
    const auto& c = prepared.contacts.front();
    const auto& nodes2 = prepared.regions[1].mesh.nodes;
    for (std::size_t i = 0; i < c.pairs.size(); ++i) {
      double sum = 0.0, x = 0.0;
      for (Index a = 0; a < c.mortar.rows(); ++a) {
        sum += c.mortar(a, static_cast<Index>(i));
        x += c.mortar(a, static_cast<Index>(i)) * nodes2[c.zone_nodes2[a]].position.x();
      }
      EXPECT_NEAR(sum, 1.0, 1e-13);
      EXPECT_NEAR(x, c.pairs[i].position1.x(), 1e-13) << n1 << " against " << n2 << ", pair " << i;
      EXPECT_NEAR(c.pairs[i].gap, 0.0, 1e-15);
    }
    // The transfer passes a constant traction as a constant.
    const Vector ones = Vector::Ones(static_cast<Index>(c.pairs.size()));
    EXPECT_LT((c.transfer * ones - Vector::Ones(c.transfer.rows())).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(ContactMortar, PatchTestUniformPressureThroughNonMatchingMeshes) {
  const double P = 2.0e-3;
  for (const auto& [n1, n2, grading] : {std::tuple{7, 4, 3.0}, std::tuple{4, 11, 2.0}, std::tuple{13, 5, 1.0}}) {
    auto problem = stacked_blocks(n1, n2, grading, P);
    problem.contacts.front().pairing = Pairing::mortar;
    const auto result = solve_contact(problem);
    double worst = 0.0;
    for (const auto& pair : result.pairs) worst = std::max(worst, std::abs(-pair.p_n - 0.5 * P) / (0.5 * P));
    EXPECT_LT(worst, 1e-6) << n1 << " against " << n2 << " elements";
    EXPECT_EQ(result.summary.pairs_in_contact, static_cast<int>(result.pairs.size()));
    std::printf("mortar patch test %d against %d: max pressure deviation %.2e\n", n1, n2, worst);
  }
}

}  // namespace bemcontact::contact

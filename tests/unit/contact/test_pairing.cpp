// Node pairing and gaps (V.2-V.3): facing nodes, common normals, gaps from the true
// geometry of the actual nodes.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/contact/pairing.hpp"
#include "contact_fixtures.hpp"

namespace bemcontact::contact {

TEST(ContactPairing, CylinderOnBlockGapsFollowTheCircle) {
  const double R = 1.0, theta = 0.25;
  const auto problem = testing::cylinder_on_block(R, theta, 20, 1.0, {1.0, 0.3}, {1.0, 0.3});
  const auto prepared = prepare_contact(problem);
  // 20 one-element pieces per zone, 21 nodes (no split inside the zone), all paired.
  EXPECT_EQ(prepared.contact_pieces[0].size(), 20u);
  EXPECT_EQ(prepared.contact_pieces[1].size(), 20u);
  ASSERT_EQ(prepared.pairs.size(), 21u);
  double total_weight = 0.0;
  for (const auto& pair : prepared.pairs) {
    // Along the common normal n (the bisector of the two outward normals, (V.2)), the
    // distance from the circle point at angle phi to the flat is exactly R (1 - cos phi) /
    // cos(phi / 2) (elementary geometry of the bisector), for nodes on the arc.
    const Vec2 x = pair.position1;
    const double phi = std::asin(x.x() / R);
    const double expected = R * (1.0 - std::cos(phi)) / std::cos(0.5 * phi);
    if (std::abs((x - Vec2(0.0, R)).norm() - R) < 1e-12)  // node on the arc (not a shifted end node)
      EXPECT_NEAR(pair.gap, expected, 1e-12);
    EXPECT_NEAR(pair.normal.norm(), 1.0, 1e-14);
    EXPECT_LT(pair.normal.y(), -0.99);  // from the cylinder down into the block
    // The facing node lies on the common normal (within the split-corner shifts at the ends).
    const Vec2 d = pair.position2 - pair.position1;
    EXPECT_LT(std::abs(d.x() * pair.normal.y() - d.y() * pair.normal.x()), 2e-3);
    total_weight += pair.weight;
  }
  // Weights integrate 1 over the cylinder's zone: the arc's chord lengths sum.
  EXPECT_NEAR(total_weight, 2.0 * R * theta, 2.0 * R * theta * 1e-3);
}

TEST(ContactPairing, Body2NormalPairsVertically) {
  auto problem = testing::cylinder_on_block(1.0, 0.25, 10, 1.0, {1.0, 0.3}, {1.0, 0.3});
  problem.pair_normal = PairNormal::body2;
  problem.bodies[1].pieces[2].end.x() = problem.bodies[1].pieces[3].start.x() = std::sin(0.25);
  problem.bodies[1].pieces[3].end.x() = problem.bodies[1].pieces[4].start.x() = -std::sin(0.25);
  const auto prepared = prepare_contact(problem);
  for (const auto& pair : prepared.pairs) {
    EXPECT_NEAR(pair.normal.y(), -1.0, 1e-14);
    EXPECT_NEAR(pair.gap, pair.position1.y() - pair.position2.y(), 1e-14);  // height above the block
  }
}

TEST(ContactPairing, ZonesThatDoNotFaceAreRejected) {
  auto problem = testing::cylinder_on_block(1.0, 0.25, 10, 1.0, {1.0, 0.3}, {1.0, 0.3});
  problem.bodies[1].pieces[2].end.x() = problem.bodies[1].pieces[3].start.x() = 0.6;
  EXPECT_THROW(prepare_contact(problem), GeometryError);
}

}  // namespace bemcontact::contact

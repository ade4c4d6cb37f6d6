// Node pairing and gaps (V.2-V.3): body 1's nodes projected on body 2's independently
// meshed zone along the pair normal, gaps to the true surface of body 2, interpolation
// weights on body 2's element.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/contact/pairing.hpp"
#include "contact_fixtures.hpp"

namespace bemcontact::contact {

TEST(ContactPairing, CylinderOnBlockGapsFollowTheCircle) {
  const double R = 1.0, theta = 0.25;
  const auto problem = testing::cylinder_on_block(R, theta, 20, 1.0, {1.0, 0.3}, {1.0, 0.3});
  const auto prepared_all = prepare_contact(problem);
  const auto& prepared = prepared_all.contacts.front();
  // 20 elements on the cylinder's zone, 21 nodes (split ends), all facing the block's zone.
  ASSERT_EQ(prepared.pairs.size(), 21u);
  EXPECT_EQ(prepared.unpaired_nodes1, 0);
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
    // The facing point lies on the common normal, and body 2's interpolation there sums to 1.
    const Vec2 d = pair.position2 - pair.position1;
    EXPECT_LT(std::abs(d.x() * pair.normal.y() - d.y() * pair.normal.x()), 1e-10);
    double sum = 0.0;
    for (int a = 0; a < pair.count2; ++a) sum += pair.shape2[a];
    EXPECT_NEAR(sum, 1.0, 1e-14);
    total_weight += pair.weight;
  }
  // Weights integrate 1 over the cylinder's zone: the arc's chord lengths sum.
  EXPECT_NEAR(total_weight, 2.0 * R * theta, 2.0 * R * theta * 1e-3);
}

TEST(ContactPairing, Body2NormalPairsVertically) {
  auto problem = testing::cylinder_on_block(1.0, 0.25, 10, 1.0, {1.0, 0.3}, {1.0, 0.3});
  problem.contacts.front().pair_normal = PairNormal::body2;
  problem.elastic(1).pieces[2].end.x() = problem.elastic(1).pieces[3].start.x() = std::sin(0.25);
  problem.elastic(1).pieces[3].end.x() = problem.elastic(1).pieces[4].start.x() = -std::sin(0.25);
  const auto prepared_all = prepare_contact(problem);
  const auto& prepared = prepared_all.contacts.front();
  for (const auto& pair : prepared.pairs) {
    EXPECT_NEAR(pair.normal.y(), -1.0, 1e-14);
    EXPECT_NEAR(pair.gap, pair.position1.y() - pair.position2.y(), 1e-14);  // height above the block
  }
}

TEST(ContactPairing, ZonesThatDoNotFaceAreRejected) {
  // The block's zone moved entirely to the right of the cylinder's: no node faces it.
  auto problem = testing::cylinder_on_block(1.0, 0.25, 10, 1.0, {1.0, 0.3}, {1.0, 0.3});
  problem.elastic(1).pieces[2].end.x() = problem.elastic(1).pieces[3].start.x() = 5.0;
  problem.elastic(1).pieces[3].end.x() = problem.elastic(1).pieces[4].start.x() = 3.0;
  EXPECT_THROW(prepare_contact(problem), GeometryError);
}

TEST(ContactPairing, NonMatchingZonesAndALargerZoneOnBody2) {
  // 13 elements on the cylinder, 29 on a block zone twice as wide: every cylinder node faces
  // the block's zone inside an element, with its own interpolation; the gaps are the
  // circle's heights above the flat (body 2's normal).
  auto problem = testing::cylinder_on_block(1.0, 0.25, 13, 1.0, {1.0, 0.3}, {1.0, 0.3});
  problem.contacts.front().pair_normal = PairNormal::body2;
  problem.elastic(1).pieces[3].elements = 29;
  problem.elastic(1).pieces[2].end.x() = problem.elastic(1).pieces[3].start.x() = 0.5;
  problem.elastic(1).pieces[3].end.x() = problem.elastic(1).pieces[4].start.x() = -0.5;
  const auto prepared_all = prepare_contact(problem);
  const auto& prepared = prepared_all.contacts.front();
  ASSERT_EQ(prepared.pairs.size(), 14u);
  EXPECT_EQ(prepared.zone_nodes2.size(), 30u);
  double weight1 = 0.0, weight2 = 0.0;
  for (const auto& pair : prepared.pairs) {
    EXPECT_NEAR(pair.gap, pair.position1.y(), 1e-14);
    EXPECT_NEAR(pair.position2.x(), pair.position1.x(), 1e-14);
    // Linear interpolation on the block's element reproduces x.
    double x = 0.0;
    for (int a = 0; a < pair.count2; ++a)
      x += pair.shape2[a] * prepared_all.regions[1].mesh.nodes[prepared.zone_nodes2[pair.zone2[a]]].position.x();
    EXPECT_NEAR(x, pair.position2.x(), 1e-12);
    weight1 += pair.weight;
  }
  for (double w : prepared.zone_weights2) weight2 += w;
  EXPECT_NEAR(weight2, 1.0, 1e-12);  // the block's zone length
  EXPECT_NEAR(weight1, 0.5, 1e-3);   // the cylinder's zone chord lengths
}

}  // namespace bemcontact::contact

// The stick zone's ends located between pairs (contact_summary.hpp), on margins sampled from
// closed forms: each law recovers its edge where the samples follow it exactly, and stays
// between the outermost stick pair and the slipping one otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bemcontact/contact/contact_summary.hpp"

namespace bemcontact::contact {
namespace {

// Margins m(x) at the stick pairs x = edge - (k + offset) h, k = 0..count-1 (outermost first).
struct Samples {
  std::vector<double> x, m;
};
template <class Margin>
Samples sample(Margin margin, double edge, double h, double offset, int count) {
  Samples s;
  for (int k = 0; k < count; ++k) {
    const double x = edge - (k + offset) * h;
    s.x.push_back(x);
    s.m.push_back(margin(x));
  }
  return s;
}

}  // namespace

// Cattaneo's margin 1 - q/(mu p) = (c/a) sqrt(1 - x^2/c^2) / sqrt(1 - x^2/a^2) for a = 1
// (at Q = 0.9 mu P, 60 elements' spacing): m^2 is a parabola but for the denominator, and
// the parabola through 4 pairs lands within 3 % of the pair spacing of c (measured 1.2 to
// 2.6 %; a line through the 2 outermost overshoots by 10 %).
TEST(StickEdge, RecedingEdgeFollowsCattaneo) {
  const double c = 0.3162, h = 0.0405;
  const auto cattaneo = [c](double x) { return c * std::sqrt(1.0 - x * x / (c * c)) / std::sqrt(1.0 - x * x); };
  for (const double offset : {0.1, 0.5, 0.9}) {
    const auto s = sample(cattaneo, c, h, offset, 4);
    const double edge = stick_edge(s.x, s.m, s.x.front() + h, StickEdgeLaw::receding);
    EXPECT_NEAR(edge, c, 0.03 * h) << offset;
  }
}

// Spence's advancing edge, m = A (c - x)^(3/2): the 2/3 power through two pairs is exact.
TEST(StickEdge, AdvancingEdgeFollowsThreeHalvesLaw) {
  const double c = 0.5, h = 0.01;
  const auto spence = [c](double x) { return 0.7 * std::pow(c - x, 1.5); };
  for (const double offset : {0.2, 0.7}) {
    const auto s = sample(spence, c, h, offset, 4);
    EXPECT_NEAR(stick_edge(s.x, s.m, s.x.front() + h, StickEdgeLaw::advancing), c, 1e-12) << offset;
  }
}

// The low end of a zone (the slip zone at smaller x) by symmetry, and the clamping: a fit
// whose zero lies past the slipping pair stops at it; too few pairs: midway.
TEST(StickEdge, LowEndsClampingAndFallback) {
  const double c = 0.3162, h = 0.0405;
  const auto cattaneo = [c](double x) { return c * std::sqrt(1.0 - x * x / (c * c)) / std::sqrt(1.0 - x * x); };
  auto s = sample(cattaneo, c, h, 0.4, 4);
  for (auto& x : s.x) x = -x;
  EXPECT_NEAR(stick_edge(s.x, s.m, s.x.front() - h, StickEdgeLaw::receding), -c, 0.03 * h);
  const auto flat = sample([](double) { return 0.5; }, c, h, 0.4, 4);  // no zero: midway
  EXPECT_NEAR(stick_edge(flat.x, flat.m, flat.x.front() + h, StickEdgeLaw::receding), flat.x.front() + 0.5 * h, 1e-15);
  const auto far = sample(cattaneo, c, h, 0.4, 4);  // the slipping pair before the true edge
  EXPECT_DOUBLE_EQ(stick_edge(far.x, far.m, far.x.front() + 0.1 * h, StickEdgeLaw::receding), far.x.front() + 0.1 * h);
  EXPECT_DOUBLE_EQ(stick_edge({0.2}, {0.3}, 0.3, StickEdgeLaw::receding), 0.25);
}

}  // namespace bemcontact::contact

namespace bemcontact::contact {
namespace {

// Contact fraction, spots and mean gap on a hand-made set of pairs (listed out of order: the
// spots follow the coordinate, not the list).
TEST(ContactSummary, FractionSpotsAndMeanGap) {
  // coordinate, weight, closed, gap, jump_n
  struct Row {
    double x, weight;
    bool closed;
    double gap, jump;
  };
  const std::vector<Row> rows = {{3.0, 1.0, false, 0.5, 0.1}, {0.0, 0.5, false, 1.0, 0.0}, {1.0, 1.0, true, 0.2, 0.2},
                                 {2.0, 1.0, true, 0.3, 0.3},  {4.0, 1.0, true, 0.0, 0.0},  {5.0, 1.0, false, 0.2, 0.0},
                                 {7.0, 0.5, true, 0.1, 0.1},  {6.0, 1.0, true, 0.4, 0.4}};
  std::vector<ContactPair> geometry(rows.size());
  std::vector<PairResult> pairs(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    geometry[i].weight = rows[i].weight;
    pairs[i].coordinate = rows[i].x;
    pairs[i].gap = rows[i].gap;
    pairs[i].jump_n = rows[i].jump;
    pairs[i].status = rows[i].closed ? PairStatus::slip : PairStatus::open;
    pairs[i].p_n = rows[i].closed ? -1.0 : 0.0;
  }
  const ContactSummary s = summarise_pairs(geometry, pairs, false, nullptr);
  // In contact by coordinate: 0 open, 1 2 closed, 3 open, 4 closed, 5 open, 6 7 closed.
  EXPECT_EQ(s.contact_spots, 3);
  EXPECT_EQ(s.pairs_in_contact, 5);
  // Weights: zone 7, closed 1 + 1 + 1 + 1 + 0.5 = 4.5.
  EXPECT_DOUBLE_EQ(s.contact_fraction, 4.5 / 7.0);
  // Open pairs' current gaps: 0.5 (0.5 - 0.1 = 0.4, weight 1), x = 0 (1.0, weight 0.5), x = 5 (0.2).
  EXPECT_DOUBLE_EQ(s.mean_gap, (0.4 + 0.5 + 0.2) / 7.0);
  // No pair in contact: no spot, fraction 0, the mean of the gaps.
  for (auto& pair : pairs) pair.status = PairStatus::open, pair.p_n = 0.0;
  const ContactSummary open = summarise_pairs(geometry, pairs, false, nullptr);
  EXPECT_EQ(open.contact_spots, 0);
  EXPECT_EQ(open.contact_fraction, 0.0);
  // One spot over the whole zone.
  for (auto& pair : pairs) pair.status = PairStatus::stick, pair.p_n = -1.0;
  const ContactSummary closed = summarise_pairs(geometry, pairs, false, nullptr);
  EXPECT_EQ(closed.contact_spots, 1);
  EXPECT_DOUBLE_EQ(closed.contact_fraction, 1.0);
  EXPECT_EQ(closed.mean_gap, 0.0);
}

}  // namespace
}  // namespace bemcontact::contact

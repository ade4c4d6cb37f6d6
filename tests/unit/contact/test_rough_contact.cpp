// examples/contact_rough_profile.toml runs: a rough rigid profile on a block touches in
// several spots whose number and share of the zone grow with the force, and the outputs
// carry them.
#include <gtest/gtest.h>

#include <string>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/output/contact_writer.hpp"

namespace bemcontact::contact {
namespace {

TEST(RoughContact, ExampleTouchesInGrowingSpots) {
  const auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_rough_profile.toml");
  const auto result = solve_contact(file.problem);
  ASSERT_EQ(result.steps.size(), 4u);
  double fraction = 0.0, gap = 1.0;
  for (const auto& step : result.steps) {
    EXPECT_GT(step.contact_fraction, fraction);
    EXPECT_LT(step.mean_gap, gap);
    EXPECT_GE(step.contact_spots, 3);
    fraction = step.contact_fraction, gap = step.mean_gap;
  }
  EXPECT_LT(fraction, 0.6);  // still partial contact
  // The fraction is that of the pairs' weights: within one pair spacing of the pair count.
  const auto& last = result.steps.back();
  EXPECT_NEAR(last.contact_fraction, static_cast<double>(last.pairs_in_contact) / result.pairs.size(),
              2.0 / result.pairs.size() * last.contact_spots);
  EXPECT_NEAR(last.normal_force, file.parameters.at("P"), 1e-9);
  const std::string steps = io::contact_steps_csv(result);
  EXPECT_NE(steps.find("pairs_in_contact,contact_fraction,contact_spots,mean_gap,"), std::string::npos);
}

}  // namespace
}  // namespace bemcontact::contact

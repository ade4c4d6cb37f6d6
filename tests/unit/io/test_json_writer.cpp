// JSON helpers of the summary.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/io/json_writer.hpp"

namespace bemcontact::io {
namespace {

TEST(IoJsonWriter, TimingsKeepTheOrderRun) {
  bem::PhaseTimings timings;
  timings.add("mesh", 0.5);
  timings.add("assembly", 0.25);
  const nlohmann::json json = timings_json(timings);
  ASSERT_EQ(json["phases"].size(), 2u);
  EXPECT_EQ(json["phases"][0]["name"], "mesh");
  EXPECT_EQ(json["phases"][1]["seconds"], 0.25);
  EXPECT_EQ(json["total"], 0.75);
}

TEST(IoJsonWriter, NonFiniteNumbersBecomeNull) {
  bem::SolveReport report;
  report.unknowns = 12;
  report.reciprocal_condition = std::nan("");
  report.relative_residual = 1e-15;
  const std::string text = write_json_string(solve_report_json(report));
  const nlohmann::json back = nlohmann::json::parse(text);
  EXPECT_EQ(back["unknowns"], 12);
  EXPECT_TRUE(back["reciprocal_condition"].is_null());
  EXPECT_EQ(back["relative_residual"], 1e-15);  // full precision survives the round trip
}

}  // namespace
}  // namespace bemcontact::io

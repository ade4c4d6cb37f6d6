// JSON helpers of the summary.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/core/error.hpp"

#include <cmath>

#include "bemcontact/io/output/json_writer.hpp"

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

TEST(IoJsonWriter, NonFiniteNumbersAreASolverErrorNamingTheKey) {
  bem::SolveReport report;
  report.unknowns = 12;
  report.reciprocal_condition = 0.5;
  report.relative_residual = 1e-15;
  const nlohmann::json back = nlohmann::json::parse(write_json_string(solve_report_json(report)));
  EXPECT_EQ(back["unknowns"], 12);
  EXPECT_EQ(back["relative_residual"], 1e-15);  // full precision survives the round trip
  for (const double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    report.relative_residual = bad;
    nlohmann::json nested = {{"solve", solve_report_json(report)}, {"list", {1.0, 2.0}}};
    try {
      write_json_string(nested);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const SolverError& e) {
      EXPECT_NE(std::string(e.what()).find("'solve.relative_residual'"), std::string::npos) << e.what();
    }
  }
  // A compressed operator has no condition estimate: NaN there is written as null.
  report.relative_residual = 1e-15;
  report.reciprocal_condition = std::nan("");
  EXPECT_TRUE(nlohmann::json::parse(write_json_string(solve_report_json(report)))["reciprocal_condition"].is_null());
  nlohmann::json list = {{"a", {1.0, std::nan("")}}};
  EXPECT_THROW(write_json_string(list), SolverError);
}

}  // namespace
}  // namespace bemcontact::io

// An elastoplastic body run from its problem file (examples/plastic_tube.toml, cells of 0.16,
// 8 steps): the files, the summary and the steps' table (the unloaded tube keeps an
// expansion and carries no net force on its cut), and the refusals of what the route does
// not serve. `validate plastic-cylinder` checks the values against the 1D reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "bemcontact/core/error.hpp"
#include "bemcontact/driver/run.hpp"
#include "support/example_text.hpp"

namespace bemcontact::driver {
namespace {

using test_support::example_text;
using test_support::replaced;

std::string coarse_tube() {
  return replaced(replaced(example_text("plastic_tube.toml"), "size = 0.08", "size = 0.16"), "increments = 20",
                  "increments = 8");
}

const std::string* file(const RunOutput& output, const std::string& name) {
  for (const auto& f : output.files.files())
    if (f.name == name) return &f.content;
  return nullptr;
}

const io::CsvTable::Column& column(const io::CsvTable& table, const std::string& name) {
  for (const auto& c : table.columns())
    if (c.name == name) return c;
  ADD_FAILURE() << "no column " << name;
  return table.columns().front();
}

std::string input_error(const std::string& text) {
  try {
    run_problem(text, "tube.toml", {});
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no input error";
  return "";
}

TEST(ElastoplasticRun, WritesTheCellsStepsAndResidualState) {
  RunOptions options;
  options.keep_tables = true;
  const auto output = run_problem(coarse_tube(), "tube.toml", options);
  for (const char* name : {"tube_boundary.csv", "tube_cells.csv", "tube_steps.csv", "tube_cells.vtk", "summary.json"})
    EXPECT_NE(file(output, name), nullptr) << name;
  const auto summary = nlohmann::json::parse(*file(output, "summary.json"));
  EXPECT_EQ(summary["kind"], "elastoplastic");
  const auto& plastic = summary["results"]["elastoplastic"];
  EXPECT_EQ(plastic["steps"], 8);
  const int yielded = plastic["plastic_zone"]["yielded_cells"];
  EXPECT_GT(yielded, 0);
  EXPECT_LT(yielded, plastic["cells"].get<int>());
  // The plastic zone hugs the bore: no yielded cell beyond r = 1.6 (the reference's c = 1.33).
  const auto& box = plastic["plastic_zone"]["box"];
  EXPECT_LT(box[1][0].get<double>(), 1.6);
  EXPECT_LT(box[1][1].get<double>(), 1.6);

  // The steps: the history's 8, up to 1.5 p_y and back to 0; the bore's permanent
  // expansion after unloading (validate plastic-cylinder checks its value).
  const auto& steps = output.tables.at("tube_steps.csv");
  const auto& amplitude = column(steps, "amplitude").numbers;
  ASSERT_EQ(amplitude.size(), 8u);
  EXPECT_DOUBLE_EQ(*std::max_element(amplitude.begin(), amplitude.end()), 1.5);
  EXPECT_DOUBLE_EQ(amplitude.back(), 0.0);
  const auto& yielded_cells = column(steps, "yielded_cells").numbers;
  EXPECT_EQ(yielded_cells.front(), 0.0);  // 0.375 p_y: elastic
  EXPECT_EQ(yielded_cells.back(), yielded);
  const auto& inner_u1 = column(steps, "inner_u1").numbers;
  EXPECT_GT(inner_u1.back(), 0.0);
  const auto& reaction = column(steps, "AB_f2").numbers;
  EXPECT_LT(std::abs(reaction.back()), 1e-3 * std::abs(*std::min_element(reaction.begin(), reaction.end())));
}

TEST(ElastoplasticRun, RefusesWhatItDoesNotServe) {
  const std::string tube = coarse_tube();
  const auto expect = [](const std::string& message, const std::string& key, const std::string& what) {
    EXPECT_NE(message.find("tube.toml:"), std::string::npos) << message;
    EXPECT_NE(message.find(key), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  expect(input_error(replaced(tube, "yield_stress = \"Y\"", "yield_stress = -1.0")), "yield_stress", "> 0");
  expect(input_error(replaced(tube, "yield_stress = \"Y\"", "yield_stress = \"Y\"\nhardening = -5.0")), "hardening",
         ">= 0");
  expect(input_error(replaced(tube, "[body.cells]\nsize = 0.16", "")), "yield_stress",
         "[cells]");
  expect(input_error(replaced(tube, "yield_stress = \"Y\"", "kinematic_hardening = 10.0")), "kinematic_hardening",
         "without yield_stress");
  expect(input_error(replaced(tube, "size = 0.16", "size = 0.16\nrefine_size = 0.01")), "refine_size",
         "without refine");
  expect(input_error(replaced(tube, "size = 0.16", "size = 0.16\nrefine = [[1, 0]]\nrefine_size = 0.5")),
         "refine_size", "at most size");
  expect(input_error(replaced(tube, "size = 0.16", "size = 0.16\nbox = [[5, 5], [6, 6]]")), "cells",
         "does not meet the region");
  expect(input_error(replaced(replaced(tube, "analysis = \"plane_strain\"", "analysis = \"axisymmetric\""),
                              "u1 = 0.0\nt2 = 0.0", "")), "yield_stress",
         "in axisymmetry");
  expect(input_error(replaced(tube, "elements = 20\nu2 = 0.0\nt1 = 0.0", "symmetry = true")), "yield_stress", "symmetry line");
  expect(input_error(replaced(tube, "increments = 8", "increments = 8\noperator = \"compressed\"")), "yield_stress",
         "compressed");
  expect(input_error(replaced(tube, "[history]", "[body.interior]\npoints = [[1.5, 0.5]]\n[history]")), "yield_stress",
         "[interior]");
  // A linear elastic region with cells: the cells would do nothing.
  expect(input_error(replaced(tube, "yield_stress = \"Y\"", "")), "cells", "linear elastic");
}

}  // namespace
}  // namespace bemcontact::driver

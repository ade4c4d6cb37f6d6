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
#include "bemcontact/io/text_format.hpp"
#include "bemcontact/operators/hmatrix.hpp"
#include "bemcontact/plasticity/j2_material.hpp"
#include "support/example_text.hpp"
#include "support/pressed_point.hpp"

namespace bemcontact::driver {
namespace {

using test_support::example_text;
using test_support::pressed_point_stress;
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

// A block pressed between smooth platens (free on one side, cells over all of it): the state is
// uniform, so piecewise-constant plastic strain is exact. Plane strain, perfectly plastic,
// against one material point under the same steps (sigma_yy tends to -2Y/sqrt3 and sigma_zz
// to sigma_yy / 2 as the flow goes on); plane stress with linear isotropic hardening H:
// uniaxial, sigma = -(Y + E H / (E + H) (eps - Y/E)) [SimoHughes1998, ch. 1].
TEST(ElastoplasticRun, PressedBlockMeetsTheClosedForms) {
  const std::string block = test_support::pressed_block_text();
  RunOptions options;
  options.keep_tables = true;
  const double Y = 250.0, E = 200000.0, strain = 0.01;
  {
    const auto output = run_problem(replaced(replaced(block, "ANALYSIS", "plane_strain"), "HARDENING", "0.0"),
                                    "block.toml", options);
    const auto& cells = output.tables.at("block_cells.csv");
    const auto point = pressed_point_stress({E, 0.3}, {Y, 0.0, 0.0}, -strain, 10);
    EXPECT_NEAR(point[1], -2.0 * Y / std::sqrt(3.0), 1e-3 * Y);  // nearly levelled at 8 Y/E
    for (std::size_t k = 0; k < 16; ++k) {
      EXPECT_NEAR(column(cells, "s22").numbers[k], point[1], 1e-7 * Y);
      EXPECT_NEAR(column(cells, "s33").numbers[k], point[2], 1e-7 * Y);
      EXPECT_NEAR(column(cells, "s11").numbers[k], 0.0, 1e-7 * Y);
    }
    // The platen's force per unit width: the same stress (the boundary's quadrature).
    EXPECT_NEAR(column(output.tables.at("block_steps.csv"), "top_f2").numbers.back(), point[1], 1e-6 * Y);
    // Crossed cells (four triangles per square) hold the same uniform state.
    const auto crossed = run_problem(replaced(replaced(replaced(block, "ANALYSIS", "plane_strain"), "HARDENING", "0.0"),
                                              "size = 0.25", "size = 0.25\nshape = \"crossed\""),
                                     "block.toml", options);
    const auto& triangles = crossed.tables.at("block_cells.csv");
    ASSERT_EQ(column(triangles, "s22").numbers.size(), 64u);
    for (const double s22 : column(triangles, "s22").numbers) EXPECT_NEAR(s22, point[1], 1e-7 * Y);
    for (const double s11 : column(triangles, "s11").numbers) EXPECT_NEAR(s11, 0.0, 1e-7 * Y);
    // So does the compressed cell operator (its far blocks by another rule: none is exact).
    if (operators::hmatrix_available()) {
      const auto compressed =
          run_problem(replaced(replaced(replaced(block, "ANALYSIS", "plane_strain"), "HARDENING", "0.0"), "size = 0.25",
                               "size = 0.25\nshape = \"crossed\"\noperator = \"compressed\""),
                      "block.toml", options);
      for (const double s22 : column(compressed.tables.at("block_cells.csv"), "s22").numbers)
        EXPECT_NEAR(s22, point[1], 1e-7 * Y);
    }
  }
  {
    const double H = E / 10.0;
    const auto output = run_problem(replaced(replaced(block, "ANALYSIS", "plane_stress"), "HARDENING", "20000.0"),
                                    "block.toml", options);
    const auto& cells = output.tables.at("block_cells.csv");
    const double expected = -(Y + E * H / (E + H) * (strain - Y / E));
    for (std::size_t k = 0; k < 16; ++k) EXPECT_NEAR(column(cells, "s22").numbers[k], expected, 1e-6 * Y);
  }
}

// A symmetry line with cells: a block clamped at its base under a strip of pressure (1.9
// times the first-yield pressure) drawn as its half with x = 0 a symmetry line (the cells'
// and elements' images across it) is the block drawn whole, meshed and celled as its mirror
// (constant elements: no node moves off the line; cells of 0.1 on the same grid lines, their
// mean points mirror-symmetric): the two discrete problems are the same, so the cells'
// plastic strains and stresses agree to round-off.
TEST(ElastoplasticRun, SymmetryLineIsTheMirroredHalf) {
  const std::string head = R"(analysis = "plane_strain"
interpolation = "constant"
[material]
E = 200000.0
nu = 0.3
yield_stress = 250.0
[cells]
size = 0.1
[[boundary]]
name = "base"
from = [X0, 0.0]
to = [1.0, 0.0]
elements = NBASE
u1 = 0.0
u2 = 0.0
[[boundary]]
name = "right"
from = [1.0, 0.0]
to = [1.0, 1.0]
elements = 10
[[boundary]]
name = "free_right"
from = [1.0, 1.0]
to = [0.3, 1.0]
elements = 7
[[boundary]]
name = "strip"
from = [0.3, 1.0]
to = [X1, 1.0]
elements = NSTRIP
pressure = 500.0
)";
  const std::string half = replaced(replaced(replaced(replaced(head, "X0", "0.0"), "NBASE", "10"), "X1", "0.0"),
                                    "NSTRIP", "3") +
                           R"([[boundary]]
name = "axis"
from = [0.0, 1.0]
to = [0.0, 0.0]
symmetry = true
)";
  const std::string whole = replaced(replaced(replaced(replaced(head, "X0", "-1.0"), "NBASE", "20"), "X1", "-0.3"),
                                     "NSTRIP", "6") +
                            R"([[boundary]]
name = "free_left"
from = [-0.3, 1.0]
to = [-1.0, 1.0]
elements = 7
[[boundary]]
name = "left"
from = [-1.0, 1.0]
to = [-1.0, 0.0]
elements = 10
)";
  RunOptions options;
  options.keep_tables = true;
  const auto a = run_problem(half, "half.toml", options);
  const auto b = run_problem(whole, "whole.toml", options);
  const auto& cells_a = a.tables.at("cells.csv");
  const auto& cells_b = b.tables.at("cells.csv");
  const auto& x_b = column(cells_b, "x").numbers;
  const auto& y_b = column(cells_b, "y").numbers;
  ASSERT_EQ(x_b.size(), 2 * column(cells_a, "x").numbers.size());
  int yielded = 0;
  for (std::size_t i = 0; i < column(cells_a, "x").numbers.size(); ++i) {
    const Vec2 at(column(cells_a, "x").numbers[i], column(cells_a, "y").numbers[i]);
    for (const double side : {1.0, -1.0}) {  // the cell and its mirror in the whole block
      std::size_t j = 0;
      while (j < x_b.size() && (Vec2(side * x_b[j], y_b[j]) - at).norm() > 1e-12) ++j;
      ASSERT_LT(j, x_b.size()) << "no cell of the whole block at " << at.transpose();
      for (const char* name : {"equivalent_plastic_strain", "s11", "s22", "s12", "s33"}) {
        const bool kappa = std::string(name) == "equivalent_plastic_strain";
        const double sign = std::string(name) == "s12" ? side : 1.0;
        EXPECT_NEAR(column(cells_a, name).numbers[i], sign * column(cells_b, name).numbers[j],
                    1e-8 * (kappa ? 250.0 / 200000.0 : 250.0))
            << name << " " << at.transpose();
      }
    }
    yielded += column(cells_a, "equivalent_plastic_strain").numbers[i] > 0.0;
  }
  EXPECT_GT(yielded, 5);
}

// The plastic zone reaching the side of the cells' box inside the body is a warning naming
// [cells] (the answer is too stiff there); a box side on the body's boundary is not.
TEST(ElastoplasticRun, WarnsWhenThePlasticZoneReachesTheBox) {
  const auto warnings = [](const std::string& text) {
    const auto output = run_problem(text, "tube.toml", {});
    std::string all;
    for (const auto& w : output.warnings) all += w + "\n";
    return all;
  };
  const std::string tube = coarse_tube();
  // The zone (to r = 1.33 along the bore) crosses x = 1.2 near y = 0.5.
  const std::string narrow = warnings(replaced(tube, "size = 0.16", "size = 0.16\nbox = [[0.0, 0.0], [1.2, 2.0]]"));
  EXPECT_NE(narrow.find("tube.toml:"), std::string::npos) << narrow;
  EXPECT_NE(narrow.find("plastic zone reaches the side of the cells' box"), std::string::npos) << narrow;
  // A box around the whole tube: its sides lie on the rollers or outside the body.
  const std::string wide = warnings(replaced(tube, "size = 0.16", "size = 0.16\nbox = [[0.0, 0.0], [2.0, 2.0]]"));
  EXPECT_EQ(wide.find("plastic zone"), std::string::npos) << wide;
}

// A force on a platen (the top of the pressed block, [load] on its boundary: u1 held, u2
// the approach) is the prescribed displacement that causes it. The block's top pressed
// 0.01 with u1 = 0 (not uniform: the top is held) gives a force per step; that force
// history on the platen gives back the approach 0.01 per step and the same cells. Elastic:
// the force at the end in one step (a body with a platen and no contact crashed before).
// Elastoplastic: the run's steps at the same times, so that the return mappings see the
// same increments (the contact model's route, the platen's motion equation changed by the
// cells at every Newton iteration).
TEST(ElastoplasticRun, ForceOnAPlatenIsThePrescribedDisplacementThatCausesIt) {
  RunOptions options;
  options.keep_tables = true;
  std::string pressed = replaced(replaced(test_support::pressed_block_text(), "ANALYSIS", "plane_strain"),
                                 "HARDENING", "20000.0");
  pressed = replaced(pressed, "u2 = -0.01\nt1 = 0.0\n", "u2 = -0.01\nu1 = 0.0\n");
  const auto on_platen = [](std::string text, double force, const std::string& amplitude) {
    text = replaced(text, "u2 = -0.01\nu1 = 0.0\n", "");
    return replaced(text, "[solver]", "[load]\nbody = \"block\"\nboundary = \"top\"\ncomponent = 2\nforce = " +
                                          io::format_number(force) + "\n" + amplitude + "[solver]");
  };
  for (const bool plastic : {false, true}) {
    std::string text = pressed;
    if (!plastic)
      text = replaced(replaced(replaced(text, "yield_stress = 250.0\nhardening = 20000.0\n", ""),
                               "[body.cells]\nsize = 0.25\n", ""),
                      "[solver]\nincrements = 10\n", "[solver]\n");
    const auto prescribed = run_problem(text, "block.toml", options);
    std::vector<double> times{1.0}, forces;
    if (plastic) {
      const auto& steps = prescribed.tables.at("block_steps.csv");
      times = column(steps, "time").numbers;
      forces = column(steps, "top_f2").numbers;
    } else {
      const auto summary = nlohmann::json::parse(*file(prescribed, "summary.json"));
      for (const auto& reaction : summary["reactions"]["block"])
        if (reaction["boundary"] == "top") forces.push_back(reaction["force"][1].get<double>());
    }
    ASSERT_EQ(forces.size(), times.size());
    std::string amplitude = "amplitude = [[0.0, 0.0]";
    for (std::size_t k = 0; k < times.size(); ++k)
      amplitude += ", [" + io::format_number(times[k]) + ", " + io::format_number(forces[k] / forces.back()) + "]";
    const auto pushed = run_problem(on_platen(text, forces.back(), amplitude + "]\n"), "block.toml", options);
    const auto& approach = column(pushed.tables.at("motions.csv"), "block_top_y_displacement").numbers;
    ASSERT_EQ(approach.size(), times.size()) << plastic;
    for (std::size_t k = 0; k < times.size(); ++k) EXPECT_NEAR(approach[k], -0.01 * times[k], 1e-9) << k;
    if (!plastic) continue;
    const auto& a = prescribed.tables.at("block_cells.csv");
    const auto& b = pushed.tables.at("block_cells.csv");
    for (const char* name : {"s11", "s22", "s12", "s33", "equivalent_plastic_strain"})
      for (std::size_t k = 0; k < column(a, name).numbers.size(); ++k)
        EXPECT_NEAR(column(b, name).numbers[k], column(a, name).numbers[k], 1e-8 * 250.0) << name << " " << k;
    EXPECT_GT(column(a, "equivalent_plastic_strain").numbers[0], 0.0);
  }
}

// Non-proportional loading: the pressed block's top pressed 0.01 over t in [0, 1] and held,
// then its right side pressed by 200 (0.8 Y) over [1, 2], a boundary with its own amplitude
// (a load group of its own). Uniform: every cell is the material point along the same
// steps with eps_22 and sigma_11 prescribed, to 1e-7 Y (the right side's pressure taken
// with the top's amplitude would press it from the start: s22 40 % of Y away).
TEST(ElastoplasticRun, BoundaryOfItsOwnAmplitudeLoadsTheCellsOnItsOwnPath) {
  std::string text = replaced(replaced(test_support::pressed_block_text(), "ANALYSIS", "plane_strain"),
                              "HARDENING", "20000.0");
  text = replaced(text, "to = [1.0, 1.0]\nelements = 8\n",
                  "to = [1.0, 1.0]\nelements = 8\npressure = 200.0\namplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0]]\n");
  text = replaced(text, "[solver]\nincrements = 10\n",
                  "[history]\ndata_amplitude = [[0.0, 0.0], [1.0, 1.0], [2.0, 1.0]]\nend_time = 2.0\n"
                  "[solver]\nincrements = 20\n");
  RunOptions options;
  options.keep_tables = true;
  const auto output = run_problem(text, "block.toml", options);
  const auto& times = column(output.tables.at("block_plastic_steps.csv"), "time").numbers;
  ASSERT_EQ(times.size(), 20u);
  std::vector<double> strains, stresses;
  for (const double t : times) {
    strains.push_back(-0.01 * std::min(t, 1.0));
    stresses.push_back(-200.0 * std::max(t - 1.0, 0.0));
  }
  const double Y = 250.0;
  const auto point = pressed_point_stress({200000.0, 0.3}, {Y, 20000.0, 0.0}, strains, stresses);
  const auto& cells = output.tables.at("block_cells.csv");
  for (std::size_t k = 0; k < column(cells, "s22").numbers.size(); ++k) {
    EXPECT_NEAR(column(cells, "s11").numbers[k], -200.0, 1e-7 * Y) << k;
    EXPECT_NEAR(column(cells, "s22").numbers[k], point[1], 1e-7 * Y) << k;
    EXPECT_NEAR(column(cells, "s33").numbers[k], point[2], 1e-7 * Y) << k;
  }
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
  expect(input_error(replaced(tube, "increments = 8", "increments = 8\noperator = \"compressed\"")), "yield_stress",
         "compressed");
  expect(input_error(replaced(tube, "[body.interior]", "[body.interior]\npoints = [[0.5, 0.5]]")), "interior",
         "not inside the body");
  // Too many cells for the memory limit: refused before the dense set-up, naming [cells].
  {
    RunOptions small;
    small.limits.max_memory_bytes = 3e6;  // above the boundary system (1.5 MB), below the 114 cells (7 MB)
    try {
      run_problem(tube, "tube.toml", small);
      ADD_FAILURE() << "no memory refusal";
    } catch (const InputError& error) {
      expect(error.what(), "cells", "of matrices, over the limit");
    }
  }
  // A linear elastic region with cells: the cells would do nothing.
  expect(input_error(replaced(tube, "yield_stress = \"Y\"", "")), "cells", "linear elastic");
}

}  // namespace
}  // namespace bemcontact::driver

// An elastoplastic region in contact (contact/plastic_coupling.hpp): each step one Newton
// on the cells' strains and the contact together. Checked three ways against what does not
// use the coupling: a block pressed by a rigid flat platen is the block whose top is pressed
// by a prescribed displacement (the material point's closed form); a ball indentation below
// first yield is the elastic contact; and the Brinell cycle's own balances (the load back to
// 0, a permanent dent, residual stresses in equilibrium). `validate brinell` checks the
// values.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/driver/run.hpp"
#include "support/example_text.hpp"
#include "support/pressed_point.hpp"

namespace bemcontact::driver {
namespace {

using test_support::example_text;
using test_support::pressed_point_stress;
using test_support::replaced;

const io::CsvTable::Column& column(const io::CsvTable& table, const std::string& name) {
  for (const auto& c : table.columns())
    if (c.name == name) return c;
  ADD_FAILURE() << "no column " << name;
  return table.columns().front();
}

// The pressed block (plane strain, its hardening `hardening`) with its top's prescribed
// displacement taken off: a smooth rigid platen wider than it pushes it 0.01 down; `solver`:
// more [solver] keys.
std::string block_under_platen(const std::string& hardening, const std::string& solver) {
  std::string block = replaced(replaced(test_support::pressed_block_text(), "ANALYSIS", "plane_strain"),
                               "HARDENING", hardening);
  block = replaced(block, "elements = 8\nu2 = -0.01\nt1 = 0.0\n", "elements = 8\n");
  return replaced(block, "increments = 10\n", "increments = 10\n" + solver) + R"(
[[body]]
name = "platen"
[body.rigid]
profile = "flat"
center = [0.5, 1.0]
half_width = 1.0
displacement = [0.0, -0.01]
[[contact]]
body1 = "block"
boundary1 = "top"
body2 = "platen"
normal = "body1"
)";
}

// A unit block (plane strain, perfectly plastic) on a roller base, its top pressed 8 Y/E
// down in 10 steps by a smooth rigid platen wider than it: uniform state, the material
// point's stress in every cell (as ElastoplasticRun.PressedBlockMeetsTheClosedForms with the
// displacement prescribed on the top).
TEST(PlasticContact, FlatPlatenPressesTheBlockAsItsPrescribedDisplacement) {
  const std::string text = block_under_platen("0.0", "");
  RunOptions options;
  options.keep_tables = true;
  const auto output = run_problem(text, "platen.toml", options);
  const double Y = 250.0;
  // Along the run's own increments: one the solver cut in halves at the limit load (the
  // block's tangent in compression vanishes there) takes another path of the return mapping.
  const auto point =
      pressed_point_stress({200000.0, 0.3}, {Y, 0.0, 0.0}, -0.01, column(output.tables.at("block_plastic_steps.csv"), "amplitude").numbers);
  const auto& cells = output.tables.at("block_cells.csv");
  ASSERT_EQ(column(cells, "s22").numbers.size(), 16u);
  for (std::size_t k = 0; k < 16; ++k) {
    EXPECT_NEAR(column(cells, "s22").numbers[k], point[1], 1e-7 * Y);
    EXPECT_NEAR(column(cells, "s33").numbers[k], point[2], 1e-7 * Y);
    EXPECT_NEAR(column(cells, "s11").numbers[k], 0.0, 1e-7 * Y);
  }
  // Every pair carries the same pressure, the cells' -s22.
  for (const double p : column(output.tables.at("contact.csv"), "p_n").numbers) EXPECT_NEAR(p, point[1], 1e-6 * Y);
}

// With record_steps every step's boundary fields are written, the elastoplastic region's
// with its cells at that step: the hardening block pressed by the platen has the material
// point's s22 at each step (to 1e-6 Y at every node), not the elastic solution's.
TEST(PlasticContact, RecordedStepsHoldEachStepsPlasticState) {
  const std::string text = block_under_platen("20000.0", "record_steps = true\n");
  RunOptions options;
  options.keep_tables = true;
  const auto output = run_problem(text, "platen.toml", options);
  const auto amplitudes = column(output.tables.at("block_plastic_steps.csv"), "amplitude").numbers;
  ASSERT_EQ(amplitudes.size(), 10u);
  for (const std::size_t k : {2u, 6u, 10u}) {
    const std::vector<double> path(amplitudes.begin(), amplitudes.begin() + static_cast<std::ptrdiff_t>(k));
    const auto point = pressed_point_stress({200000.0, 0.3}, {250.0, 20000.0, 0.0}, -0.01, path);
    const std::string name = "steps/block_boundary_step" + std::to_string(k) + ".csv";
    ASSERT_TRUE(output.tables.count(name)) << name;
    for (const double s22 : column(output.tables.at(name), "s22").numbers) EXPECT_NEAR(s22, point[1], 1e-6 * 250.0) << k;
  }
}

// A unit block of the pressed block's material (linear hardening E/10) between y0 and y0 + 1,
// held at x = 0 by a roller; `bottom` and `top` the conditions of those sides (none:
// free, for the contact).
std::string hardening_block(const std::string& name, double y0, const std::string& bottom, const std::string& top) {
  const auto y = [&](double dy) { return std::to_string(y0 + dy); };
  return "[[body]]\nname = \"" + name +
         "\"\n[body.material]\nE = 200000.0\nnu = 0.3\nyield_stress = 250.0\nhardening = 20000.0\n"
         "[body.cells]\nsize = 0.25\n"
         "[[body.boundary]]\nname = \"bottom\"\nfrom = [0.0, " + y(0) + "]\nto = [1.0, " + y(0) + "]\nelements = 8\n" +
         bottom + "[[body.boundary]]\nname = \"right\"\nfrom = [1.0, " + y(0) + "]\nto = [1.0, " + y(1) +
         "]\nelements = 8\n[[body.boundary]]\nname = \"top\"\nfrom = [1.0, " + y(1) + "]\nto = [0.0, " + y(1) +
         "]\nelements = 8\n" + top + "[[body.boundary]]\nname = \"left\"\nfrom = [0.0, " + y(1) + "]\nto = [0.0, " +
         y(0) + "]\nelements = 8\nu1 = 0.0\nt2 = 0.0\n";
}

// The lower block on a roller base, the upper one on it (frictionless contact), its top
// pressed 0.02 down in `increments` steps.
std::string stacked_blocks_text(int increments) {
  return "title = \"two blocks\"\nanalysis = \"plane_strain\"\n" +
         hardening_block("lower", 0.0, "u2 = 0.0\nt1 = 0.0\n", "") +
         hardening_block("upper", 1.0, "", "u2 = -0.02\nt1 = 0.0\n") +
         "[[contact]]\nbody1 = \"lower\"\nboundary1 = \"top\"\nbody2 = \"upper\"\n"
         "boundary2 = \"bottom\"\nnormal = \"body1\"\n[solver]\nincrements = " + std::to_string(increments) + "\n";
}

// Two elastoplastic blocks stacked, in frictionless contact, the upper one's top pressed
// 0.02 down: each is compressed 0.01 uniformly, so every cell of both is the material
// point pressed 8 Y/E (with hardening: no limit load) along the run's increments. Both
// regions' Newton iterations run together on one linearised contact.
TEST(PlasticContact, TwoElastoplasticBlocksPressedTogetherAreEachThePressedBlock) {
  const std::string text = stacked_blocks_text(10);
  RunOptions options;
  options.keep_tables = true;
  const auto output = run_problem(text, "blocks.toml", options);
  const double Y = 250.0;
  for (const std::string body : {"lower", "upper"}) {
    const auto point = pressed_point_stress({200000.0, 0.3}, {Y, 20000.0, 0.0}, -0.01,
                                            column(output.tables.at(body + "_plastic_steps.csv"), "amplitude").numbers);
    const auto& cells = output.tables.at(body + "_cells.csv");
    ASSERT_EQ(column(cells, "s22").numbers.size(), 16u) << body;
    EXPECT_GT(column(cells, "equivalent_plastic_strain").numbers[0], 4.0 * Y / 200000.0) << body;
    for (std::size_t k = 0; k < 16; ++k) {
      EXPECT_NEAR(column(cells, "s22").numbers[k], point[1], 1e-7 * Y) << body << " cell " << k;
      EXPECT_NEAR(column(cells, "s33").numbers[k], point[2], 1e-7 * Y) << body << " cell " << k;
      EXPECT_NEAR(column(cells, "s11").numbers[k], 0.0, 1e-7 * Y) << body << " cell " << k;
    }
  }
  // Every pair carries the cells' s22 (as the platen's pairs do).
  const auto point = pressed_point_stress({200000.0, 0.3}, {Y, 20000.0, 0.0}, -0.01,
                                          column(output.tables.at("lower_plastic_steps.csv"), "amplitude").numbers);
  for (const double p : column(output.tables.at("contact.csv"), "p_n").numbers) EXPECT_NEAR(p, point[1], 1e-6 * Y);
}

// The memory limit is for every elastoplastic region's cells together: two blocks that each
// fit alone are refused together, at the second block's [cells], naming the sum.
TEST(PlasticContact, TheMemoryLimitCountsEveryElastoplasticRegion) {
  const std::string text = stacked_blocks_text(2);
  RunOptions options;
  options.keep_tables = true;
  const auto output = run_problem(text, "blocks.toml", options);
  // One block's cells: 16 cells, its nodes as meshed.
  const auto nodes = static_cast<Index>(column(output.tables.at("lower_boundary.csv"), "x").numbers.size());
  const double one = bem::elastoplastic_region_bytes(16, nodes, AnalysisType::plane_strain);
  options.limits.max_memory_bytes = 1.5 * one;
  try {
    run_problem(text, "blocks.toml", options);
    ADD_FAILURE() << "two blocks' cells fit in 1.5 times one's";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("with the other elastoplastic regions' cells"), std::string::npos) << what;
    EXPECT_NE(what.find("blocks.toml:"), std::string::npos) << what;
    EXPECT_NE(what.find("cells"), std::string::npos) << what;
  }
}

// A block of the hardening material over [0, 1] x [0, 1] (sign = 1) or its mirror image
// across y = 0 (sign = -1), cells of 1/8, a roller at x = 0, pressed 0.004 toward y = 0 on
// its far side's first 0.4 (a punch of prescribed displacement): its near side "face" is free.
std::string punched_block(const std::string& name, int sign) {
  struct Side {
    const char* name;
    double x0, y0, x1, y1;
    int elements;
    std::string conditions;
  };
  const std::string pressed = "u2 = " + std::to_string(-0.004 * sign) + "\nt1 = 0.0\n";
  std::vector<Side> sides{{"face", 0.0, 0.0, 1.0, 0.0, 8, ""},
                          {"right", 1.0, 0.0, 1.0, 1.0, 8, ""},
                          {"free", 1.0, 1.0, 0.4, 1.0, 6, ""},
                          {"punch", 0.4, 1.0, 0.0, 1.0, 4, pressed},
                          {"left", 0.0, 1.0, 0.0, 0.0, 8, "u1 = 0.0\nt2 = 0.0\n"}};
  std::string text = "[[body]]\nname = \"" + name +
                     "\"\n[body.material]\nE = 200000.0\nnu = 0.3\nyield_stress = 250.0\nhardening = 20000.0\n"
                     "[body.cells]\nsize = 0.125\n";
  if (sign < 0) std::reverse(sides.begin(), sides.end());
  for (const auto& side : sides) {
    // The mirror image runs its sides the other way round (the body stays on their left).
    const double ys = sign;
    const auto point = [&](double x, double y) { return "[" + std::to_string(x) + ", " + std::to_string(ys * y) + "]"; };
    const std::string from = sign > 0 ? point(side.x0, side.y0) : point(side.x1, side.y1);
    const std::string to = sign > 0 ? point(side.x1, side.y1) : point(side.x0, side.y0);
    text += "[[body.boundary]]\nname = \"" + std::string(side.name) + "\"\nfrom = " + from + "\nto = " + to +
            "\nelements = " + std::to_string(side.elements) + "\n" + side.conditions;
  }
  return text;
}

// A block pressed by a punch onto its mirror image, both elastoplastic, is by symmetry the
// block pressed onto a frictionless rigid flat: the same cells' stresses to round-off, and
// the two blocks each other's mirror. The field is not uniform (38 of 64 cells yield, one
// pair lifts off): the two regions' Newton iterations, held cells included, must reach the
// one solution. (Before held cells were released where the solution unloads them, the
// regions settled on different held sets: 1.3 % apart.)
TEST(PlasticContact, BlockOnItsMirrorImageIsTheBlockOnARigidFlat) {
  const std::string header = "title = \"mirror\"\nanalysis = \"plane_strain\"\n";
  const std::string steps = "[solver]\nincrements = 10\n";
  const std::string pair = header + punched_block("upper", 1) + punched_block("lower", -1) +
                           "[[contact]]\nbody1 = \"upper\"\nboundary1 = \"face\"\nbody2 = \"lower\"\n"
                           "boundary2 = \"face\"\nnormal = \"body1\"\n" + steps;
  const std::string on_flat = header + punched_block("lower", -1) +
                              "[[body]]\nname = \"flat\"\n[body.rigid]\nprofile = \"flat\"\ncenter = [0.5, 0.0]\n"
                              "half_width = 1.0\ndisplacement = [0.0, 0.0]\n[[contact]]\nbody1 = \"lower\"\n"
                              "boundary1 = \"face\"\nbody2 = \"flat\"\nnormal = \"body1\"\n" + steps;
  RunOptions options;
  options.keep_tables = true;
  const auto both = run_problem(pair, "pair.toml", options);
  const auto one = run_problem(on_flat, "flat.toml", options);
  const auto& lower = both.tables.at("lower_cells.csv");
  const auto& upper = both.tables.at("upper_cells.csv");
  const auto& alone = one.tables.at("lower_cells.csv");
  const auto& s22 = column(alone, "s22").numbers;
  const double peak = std::abs(*std::min_element(s22.begin(), s22.end()));
  int yielded = 0;
  for (const double kappa : column(alone, "equivalent_plastic_strain").numbers) yielded += kappa > 0.0;
  EXPECT_GE(yielded, 20);
  for (const char* component : {"s11", "s22", "s12", "s33"}) {
    const auto& a = column(lower, component).numbers;
    const auto& b = column(alone, component).numbers;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-9 * peak) << component << " cell " << k;
  }
  // The upper block's cells are the lower's mirrored (s12 changes sign).
  const auto& x = column(lower, "x").numbers;
  const auto& y = column(lower, "y").numbers;
  for (std::size_t k = 0; k < x.size(); ++k) {
    std::size_t image = x.size();
    for (std::size_t j = 0; j < x.size(); ++j)
      if (std::abs(column(upper, "x").numbers[j] - x[k]) < 1e-9 && std::abs(column(upper, "y").numbers[j] + y[k]) < 1e-9)
        image = j;
    ASSERT_LT(image, x.size()) << "cell " << k << " has no mirror image";
    EXPECT_NEAR(column(upper, "s22").numbers[image], column(lower, "s22").numbers[k], 1e-9 * peak);
    EXPECT_NEAR(column(upper, "s12").numbers[image], -column(lower, "s12").numbers[k], 1e-9 * peak);
  }
}

// The Brinell example coarsened (cells of 0.64 away from the contact, 18 elements on its
// zone) and loaded to its peak only.
std::string coarse_brinell(double yield_stress) {
  std::string text = example_text("brinell.toml");
  text = replaced(text, "Y = 150.0", "Y = " + std::to_string(yield_stress));
  text = replaced(text, "cell = 0.16", "cell = 0.64");
  text = replaced(text, "n = 36", "n = 18");
  text = replaced(text, "end_time = 2.0", "end_time = 1.0");
  return replaced(text, "increments = 20", "increments = 2");
}

// The boundary meshed as given (nodes_at_cells = false), to compare with the elastic body.
std::string on_the_given_mesh(const std::string& text) {
  return replaced(text, "refine_size = \"cell / 4\"\n", "refine_size = \"cell / 4\"\nnodes_at_cells = false\n");
}

// The same file without yield_stress and cells.
std::string without_plasticity(const std::string& text) {
  return replaced(replaced(text, "yield_stress = \"Y\"\n", ""),
                  "[body.cells]\nsize = \"cell\"\nbox = [[0.0, -2.56], [2.56, 0.0]]\nrefine = [[0.0, 0.0]]\n"
                  "refine_size = \"cell / 4\"\nnodes_at_cells = false\n",
                  "");
}

// Below first yield the cells carry no initial stress: on the same mesh (nodes_at_cells =
// false) the pressures (and with friction the shears, the law's path through the steps
// included) are the elastic contact's to the solvers' tolerance.
TEST(PlasticContact, BallBelowFirstYieldIsTheElasticContact) {
  RunOptions options;
  options.keep_tables = true;
  for (const bool friction : {false, true}) {
    std::string text = on_the_given_mesh(coarse_brinell(1e9));
    if (friction) text = replaced(text, "normal = \"body1\"\n", "normal = \"body1\"\nfriction = 0.3\n");
    const auto plastic = run_problem(text, "ball.toml", options);
    const auto elastic = run_problem(without_plasticity(text), "ball.toml", options);
    const auto summary = nlohmann::json::parse(plastic.files.files().back().content);
    EXPECT_EQ(summary["results"]["elastoplastic"]["plastic_zone"]["yielded_cells"], 0);
    const auto& q = column(elastic.tables.at("contact.csv"), "p_n").numbers;
    const double peak = -*std::min_element(q.begin(), q.end());
    EXPECT_GT(peak, 1000.0);
    for (const char* name : {"p_n", "p_t"}) {
      const auto& p = column(plastic.tables.at("contact.csv"), name).numbers;
      const auto& e = column(elastic.tables.at("contact.csv"), name).numbers;
      ASSERT_EQ(p.size(), e.size());
      for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], e[i], 1e-8 * peak) << name << " " << i;
    }
    if (friction) {  // the shears are there to compare
      const auto& t = column(elastic.tables.at("contact.csv"), "p_t").numbers;
      EXPECT_GT(*std::max_element(t.begin(), t.end()) - *std::min_element(t.begin(), t.end()), 1e-3 * peak);
    }
  }
}

// The thesis' elastic ball on its support (examples/contact_hertz_sphere.toml), the support
// (side 2: its nodes enter the jumps through the ball's pairs' shape functions) made
// elastoplastic with a yield stress it never reaches, on the same mesh: the pressures and the
// interior grid's stresses (the cells' fields added) are those of the elastic support.
TEST(PlasticContact, ElasticBallOnASupportThatStaysElasticIsTheElasticContact) {
  RunOptions options;
  options.keep_tables = true;
  const std::string elastic_text = example_text("contact_hertz_sphere.toml");
  const std::string plastic_text =
      replaced(elastic_text, "E = 72000.0\nnu = 0.32\n",
               "E = 72000.0\nnu = 0.32\nyield_stress = 1e9\n[body.cells]\nsize = 0.04\nbox = [[0.0, -0.16], [0.16, 0.0]]\n"
               "nodes_at_cells = false\n");
  const auto elastic = run_problem(elastic_text, "hertz.toml", options);
  const auto plastic = run_problem(plastic_text, "hertz.toml", options);
  ASSERT_TRUE(plastic.tables.count("support_cells.csv"));
  const auto& p = column(plastic.tables.at("contact.csv"), "p_n").numbers;
  const auto& q = column(elastic.tables.at("contact.csv"), "p_n").numbers;
  ASSERT_EQ(p.size(), q.size());
  const double peak = -*std::min_element(q.begin(), q.end());
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], q[i], 1e-8 * peak) << i;
  const auto& s = column(plastic.tables.at("support_interior.csv"), "von_mises").numbers;
  const auto& t = column(elastic.tables.at("support_interior.csv"), "von_mises").numbers;
  ASSERT_EQ(s.size(), t.size());
  for (std::size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(s[i], t[i], 1e-7 * peak) << i;
}

// The hardening block held only by its contacts: a roller on its left side, frictionless
// contacts with a rigid floor below and a rigid platen above, pressed 0.01. Its vertical
// translation is a free motion (a pin whose displacement is a datum of the cells, its
// reaction a complementary value): every cell is the material point pressed 0.01.
TEST(PlasticContact, BlockHeldOnlyByItsContactsIsThePressedBlock) {
  std::string text = replaced(replaced(test_support::pressed_block_text(), "ANALYSIS", "plane_strain"),
                              "HARDENING", "20000.0");
  text = replaced(replaced(text, "u2 = 0.0\nt1 = 0.0\n", ""), "u2 = -0.01\nt1 = 0.0\n", "");
  text = replaced(text, "[solver]",
                  "[[body]]\nname = \"floor\"\n[body.rigid]\nprofile = \"contour\"\npoints = [[2.0, 0.0], [-1.0, 0.0]]\n"
                  "displacement = [0.0, 0.0]\n[[body]]\nname = \"platen\"\n[body.rigid]\nprofile = \"flat\"\n"
                  "center = [0.5, 1.0]\nhalf_width = 1.0\ndisplacement = [0.0, -0.01]\n"
                  "[[contact]]\nname = \"below\"\nbody1 = \"block\"\nboundary1 = \"bottom\"\nbody2 = \"floor\"\n"
                  "normal = \"body1\"\n[[contact]]\nname = \"above\"\nbody1 = \"block\"\nboundary1 = \"top\"\n"
                  "body2 = \"platen\"\nnormal = \"body1\"\n[solver]");
  RunOptions options;
  options.keep_tables = true;
  const auto output = run_problem(text, "free.toml", options);
  ASSERT_TRUE(output.tables.count("motions.csv"));  // the free motion is reported
  const double Y = 250.0;
  const auto point = pressed_point_stress({200000.0, 0.3}, {Y, 20000.0, 0.0}, -0.01,
                                          column(output.tables.at("block_plastic_steps.csv"), "amplitude").numbers);
  const auto& cells = output.tables.at("block_cells.csv");
  ASSERT_EQ(column(cells, "s22").numbers.size(), 16u);
  for (std::size_t k = 0; k < 16; ++k) {
    EXPECT_NEAR(column(cells, "s22").numbers[k], point[1], 1e-7 * Y) << k;
    EXPECT_NEAR(column(cells, "s11").numbers[k], 0.0, 1e-7 * Y) << k;
  }
  for (const char* contact : {"below.csv", "above.csv"})
    for (const double p : column(output.tables.at(contact), "p_n").numbers) EXPECT_NEAR(p, point[1], 1e-6 * Y);
}

// A block of two regions side by side, bonded along x = 1: "left" over [0, 1] x [0, 1]
// (elastoplastic, yield stress 250, hardening E/10, roller at x = 0) and "right" over
// [1, 2] x [0, 1] with the material `right_material`, both on a roller base; a smooth rigid
// flat pushes both tops `depth` down in 10 steps. The bond has 6 elements a side: the cells'
// vertices at y = 0.25 and 0.75 put nodes on it (nodes_at_cells), on both sides alike.
std::string bonded_block_text(const std::string& right_material, double depth) {
  const auto region = [](const std::string& name, double x0, const std::string& material, const std::string& left,
                         const std::string& right) {
    const auto x = [&](double dx) { return std::to_string(x0 + dx); };
    return "[[body.region]]\nname = \"" + name + "\"\n[body.region.material]\n" + material +
           "[[body.region.boundary]]\nname = \"" + name + " bottom\"\nfrom = [" + x(0) + ", 0.0]\nto = [" + x(1) +
           ", 0.0]\nelements = 8\nu2 = 0.0\nt1 = 0.0\n[[body.region.boundary]]\nname = \"" + name +
           " right\"\nfrom = [" + x(1) + ", 0.0]\nto = [" + x(1) + ", 1.0]\nelements = " +
           (right.empty() ? "8" : "6") + "\n" + right +
           "[[body.region.boundary]]\nname = \"" + name + " top\"\nfrom = [" + x(1) + ", 1.0]\nto = [" + x(0) +
           ", 1.0]\nelements = 8\n[[body.region.boundary]]\nname = \"" + name + " left\"\nfrom = [" + x(0) +
           ", 1.0]\nto = [" + x(0) + ", 0.0]\nelements = " + (left == "u1 = 0.0\nt2 = 0.0\n" ? "8" : "6") + "\n" +
           left;
  };
  const std::string bond = "interface = \"bond\"\n";
  std::string text = "title = \"bonded block\"\nanalysis = \"plane_strain\"\n[[body]]\nname = \"block\"\n" +
                     region("left", 0.0,
                            "E = 200000.0\nnu = 0.3\nyield_stress = 250.0\nhardening = 20000.0\n"
                            "[body.region.cells]\nsize = 0.25\n",
                            "u1 = 0.0\nt2 = 0.0\n", bond) +
                     region("right", 1.0, right_material, bond, "");
  text += "[[body]]\nname = \"platen\"\n[body.rigid]\nprofile = \"flat\"\ncenter = [1.0, 1.0]\nhalf_width = 2.0\n"
          "displacement = [0.0, " + std::to_string(-depth) + "]\n";
  for (const std::string side : {"left", "right"})
    text += "[[contact]]\nname = \"" + side + "\"\nbody1 = \"block\"\nboundary1 = \"" + side +
            " top\"\nbody2 = \"platen\"\nnormal = \"body1\"\n";
  return text + "[solver]\nincrements = 10\n";
}

// Two regions side by side pressed by a flat stay uniform, each at its own stress: the
// bond moves with the elastoplastic region's cells (its lateral plastic flow) and carries
// no traction. Without the cells' part in the bond equations the bond would shear and the
// fields would not be uniform. Right region elastic (E = 100 000: s22 = E eps / (1 - nu^2))
// and elastoplastic (yield stress 400, each region its material point).
TEST(PlasticContact, BondedRegionsSideBySidePressedByAFlatAreEachUniform) {
  RunOptions options;
  options.keep_tables = true;
  const double Y = 250.0, eps = -0.01;
  for (const bool right_plastic : {false, true}) {
    const std::string right = right_plastic ? "E = 200000.0\nnu = 0.3\nyield_stress = 400.0\nhardening = 20000.0\n"
                                              "[body.region.cells]\nsize = 0.25\n"
                                            : "E = 100000.0\nnu = 0.3\n";
    const auto output = run_problem(bonded_block_text(right, -eps), "bonded.toml", options);
    const auto amplitudes = column(output.tables.at("left_plastic_steps.csv"), "amplitude").numbers;
    const auto left = pressed_point_stress({200000.0, 0.3}, {Y, 20000.0, 0.0}, eps, amplitudes);
    EXPECT_LT(left[1], -1.5 * Y);  // well past first yield
    const double right_s22 = right_plastic ? pressed_point_stress({200000.0, 0.3}, {400.0, 20000.0, 0.0}, eps,
                                                                  amplitudes)[1]
                                           : 100000.0 * eps / (1.0 - 0.09);
    const auto expect_cells = [&](const std::string& name, double s22) {
      const auto& cells = output.tables.at(name + "_cells.csv");
      ASSERT_EQ(column(cells, "s22").numbers.size(), 16u) << name;
      for (std::size_t k = 0; k < 16; ++k) {
        EXPECT_NEAR(column(cells, "s22").numbers[k], s22, 1e-7 * Y) << name << " cell " << k;
        EXPECT_NEAR(column(cells, "s11").numbers[k], 0.0, 1e-7 * Y) << name << " cell " << k;
        EXPECT_NEAR(column(cells, "s12").numbers[k], 0.0, 1e-7 * Y) << name << " cell " << k;
      }
    };
    expect_cells("left", left[1]);
    if (right_plastic) expect_cells("right", right_s22);
    // Each contact's pairs carry their region's stress; every node of both boundaries too.
    for (const auto& [name, s22] : {std::pair<std::string, double>{"left", left[1]}, {"right", right_s22}}) {
      const auto& p = column(output.tables.at(name + ".csv"), "p_n").numbers;
      ASSERT_EQ(p.size(), 9u) << name;
      for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], s22, 1e-6 * Y) << name << " pair " << i;
      const auto& boundary = output.tables.at(name + "_boundary.csv");
      for (const double s : column(boundary, "s22").numbers) EXPECT_NEAR(s, s22, 1e-5 * Y) << name;
      for (const double s : column(boundary, "s12").numbers) EXPECT_NEAR(s, 0.0, 1e-5 * Y) << name;
    }
  }
}

// An axisymmetric cylinder (radius 1, height 2) of two elastoplastic regions stacked and
// bonded along z = 1 (the bond meets the axis), both of the hardening material, on a
// roller base, pressed 0.02 by a smooth rigid flat in 10 steps: uniaxial compression
// eps_zz = -0.01, every cell at |s_zz| = (Y + H |eps|) / (1 + H / E) (monotonic: the
// closed form, path free) and s_rr = s_tt = s_rz = 0.
TEST(PlasticContact, AxisymmetricRegionsStackedAndBondedOnTheAxisAreUniaxial) {
  const std::string material =
      "[body.region.material]\nE = 200000.0\nnu = 0.3\nyield_stress = 250.0\nhardening = 20000.0\n"
      "[body.region.cells]\nsize = 0.25\n";
  const auto side = [](const std::string& name, const std::string& from, const std::string& to,
                       const std::string& conditions) {
    return "[[body.region.boundary]]\nname = \"" + name + "\"\nfrom = " + from + "\nto = " + to +
           "\nelements = 8\n" + conditions;
  };
  const std::string text =
      "title = \"stacked cylinder\"\nanalysis = \"axisymmetric\"\n[[body]]\nname = \"cylinder\"\n"
      "[[body.region]]\nname = \"lower\"\n" + material +
      side("base", "[0.0, 0.0]", "[1.0, 0.0]", "u2 = 0.0\nt1 = 0.0\n") + side("lower side", "[1.0, 0.0]", "[1.0, 1.0]", "") +
      side("bond", "[1.0, 1.0]", "[0.0, 1.0]", "interface = \"bond\"\n") + side("lower axis", "[0.0, 1.0]", "[0.0, 0.0]", "") +
      "[[body.region]]\nname = \"upper\"\n" + material +
      side("bond above", "[0.0, 1.0]", "[1.0, 1.0]", "interface = \"bond\"\n") +
      side("upper side", "[1.0, 1.0]", "[1.0, 2.0]", "") + side("top", "[1.0, 2.0]", "[0.0, 2.0]", "") +
      side("upper axis", "[0.0, 2.0]", "[0.0, 1.0]", "") +
      "[[body]]\nname = \"platen\"\n[body.rigid]\nprofile = \"flat\"\ncenter = [0.5, 2.0]\nhalf_width = 1.0\n"
      "displacement = [0.0, -0.02]\n[[contact]]\nbody1 = \"cylinder\"\nboundary1 = \"top\"\nbody2 = \"platen\"\n"
      "normal = \"body1\"\n[solver]\nincrements = 10\n";
  RunOptions options;
  options.keep_tables = true;
  const auto output = run_problem(text, "cylinder.toml", options);
  const double E = 200000.0, Y = 250.0, H = 20000.0;
  const double szz = -(Y + H * 0.01) / (1.0 + H / E);
  for (const std::string name : {"lower", "upper"}) {
    const auto& cells = output.tables.at(name + "_cells.csv");
    ASSERT_GE(column(cells, "s22").numbers.size(), 16u) << name;
    for (std::size_t k = 0; k < column(cells, "s22").numbers.size(); ++k) {
      EXPECT_NEAR(column(cells, "s22").numbers[k], szz, 1e-7 * Y) << name << " cell " << k;
      for (const char* zero : {"s11", "s12", "s33"})
        EXPECT_NEAR(column(cells, zero).numbers[k], 0.0, 1e-7 * Y) << name << " cell " << k << " " << zero;
    }
  }
  for (const double p : column(output.tables.at("contact.csv"), "p_n").numbers) EXPECT_NEAR(p, szz, 1e-6 * Y);
}

// What the coupling does not serve is refused at the region's yield_stress, with its line,
// before any cell is made; what it serves in part is said.
TEST(PlasticContact, RefusesWhatTheCouplingDoesNotServe) {
  const auto refusal = [](const std::string& text) {
    try {
      run_problem(text, "ball.toml", {});
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    ADD_FAILURE() << "no input error";
    return std::string();
  };
  const std::string ball = coarse_brinell(150.0);
  // Wear cycles (they need friction, wear and a closed cycle: pressed, eased, pressed again).
  std::string worn = replaced(ball, "normal = \"body1\"\n", "normal = \"body1\"\nfriction = 0.3\nwear_coefficient1 = 1e-7\n");
  worn = replaced(worn, "[1.0, 1.0], [1.05, 0.995], [2.0, 0.0]]", "[1.0, 1.0], [1.5, 0.5], [2.0, 1.0]]");
  worn = replaced(worn, "end_time = 1.0", "end_time = 2.0\ncycles = 4\ncycle_start = 1.0");
  const std::string cycles = refusal(worn);
  EXPECT_NE(cycles.find("ball.toml:"), std::string::npos) << cycles;
  EXPECT_NE(cycles.find("yield_stress"), std::string::npos) << cycles;
  EXPECT_NE(cycles.find("cycle jumping"), std::string::npos) << cycles;
  // Compressed operators serve the elastic systems only: said, not refused.
  const auto compressed = run_problem(replaced(ball, "increments = 2", "increments = 2\noperator = \"compressed\""),
                                      "ball.toml", {});
  EXPECT_TRUE(std::any_of(compressed.warnings.begin(), compressed.warnings.end(), [](const std::string& w) {
    return w.find("stay dense") != std::string::npos;
  }));
  // Cells beyond the memory limit: refused at [cells] before their matrices are made.
  RunOptions small;
  small.limits.max_memory_bytes = 2e6;  // above the boundary (164 unknowns), below the cells
  try {
    run_problem(replaced(ball, "cell = 0.64", "cell = 0.16"), "ball.toml", small);
    ADD_FAILURE() << "no memory refusal";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("cells"), std::string::npos) << what;
    EXPECT_NE(what.find("--max-memory"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace bemcontact::driver

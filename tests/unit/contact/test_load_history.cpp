// Load histories: amplitudes, several force loads, adaptive stepping, loads no contact
// state can carry.
#include <gtest/gtest.h>

#include <cstdio>

#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "support/example_text.hpp"

namespace bemcontact::contact {
namespace {

using test_support::replaced;
std::string fretting_text() { return test_support::example_text("fretting_cylinder.toml"); }

}  // namespace

TEST(LoadHistory, AmplitudeIsPiecewiseLinearAndConstantOutside) {
  Amplitude ramp;
  EXPECT_DOUBLE_EQ(ramp.at(0.25), 0.25);
  EXPECT_DOUBLE_EQ(ramp.at(3.0), 1.0);
  Amplitude table{{{1.0, 0.0}, {2.0, 1.0}, {3.0, -1.0}}};
  EXPECT_DOUBLE_EQ(table.at(0.5), 0.0);
  EXPECT_DOUBLE_EQ(table.at(1.5), 0.5);
  EXPECT_DOUBLE_EQ(table.at(2.75), -0.5);
  EXPECT_DOUBLE_EQ(table.at(9.0), -1.0);
  EXPECT_EQ(table.corners(), (std::vector<double>{1.0, 2.0, 3.0}));
}

TEST(LoadHistory, FileReadsLoadsAmplitudesAndTheEndOfTheHistory) {
  const auto file = io::parse_contact_problem(fretting_text(), "fretting.toml");
  const auto& problem = file.problem;
  ASSERT_EQ(problem.forces.size(), 2u);
  EXPECT_EQ(problem.forces[0].name, "P");
  EXPECT_EQ(problem.forces[1].component, 0);
  EXPECT_DOUBLE_EQ(problem.end_time, 4.0);  // the last time of the amplitudes
  EXPECT_TRUE(problem.adaptive);            // friction > 0
  // The cyclic shorthand: a triangle wave through the mean.
  const auto cyclic = io::parse_contact_problem(
      replaced(fretting_text(), "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, -1.0], [4.0, 1.0]]",
               "amplitude = { amplitude = 1.0, cycles = 2, start = 1.0, period = 2.0 }"),
      "cyclic.toml");
  const auto& q = cyclic.problem.forces[1].amplitude;
  EXPECT_DOUBLE_EQ(q.at(1.5), 1.0);
  EXPECT_DOUBLE_EQ(q.at(2.5), -1.0);
  EXPECT_DOUBLE_EQ(q.at(5.0), 0.0);
  EXPECT_DOUBLE_EQ(cyclic.problem.end_time, 5.0);
}

TEST(LoadHistory, AmplitudeTimesMustIncrease) {
  try {
    io::parse_contact_problem(replaced(fretting_text(), "[3.0, -1.0], [4.0, 1.0]", "[3.0, -1.0], [2.5, 1.0]"),
                              "bad.toml");
    FAIL() << "decreasing times were accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("load[2].amplitude"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("must increase"), std::string::npos) << error.what();
  }
}

TEST(LoadHistory, ATangentialForceWithoutFrictionIsASolverErrorNamingTheLoad) {
  auto text = replaced(fretting_text(), "friction = \"mu\"", "friction = 0.0");
  text = replaced(text, "force = \"Q_ratio * mu * P\"", "force = 10.0");
  const auto file = io::parse_contact_problem(text, "frictionless.toml", {{"n", 20.0}});
  try {
    solve_contact(file.problem);
    FAIL() << "a tangential force without friction was carried";
  } catch (const SolverError& error) {
    EXPECT_NE(std::string(error.what()).find("load 'Q'"), std::string::npos) << error.what();
  }
}

TEST(LoadHistory, AForceAboveTheFrictionLimitIsASolverError) {
  const auto file = io::parse_contact_problem(fretting_text(), "gross.toml", {{"n", 20.0}, {"Q_ratio", 1.2}});
  EXPECT_THROW(solve_contact(file.problem), SolverError);
}

TEST(LoadHistory, AdaptiveStepsFollowTheFineHistory) {
  // A steel cylinder on aluminium (the normal load alone makes them slip against each
  // other), then Q = 0.6 mu P, 100 elements per zone: 16 equal steps leave the shear 15 % of
  // its peak away from 512 equal steps (it zig-zags from pair to pair); the adaptive
  // stepping from the same 16 comes within 1.4 % (held to 2.5 %) in 110 steps, 8 of them
  // redone. Growing each accepted step by 2 whatever it changed redid every other step:
  // 71 steps and 69 redone, 2.8 % away.
  auto text = replaced(fretting_text(), "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, -1.0], [4.0, 1.0]]",
                       "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0]]");
  text = replaced(text, "[body.material]\nE = \"E\"\nnu = 0.3\n[body.vertices]\nQL",
                  "[body.material]\nE = 210000.0\nnu = 0.3\n[body.vertices]\nQL");
  text = replaced(text, "name = \"block\"\n[body.material]\nE = \"E\"\nnu = 0.3",
                  "name = \"block\"\n[body.material]\nE = 70000.0\nnu = 0.33");
  const auto file = io::parse_contact_problem(text, "steel_on_aluminium.toml", {{"n", 100.0}});
  auto solve = [&](bool adaptive, int increments) {
    auto problem = file.problem;
    problem.adaptive = adaptive;
    problem.increments = increments;
    problem.drop_interior_points();
    return solve_contact(problem);
  };
  const auto fine = solve(false, 512), coarse = solve(false, 16), adaptive = solve(true, 16);
  double peak = 0.0;
  for (const auto& pair : fine.pairs) peak = std::max(peak, std::abs(pair.p_t));
  auto distance = [&](const ContactResult& result) {
    double worst = 0.0;
    for (std::size_t i = 0; i < fine.pairs.size(); ++i)
      worst = std::max(worst, std::abs(result.pairs[i].p_t - fine.pairs[i].p_t));
    return worst / peak;
  };
  EXPECT_GT(distance(coarse), 0.10);
  EXPECT_LT(distance(adaptive), 0.025);
  EXPECT_GT(adaptive.steps_taken, 16);
  EXPECT_LT(adaptive.steps_taken, 200);
  EXPECT_LT(adaptive.rejected_steps, adaptive.steps_taken / 4);
  // Most Newton systems are solved through earlier factors (kept, or a bordered update).
  const auto& systems = adaptive.newton_systems;
  EXPECT_GT(systems.updated, 0);
  EXPECT_GT(systems.updated + systems.reused, systems.factored);
}

}  // namespace bemcontact::contact

namespace bemcontact::contact {

TEST(LoadHistory, StepsThatChangeTooManyPairsAtTheShortestStepAreReported) {
  // max_steps = increments leaves no shorter step: the steps that change more than
  // max_state_changes pairs are taken as they are, counted and named in a warning. With
  // room to shorten (the default max_steps) none is left; the slip zone sticking at once at
  // the reversals is not counted, whatever the step.
  const auto file = io::parse_contact_problem(fretting_text(), "fretting.toml", {{"n", 30.0}});
  auto problem = file.problem;
  problem.drop_interior_points();
  problem.increments = 8;
  const auto roomy = solve_contact(problem);
  EXPECT_EQ(roomy.steps_at_shortest, 0);
  problem.max_steps = 8;
  const auto tight = solve_contact(problem);
  EXPECT_GT(tight.steps_at_shortest, 0);
  EXPECT_EQ(tight.rejected_steps, 0);
  ASSERT_FALSE(tight.warnings.empty());
  EXPECT_NE(tight.warnings.back().find("raise max_steps"), std::string::npos) << tight.warnings.back();
}

TEST(LoadHistory, AStepStartsOnTheLineThroughTheLastTwo) {
  // Between the amplitudes' corners the solution is affine in t while no pair changes state,
  // so a step that starts on the line through the last two steps, with that point's active
  // sets, takes one Newton iteration where a pair closes, starts to slip or sticks, and none
  // where no pair changes state (the point is the solution). Measured on the fretting cycle
  // with 60 elements per zone: 78 of its 99 steps take one iteration or none (41 when each
  // step started from the last one's solution and sets, 52 taking two).
  const auto file = io::parse_contact_problem(fretting_text(), "fretting.toml", {{"n", 60.0}});
  auto problem = file.problem;
  problem.drop_interior_points();
  const auto result = solve_contact(problem);
  int one = 0, none = 0, steps = 0;
  for (const auto& step : result.steps) {
    ++steps;
    one += step.newton_iterations <= 1;
    none += step.newton_iterations == 0;
    EXPECT_LE(step.newton_iterations, 3) << "at t = " << step.time;
  }
  ASSERT_EQ(steps, result.steps_taken);
  EXPECT_GE(one, 0.7 * steps) << one << " of " << steps << " steps in one iteration or none";
  EXPECT_GT(none, 0);
}

TEST(LoadHistory, ManyPairsTakeTheirProductsFromTheCompressedOperator) {
  // From 400 pairs the formed M is also held as a hierarchical matrix (accuracy 1e-14) for
  // the iterations' products and the update checks, the Newton systems' entries still from
  // M: its products within 1e-13 of M's (measured 2e-15), and the fretting history (P, then
  // Q to Q* and back to -Q*) within 1e-8 of the peak pressure of the run with M's own
  // products (contact_operator = "dense" keeps them), the same steps, Newton iterations and
  // steps at round-off. Measured 5.9e-10: each run stops at a residual of 1e-10 (the
  // tolerance), so the two agree to about that. At 1e-12 the products' error (1e-12 at 1 921
  // pairs) put the residual of 1 195 of the 2 106 steps of that cycle at 1.0-1.8e-10, above
  // the tolerance: each took one iteration more (4 619 against 3 320) and ended at round-off.
  auto text = replaced(fretting_text(), "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, -1.0], [4.0, 1.0]]",
                       "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, -1.0]]");
  const auto file = io::parse_contact_problem(text, "fretting.toml", {{"n", 400.0}});
  auto problem = file.problem;
  problem.drop_interior_points();
  problem.end_time = 3.0;
  const ContactModel model(problem);
  const auto& condensed = model.condensed();
  ASSERT_TRUE(condensed.M_products != nullptr);
  Vector x(condensed.M.cols());
  for (Index k = 0; k < x.size(); ++k) x[k] = std::cos(0.3 * static_cast<double>(k)) + (k % 2 ? 0.1 : 1.0);
  const Vector exact = condensed.M * x;
  EXPECT_LT((condensed.apply_M(x) - exact).norm(), 1e-13 * exact.norm());
  const auto compressed = solve_contact(problem);
  problem.solver.contact_operator = CondensedOperatorKind::dense;
  EXPECT_EQ(ContactModel(problem).condensed().M_products, nullptr);
  const auto formed = solve_contact(problem);
  ASSERT_EQ(compressed.steps_taken, formed.steps_taken);
  EXPECT_EQ(compressed.summary.newton_iterations, formed.summary.newton_iterations);
  EXPECT_EQ(compressed.steps_at_round_off, formed.steps_at_round_off);
  // The copy's size is reported (terminal, summary.json's products_compression), and only
  // where it took the products.
  EXPECT_GT(compressed.products_compression, 0.0);
  EXPECT_LT(compressed.products_compression, 1.0);
  EXPECT_EQ(formed.products_compression, 0.0);
  double peak = 0.0, worst = 0.0;
  for (const auto& pair : formed.pairs) peak = std::max(peak, std::abs(pair.p_n));
  for (std::size_t i = 0; i < formed.pairs.size(); ++i)
    worst = std::max({worst, std::abs(compressed.pairs[i].p_n - formed.pairs[i].p_n),
                      std::abs(compressed.pairs[i].p_t - formed.pairs[i].p_t)});
  EXPECT_LT(worst, 1e-8 * peak);
  std::printf("  compressed products: pressures and shears within %.2e of the peak pressure\n", worst / peak);
}

TEST(LoadHistory, AHistoryUnloadedToZeroOrNearlyEndsConverged) {
  // P and Q taken back to 0 (or P to 1e-3 of its peak) after the cycle: at zero load the
  // contact variables are round-off, which the residual must not take as its scale (the
  // last step failed with residual 1, or 7e-5 at 1e-3, before the floor on its scales).
  // With wear, the same (wear rides on the history's own steps).
  auto text = replaced(fretting_text(), "amplitude = [[0.0, 0.0], [1.0, 1.0]]",
                       "amplitude = [[0.0, 0.0], [1.0, 1.0], [4.0, 1.0], [5.0, END]]");
  text = replaced(text, "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, -1.0], [4.0, 1.0]]",
                  "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, -1.0], [4.0, 1.0], [4.5, 0.0]]");
  for (const char* end : {"0.0", "0.001"})
    for (const bool wear : {false, true}) {
      auto variant = replaced(text, "END", end);
      if (wear) variant = replaced(variant, "friction = \"mu\"\n", "friction = \"mu\"\nwear_coefficient1 = 1e-9\n");
      auto problem = io::parse_contact_problem(variant, "unloaded.toml").problem;
      problem.drop_interior_points();
      ContactResult result;
      ASSERT_NO_THROW(result = solve_contact(problem)) << "P to " << end << (wear ? ", with wear" : "");
      if (std::string(end) == "0.0") EXPECT_EQ(result.summary.pairs_in_contact, 0);
      else EXPECT_GT(result.summary.pairs_in_contact, 0);
    }
}

TEST(LoadHistory, ABoundaryAmplitudeEqualsTheDataAmplitudeWhenTheyAgree) {
  // The bulk stress of fretting_bulk_stress.toml through its boundary's own amplitude, or
  // through [history] data_amplitude: the same history, the same answer.
  const auto own = test_support::example_text("fretting_bulk_stress.toml");
  auto shared = test_support::replaced(own, "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0]]   # the bulk stress comes with Q\n", "");
  shared += "\n[history]\ndata_amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0]]\n";
  const io::ParameterOverrides coarse{{"n", 20.0}};
  const auto a = solve_contact(io::parse_contact_problem(own, "own.toml", coarse).problem);
  const auto b = solve_contact(io::parse_contact_problem(shared, "shared.toml", coarse).problem);
  ASSERT_EQ(a.pairs.size(), b.pairs.size());
  double scale = 0.0, difference = 0.0;
  for (std::size_t i = 0; i < a.pairs.size(); ++i) {
    scale = std::max(scale, std::abs(a.pairs[i].p_n));
    difference = std::max({difference, std::abs(a.pairs[i].p_n - b.pairs[i].p_n), std::abs(a.pairs[i].p_t - b.pairs[i].p_t)});
  }
  EXPECT_LT(difference, 1e-9 * scale);
}

TEST(LoadHistory, AnInterferenceRampedInStepsEndsAtTheSamePressure) {
  // Frictionless: the path does not matter, so a shrink fit built up over 4 steps ends
  // where the one-step fit is.
  auto text = test_support::example_text("contact_shrink_fit.toml");
  const auto once = solve_contact(io::parse_contact_problem(text, "once.toml").problem);
  text = test_support::replaced(text, "interference = \"delta\"",
                                "interference = \"delta\"\ninterference_amplitude = [[0.0, 0.0], [1.0, 1.0]]\nincrements = 4");
  const auto ramped = solve_contact(io::parse_contact_problem(text, "ramped.toml").problem);
  EXPECT_EQ(ramped.steps_taken, 4);
  EXPECT_NEAR(ramped.summary.peak_pressure, once.summary.peak_pressure, 1e-9 * once.summary.peak_pressure);
  EXPECT_GT(ramped.steps.front().peak_pressure, 0.2 * once.summary.peak_pressure);
  EXPECT_LT(ramped.steps.front().peak_pressure, 0.3 * once.summary.peak_pressure);  // a quarter of the fit
}

TEST(LoadHistory, ClosedPairsHaveTheirGapAsJumpInEveryKindOfContact) {
  // jump_n is [u]·n itself and gap the initial gap less the interference applied so far:
  // closed pairs have jump_n = gap, in a shrink fit (the jump is the overlap -delta, the
  // whole fit at once and a quarter of it after the first of 4 steps) as in Hertz's contact.
  auto text = test_support::example_text("contact_shrink_fit.toml");
  const auto fit = io::parse_contact_problem(text, "fit.toml");
  const double delta = fit.parameters.at("delta");
  text = test_support::replaced(text, "interference = \"delta\"",
                                "interference = \"delta\"\ninterference_amplitude = [[0.0, 0.0], [1.0, 1.0]]\n"
                                "increments = 4\nrecord_steps = true");
  const auto ramped = solve_contact(io::parse_contact_problem(text, "ramped.toml").problem);
  const auto ball = solve_contact(io::parse_contact_problem(test_support::example_text("contact_hertz_sphere.toml"),
                                                            "ball.toml").problem);
  for (const auto& [pairs, overlap] : {std::pair{ramped.pairs, delta}, std::pair{ramped.step_pairs.front(), 0.25 * delta}}) {
    for (const auto& pair : pairs) {
      ASSERT_NE(pair.status, PairStatus::open);
      EXPECT_NEAR(pair.gap, -overlap, 1e-12 * delta);
      EXPECT_NEAR(pair.jump_n, pair.gap, 1e-9 * delta);
    }
  }
  for (const auto& pair : ball.pairs)
    if (pair.status != PairStatus::open) EXPECT_NEAR(pair.jump_n, pair.gap, 1e-9 * ball.summary.approach * -1.0);
}

}  // namespace bemcontact::contact

#include "bemcontact/io/output/contact_writer.hpp"

namespace bemcontact::contact {

TEST(LoadHistory, RecordedStepsAreAParaViewTimeSeries) {
  auto problem = io::parse_contact_problem(test_support::example_text("fretting_cylinder.toml"), "fretting.toml",
                                           {{"n", 10.0}})
                     .problem;
  problem.record_steps = true;
  problem.set_friction(0.0);  // frictionless: the equal steps as given
  problem.adaptive = false;
  problem.forces.pop_back();  // P only
  problem.increments = 4;
  problem.end_time = 1.0;
  const auto result = solve_contact(problem);
  ASSERT_EQ(result.step_boundary.size(), 4u);
  std::map<std::string, std::string> files;
  for (const auto& f : io::contact_output_files(problem, result)) files[f.name] = f.text();
  ASSERT_TRUE(files.count("cylinder_boundary.pvd"));
  const std::string& pvd = files["cylinder_boundary.pvd"];
  std::size_t datasets = 0;
  for (std::size_t at = pvd.find("<DataSet"); at != std::string::npos; at = pvd.find("<DataSet", at + 1)) ++datasets;
  EXPECT_EQ(datasets, 4u);
  EXPECT_NE(pvd.find("timestep=\"0.5\""), std::string::npos);
  EXPECT_NE(pvd.find("file=\"steps/cylinder_boundary_step4.vtp\""), std::string::npos);  // the step files' folder
  const std::string& step = files.at("steps/block_boundary_step4.vtp");
  EXPECT_NE(step.find("NumberOfPoints=\"" + std::to_string(result.meshes[1].node_count()) + "\""), std::string::npos);
  EXPECT_NE(step.find("Name=\"s11\""), std::string::npos);
  // The last step is the final state.
  EXPECT_NEAR(result.step_boundary.back()[1].traction[0].y(), result.boundary[1].traction[0].y(), 1e-12);
}

}  // namespace bemcontact::contact

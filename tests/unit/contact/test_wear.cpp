// Archard wear (contact/wear.hpp): one step's wear, the linearly implicit cycle jump, the keys'
// checks, and a wear run that wears its contact away.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/wear.hpp"
#include "bemcontact/core/error.hpp"
#include "support/contact_input.hpp"
#include "support/example_text.hpp"

namespace bemcontact {
namespace {

using test_support::example_text;
using test_support::mentions;
using test_support::replaced;

std::string wear_input_error(const std::string& text) { return test_support::contact_input_error(text, "wear.toml"); }

// n pairs pressed by a rigid platen under a force: w_n = -lambda / c + approach, the force
// equation sum w_i lambda_i = P. A uniform gap change moves the platen, not the pressures.
struct PlatenPairs {
  Matrix M, b, f, f_delta;
  Vector x;
  explicit PlatenPairs(Index n, double c = 2.0) : M(Matrix::Zero(2 * n, 2 * n)), b(Matrix::Zero(2 * n, 1)),
                                                  f(Matrix::Zero(1, 2 * n)), f_delta(Matrix::Zero(1, 1)),
                                                  x(Vector::Zero(2 * n)) {
    for (Index i = 0; i < n; ++i) {
      M(2 * i, 2 * i) = -1.0 / c;
      M(2 * i + 1, 2 * i + 1) = -1.0 / c;
      b(2 * i, 0) = 1.0;
      f(0, 2 * i) = 1.0 + 0.1 * static_cast<double>(i);  // unequal weights
      x[2 * i] = 1.0;
    }
  }
};

}  // namespace

TEST(Wear, StepWearIsArchardsLawPerSide) {
  contact::WearCoefficients k{Vector::Constant(3, 2.0), Vector::Constant(3, 0.5)};
  contact::WearDepths depths{Vector::Zero(3), Vector::Zero(3)};
  const Vector x = (Vector(6) << 10.0, 1.0, 0.0, 0.0, 4.0, -1.0).finished();  // lambda_n, tau per pair
  const Vector w = (Vector(6) << 0.0, 0.3, 0.0, 0.5, 0.0, -0.2).finished();    // w_n, w_t per pair
  const Vector previous = (Vector(3) << 0.1, 0.1, -0.2).finished();             // the last step's w_t
  contact::add_step_wear(k, x, w, previous, depths);
  EXPECT_DOUBLE_EQ(depths.side1[0], 2.0 * 10.0 * 0.2);
  EXPECT_DOUBLE_EQ(depths.side2[0], 0.5 * 10.0 * 0.2);
  EXPECT_EQ(depths.side1[1], 0.0);  // open: no pressure, no wear, whatever it slides
  EXPECT_EQ(depths.side1[2], 0.0);  // stuck: no slip increment
  std::vector<contact::ContactPair> pairs(3);
  for (auto& p : pairs) p.weight = 0.25;
  EXPECT_DOUBLE_EQ(contact::worn_volume(pairs, depths.side1, 0, 3), 0.25 * 4.0);
}

// Uniform wear under a force load lowers the platen and leaves the pressures: the implicit
// jump passes it whole, whatever the jump; a non-uniform one solves (I - tau D G) dh = tau r
// and tends to the explicit tau r for short jumps.
TEST(Wear, ImplicitJumpPassesUniformWearAndSolvesItsSystem) {
  const Index n = 6;
  const PlatenPairs platen(n);
  const auto response = contact::pressure_response(platen.M, platen.b, platen.f, platen.f_delta, platen.x);
  ASSERT_EQ(response.closed.size(), static_cast<std::size_t>(n));
  EXPECT_LT((response.G * Vector::Ones(n)).norm(), 1e-12);
  const Vector rate = Vector::Constant(n, 1e-3);
  const Vector uniform = Vector::Constant(n, 1e-4);
  EXPECT_LT((contact::implicit_jump(response, rate, uniform, 1e4) - 1e4 * uniform).norm(), 1e-12);

  Vector wear(n);
  for (Index i = 0; i < n; ++i) wear[i] = 1e-4 * (1.0 + static_cast<double>(i * i));
  for (const double tau : {1.0, 1e3, 1e6}) {
    const Vector jump = contact::implicit_jump(response, rate, wear, tau);
    const Vector residual = jump - tau * rate.asDiagonal() * (response.G * jump) - tau * wear;
    EXPECT_LT(residual.norm(), 1e-10 * tau * wear.norm()) << tau;
    EXPECT_TRUE(jump.allFinite());
  }
  const Vector short_jump = contact::implicit_jump(response, rate, wear, 1e-3);
  EXPECT_LT((short_jump - 1e-3 * wear).norm(), 1e-5 * (1e-3 * wear).norm());
  // The pairs out of contact have no pressure to respond: their wear is extrapolated as it is.
  PlatenPairs half(n);
  half.x[0] = 0.0;
  const auto partial = contact::pressure_response(half.M, half.b, half.f, half.f_delta, half.x);
  EXPECT_EQ(partial.closed.size(), static_cast<std::size_t>(n - 1));
  EXPECT_DOUBLE_EQ(contact::implicit_jump(partial, rate, wear, 50.0)[0], 50.0 * wear[0]);
}

TEST(Wear, AdaptiveJumpFollowsThePressureChange) {
  const contact::CycleJumpControl control{1000, 0.05};
  EXPECT_TRUE(control.reject(8, 0.06));
  EXPECT_FALSE(control.reject(1, 0.5));  // a single cycle is computed, not extrapolated
  EXPECT_EQ(control.next(8, 0.06), 4);
  EXPECT_EQ(control.next(8, 0.01), 16);
  EXPECT_EQ(control.next(8, 0.03), 8);
  EXPECT_EQ(control.next(800, 0.0), 1000);
}

TEST(Wear, KeysAreCheckedWhereTheyAreRead) {
  const std::string punch = example_text("wear_punch_gross_slip.toml");
  const std::string cylinder = example_text("fretting_wear.toml");
  const auto negative = wear_input_error(replaced(punch, "\nk = 1e-8", "\nk = -1e-8"));
  EXPECT_TRUE(mentions(negative, "wear_coefficient1")) << negative;
  const auto rigid = wear_input_error(replaced(punch, "wear_coefficient1 = \"k\"", "wear_coefficient2 = \"k\""));
  EXPECT_TRUE(mentions(rigid, "wear_coefficient2") && mentions(rigid, "rigid")) << rigid;
  const auto no_wear = wear_input_error(replaced(punch, "wear_coefficient1 = \"k\"\n", ""));
  EXPECT_TRUE(mentions(no_wear, "history.cycles") && mentions(no_wear, "without wear")) << no_wear;
  const auto no_start = wear_input_error(replaced(punch, "cycle_start = 2.0\n", ""));
  EXPECT_TRUE(mentions(no_start, "cycle_start")) << no_start;
  const auto late = wear_input_error(replaced(punch, "cycle_start = 2.0", "cycle_start = 4.0"));
  EXPECT_TRUE(mentions(late, "before end_time")) << late;
  const auto open_cycle = wear_input_error(replaced(punch, "cycle_start = 2.0", "cycle_start = 1.0"));
  EXPECT_TRUE(mentions(open_cycle, "does not close") && mentions(open_cycle, "rigid body 'punch'")) << open_cycle;
  const auto zero_jump = wear_input_error(replaced(punch, "cycle_start = 2.0", "cycle_start = 2.0\ncycle_jump = 0"));
  EXPECT_TRUE(mentions(zero_jump, "history.cycle_jump")) << zero_jump;
  const auto both = wear_input_error(
      replaced(punch, "cycle_start = 2.0", "cycle_start = 2.0\ncycle_jump = 10\nmax_cycle_jump = 100"));
  EXPECT_TRUE(mentions(both, "max_cycle_jump") && mentions(both, "no effect")) << both;
  const auto single = wear_input_error(replaced(replaced(punch, "N = 100000", "N = 1"), "cycle_start = 2.0",
                                                "cycle_start = 2.0\nmax_pressure_change = 0.1"));
  EXPECT_TRUE(mentions(single, "cycle_start") && mentions(single, "no effect")) << single;
  const auto recorded = wear_input_error(replaced(punch, "increments = 16", "increments = 16\nrecord_steps = true"));
  EXPECT_TRUE(mentions(recorded, "solver.record_steps") && mentions(recorded, "wear_profile")) << recorded;
  EXPECT_EQ(wear_input_error(cylinder), "no error");
}

// A prescribed approach that the wear outgrows (a coefficient so large that one step wears
// past it): the run stops naming the cycle (exit 3).
TEST(Wear, AContactWornAwayStopsTheRun) {
  std::string text = replaced(example_text("wear_punch_gross_slip.toml"), "displacement = [\"delta\", 0.0]",
                              "displacement = [\"delta\", -1e-4]");
  const auto start = text.find("[load]");
  text = text.substr(0, start) + text.substr(text.find("[history]"));
  auto file = io::parse_contact_problem(text, "wear.toml", {{"k", 10.0}, {"N", 10.0}, {"n", 10.0}});
  file.problem.drop_interior_points();
  try {
    (void)contact::solve_contact(file.problem);
    FAIL() << "no error";
  } catch (const SolverError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(mentions(message, "no longer touch") && mentions(message, "load cycle")) << message;
  }
}

}  // namespace bemcontact

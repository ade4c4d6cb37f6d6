// Normal compliance (ContactKind::compliant, NormalCompliance): the Newton solution follows
// the law pair by pair, friction follows beta (c_t / c_n) p_n in slip, and the keys of the
// law are checked where they are read.
#include <gtest/gtest.h>

#include <cmath>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/reference/winkler.hpp"
#include "support/contact_input.hpp"
#include "support/example_text.hpp"

namespace bemcontact {
namespace {

using test_support::example_text;
using test_support::replaced;

std::string compliant_text() { return example_text("contact_compliant_cylinder.toml"); }

std::string compliance_input_error(const std::string& text) {
  return test_support::contact_input_error(text, "compliant.toml");
}

using test_support::mentions;

}  // namespace

// Every pair in contact carries c_n pen^m of its own interpenetration pen = jump_n - gap, and
// every open pair has pen <= 0; the pressures balance the load.
TEST(NormalCompliance, EveryPairFollowsTheLaw) {
  for (const double m : {1.0, 2.2}) {
    const double cn = m == 1.0 ? 1.0e4 : 5.8e6;
    const auto file = io::parse_contact_problem(compliant_text(), "compliant.toml", {{"m", m}, {"cn", cn}});
    const auto result = contact::solve_contact(file.problem);
    double peak = 0.0;
    for (const auto& pair : result.pairs) peak = std::max(peak, -pair.p_n);
    for (const auto& pair : result.pairs) {
      const double pen = pair.jump_n - pair.gap;
      if (pair.status == contact::PairStatus::open) {
        EXPECT_LE(pen, 1e-12) << pair.coordinate;
        EXPECT_EQ(pair.p_n, 0.0);
      } else {
        EXPECT_NEAR(-pair.p_n, cn * std::pow(std::max(pen, 0.0), m), 1e-8 * peak) << pair.coordinate;
      }
    }
    EXPECT_NEAR(result.summary.normal_force, file.parameters.at("P"), 1e-6 * file.parameters.at("P"));
    const reference::WinklerCylinder exact{file.parameters.at("P"), 1.0, cn, m};
    EXPECT_NEAR(result.summary.centre_pressure / exact.max_pressure(), 1.0, 2.5e-3);
  }
}

// A tangential force near the friction limit Q = beta (c_t / c_n) P (on an elastic block:
// on the example's near-rigid one the tangential stiffness is 10^5 times the normal one and
// the step stalls at a residual of 1e-7): most pairs slip, with p_t = beta (c_t / c_n) p_n.
// With m_t != m_n (2 against 1; 3 and 1.5 against 2.2, c_t giving the centre the threshold
// beta p0) under Q = 0.1 P: every slipping pair carries beta c_t pen^m_t of its own
// interpenetration.
TEST(NormalCompliance, GrossSlipFollowsTheThreshold) {
  const std::string loads = "[[load]]\nname = \"P\"\nbody = \"cylinder\"\ncomponent = 2\nforce = \"-P\"\n"
                            "amplitude = [[0.0, 0.0], [1.0, 1.0]]\n"
                            "[[load]]\nname = \"Q\"\nbody = \"cylinder\"\ncomponent = 1\nforce = \"Qr * P\"\n"
                            "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0]]\n";
  const auto with_friction = [&](const std::string& law) {
    auto text = replaced(compliant_text(), "normal_exponent = \"m\"", "normal_exponent = \"m\"\nfriction = 0.3\n" + law);
    text = replaced(text, "\nm = 1.0", "\nm = 1.0\nQr = 0.1\nct = 1.0e4\nmt = 1.0");
    return replaced(text, "[load]\nbody = \"cylinder\"\ncomponent = 2\nforce = \"-P\"\n", loads);
  };
  {
    const auto file = io::parse_contact_problem(with_friction("friction_stiffness = 2.0e4"), "compliant.toml",
                                                {{"E_block", 70000.0}, {"Qr", 0.6 * 0.999}});
    const auto result = contact::solve_contact(file.problem);
    double peak = 0.0;
    for (const auto& pair : result.pairs) peak = std::max(peak, -pair.p_n);
    int slipping = 0;
    for (const auto& pair : result.pairs) {
      if (pair.status == contact::PairStatus::open) continue;
      EXPECT_LE(std::abs(pair.p_t), 0.6 * -pair.p_n + 1e-9 * peak) << pair.coordinate;
      if (pair.status == contact::PairStatus::slip) {
        ++slipping;
        EXPECT_NEAR(std::abs(pair.p_t), 0.6 * -pair.p_n, 1e-7 * peak) << pair.coordinate;
      }
    }
    EXPECT_GT(slipping, result.summary.pairs_in_contact / 2);
    EXPECT_NEAR(std::abs(result.summary.tangential_force), 0.999 * 0.6 * file.parameters.at("P"),
                1e-6 * file.parameters.at("P"));
  }
  struct Case {
    double m, cn, mt, ct;
  };
  for (const Case& law : {Case{1.0, 1.0e4, 2.0, 2.0e6}, Case{2.2, 5.8e6, 3.0, 3.74e8}, Case{2.2, 5.8e6, 1.5, 1.515e5}}) {
    const auto file = io::parse_contact_problem(
        with_friction("friction_stiffness = \"ct\"\nfriction_exponent = \"mt\""), "compliant.toml",
        {{"E_block", 70000.0}, {"Qr", 0.1}, {"m", law.m}, {"cn", law.cn}, {"mt", law.mt}, {"ct", law.ct}});
    auto problem = file.problem;
    problem.adaptive = false;  // 16 equal steps: 62-66 Newton iterations against 450-540 adaptive
    const auto result = contact::solve_contact(problem);
    double peak = 0.0;
    for (const auto& pair : result.pairs) peak = std::max(peak, -pair.p_n);
    int slipping = 0;
    for (const auto& pair : result.pairs) {
      if (pair.status != contact::PairStatus::slip) continue;
      ++slipping;
      const double pen = std::max(pair.jump_n - pair.gap, 0.0);
      EXPECT_NEAR(std::abs(pair.p_t), 0.3 * law.ct * std::pow(pen, law.mt), 1e-9 * peak) << law.mt << " " << pair.coordinate;
      EXPECT_NEAR(-pair.p_n, law.cn * std::pow(pen, law.m), 1e-8 * peak) << law.mt << " " << pair.coordinate;
    }
    EXPECT_GT(slipping, result.summary.pairs_in_contact / 3) << law.mt;
    EXPECT_NEAR(std::abs(result.summary.tangential_force), 0.1 * file.parameters.at("P"), 1e-6 * file.parameters.at("P"));
  }
}

// m_t = 1 against m_n = 2.2: the halves of the first steps do not converge (the threshold far
// exceeds beta p_n at small interpenetrations); adaptive stepping takes the last longer step
// that converged, says so, and the law holds pair by pair.
TEST(NormalCompliance, AConcaveThresholdTakesAConvergedLongerStep) {
  auto text = replaced(compliant_text(), "normal_exponent = \"m\"",
                       "normal_exponent = 2.2\nfriction = 0.3\nfriction_stiffness = 11207.0\nfriction_exponent = 1.0");
  text = replaced(text, "[load]\nbody = \"cylinder\"\ncomponent = 2\nforce = \"-P\"\n",
                  "[[load]]\nname = \"P\"\nbody = \"cylinder\"\ncomponent = 2\nforce = \"-P\"\n"
                  "amplitude = [[0.0, 0.0], [1.0, 1.0]]\n"
                  "[[load]]\nname = \"Q\"\nbody = \"cylinder\"\ncomponent = 1\nforce = \"0.1 * P\"\n"
                  "amplitude = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0]]\n");
  const auto file = io::parse_contact_problem(text, "compliant.toml", {{"E_block", 70000.0}, {"cn", 5.8e6}});
  const auto result = contact::solve_contact(file.problem);
  EXPECT_GT(result.steps_past_state_limit, 0);
  double peak = 0.0;
  for (const auto& pair : result.pairs) peak = std::max(peak, -pair.p_n);
  for (const auto& pair : result.pairs)
    if (pair.status == contact::PairStatus::slip)
      EXPECT_NEAR(std::abs(pair.p_t), 0.3 * 11207.0 * std::max(pair.jump_n - pair.gap, 0.0), 1e-9 * peak);
}

TEST(NormalCompliance, KeysAreCheckedWhereTheyAreRead) {
  const auto missing = compliance_input_error(replaced(compliant_text(), "normal_stiffness = \"cn\"\n", ""));
  EXPECT_TRUE(mentions(missing, "compliant.toml:")) << missing;
  EXPECT_TRUE(mentions(missing, "normal_stiffness")) << missing;
  const auto other_kind = compliance_input_error(replaced(compliant_text(), "kind = \"compliant\"", "kind = \"unilateral\""));
  EXPECT_TRUE(mentions(other_kind, "normal_stiffness belongs to normal compliance")) << other_kind;
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"normal_exponent = \"m\"", "normal_exponent = 0.5"}, {"normal_stiffness = \"cn\"", "normal_stiffness = 0.0"}}) {
    const auto message = compliance_input_error(replaced(compliant_text(), from, to));
    EXPECT_TRUE(mentions(message, "compliant.toml:")) << message;
    EXPECT_TRUE(mentions(message, to.substr(0, to.find(' ')))) << message;
  }
  const auto no_friction =
      compliance_input_error(replaced(compliant_text(), "normal_exponent = \"m\"", "normal_exponent = \"m\"\nfriction_stiffness = 1.0"));
  EXPECT_TRUE(mentions(no_friction, "with friction = 0 it has no effect")) << no_friction;
  const auto exponent = compliance_input_error(replaced(
      compliant_text(), "normal_exponent = \"m\"", "normal_exponent = \"m\"\nfriction_exponent = 1.5"));
  EXPECT_TRUE(mentions(exponent, "friction_exponent") && mentions(exponent, "no effect")) << exponent;
  const auto thesis =
      compliance_input_error(replaced(compliant_text(), "[load]", "[solver]\nalgorithm = \"thesis\"\n\n[load]"));
  EXPECT_TRUE(mentions(thesis, "Newton algorithm only")) << thesis;
}

}  // namespace bemcontact

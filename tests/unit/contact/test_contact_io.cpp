// The contact problem file and the writers: the examples read as documented, and the
// outputs hold one row per pair and the summary quantities.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include <nlohmann/json.hpp>

#include "bemcontact/io/input/problem_text.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/output/contact_writer.hpp"

namespace bemcontact {

TEST(ContactIo, ExamplesReadWithTheirSettings) {
  const std::string dir = BEMCONTACT_EXAMPLES_DIR;
  const auto hertz = io::read_contact_file(dir + "/contact_hertz_sphere.toml");
  EXPECT_EQ(hertz.problem.analysis, AnalysisType::axisymmetric);
  EXPECT_EQ(hertz.problem.contacts.front().law.kind, contact::ContactKind::unilateral);
  EXPECT_EQ(hertz.problem.contacts.front().pair_normal, contact::PairNormal::body2);
  ASSERT_EQ(hertz.problem.forces.size(), 1u);
  EXPECT_DOUBLE_EQ(hertz.problem.forces[0].force, -31.5);
  EXPECT_EQ(hertz.problem.forces[0].component, 1);
  EXPECT_EQ(hertz.problem.bodies[0].name, "ball");
  EXPECT_DOUBLE_EQ(hertz.problem.elastic(0).material.young_modulus, 432000.0);
  const auto spence = io::read_contact_file(dir + "/contact_spence_sphere.toml");
  EXPECT_DOUBLE_EQ(spence.problem.contacts.front().law.friction, 0.1);
  EXPECT_EQ(spence.problem.increments, 16);
  const auto punch = io::read_contact_file(dir + "/contact_flat_punch.toml");
  EXPECT_EQ(punch.problem.contacts.front().law.kind, contact::ContactKind::bilateral);
  EXPECT_EQ(punch.problem.analysis, AnalysisType::plane_stress);
  EXPECT_TRUE(punch.problem.forces.empty());
  EXPECT_EQ(io::problem_kind(io::read_problem_text(dir + "/contact_punch_halfplane.toml")), io::ProblemKind::contact);
  EXPECT_EQ(io::problem_kind(io::read_problem_text(dir + "/plate_tension.toml")), io::ProblemKind::body);
}

TEST(ContactIo, WritersHoldEveryPairAndTheSummary) {
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_punch_halfplane.toml");
  file.problem.record_steps = true;
  file.problem.increments = 2;
  const auto result = contact::solve_contact(file.problem);
  const auto files = io::contact_output_files(file.problem, result, false);
  std::map<std::string, std::string> by_name;
  for (const auto& f : files) by_name[f.name] = f.text();
  ASSERT_TRUE(by_name.count("contact.csv"));
  ASSERT_TRUE(by_name.count("steps/contact_step2.csv"));  // per-step files in the sub-folder steps/
  ASSERT_TRUE(by_name.count("steps/punch_boundary_step2.csv"));
  for (const auto& [name, content] : by_name)
    EXPECT_TRUE(name.find("_step") == std::string::npos || name.find("_steps.csv") != std::string::npos ||
                name.rfind("steps/", 0) == 0)
        << name;
  ASSERT_TRUE(by_name.count("punch_boundary.csv"));
  ASSERT_TRUE(by_name.count("support_boundary.csv"));
  const std::string& csv = by_name["contact.csv"];
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "pair,x,y,coordinate,nx,ny,gap,p_n,p_t,slip_ratio,jump_n,jump_t,status");
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), result.pairs.size() + 1);
  EXPECT_FALSE(by_name.count("summary.json"));  // the caller's (io/run_summary.hpp)
  io::RunSummary blocks;
  io::fill_contact_summary(blocks, file.problem, result);
  const auto summary = io::summary_json(blocks);
  EXPECT_EQ(summary.at("kind"), "contact");
  EXPECT_EQ(summary.at("options").at("law").at("kind"), contact::to_string(file.problem.contacts.front().law.kind));
  EXPECT_EQ(summary.at("mesh").at("regions").size(), 2u);
  EXPECT_TRUE(summary.at("reactions").contains("punch"));
  const auto& c = summary.at("results").at("contact");
  EXPECT_DOUBLE_EQ(c.at("a").get<double>(), result.summary.contact_radius);
  EXPECT_DOUBLE_EQ(c.at("approach").get<double>(), result.summary.approach);
  EXPECT_EQ(c.at("steps").size(), 2u);
  EXPECT_EQ(c.at("algorithm").get<std::string>(), "newton");
  EXPECT_TRUE(c.at("timings").contains("phases"));
}

// motions.csv's columns name the body and the direction: a named load by its name, a
// load without one by its boundary and component (r, z in axisymmetry), a moment as
// _moment and _rotation; characters outside letters and digits become '_', and a name met
// twice gets a suffix.
TEST(ContactIo, MotionColumnsNameTheBodyAndTheDirection) {
  const std::string dir = BEMCONTACT_EXAMPLES_DIR;
  const contact::ContactResult none;
  const auto fretting = io::read_contact_file(dir + "/fretting_cylinder.toml");
  EXPECT_EQ(io::motion_columns(fretting.problem, none),
            (std::vector<std::string>{"cylinder_P_force", "cylinder_P_displacement", "cylinder_Q_force",
                                      "cylinder_Q_displacement"}));
  const auto ball = io::read_contact_file(dir + "/contact_hertz_sphere.toml");
  EXPECT_EQ(io::motion_columns(ball.problem, none),
            (std::vector<std::string>{"ball_top_z_force", "ball_top_z_displacement"}));
  auto punch = io::read_contact_file(dir + "/contact_rigid_punch.toml").problem;
  ASSERT_EQ(punch.forces.size(), 1u);
  auto moment = punch.forces.front();
  moment.component = 2;
  punch.forces.push_back(moment);
  auto named = moment;
  named.named = true;
  named.name = "turn it";
  punch.forces.push_back(named);
  contact::ContactResult free;
  free.free_motions = {{punch.forces.front().body, "y"}};
  EXPECT_EQ(io::motion_columns(punch, free),
            (std::vector<std::string>{"punch_y_force", "punch_y_displacement", "punch_moment", "punch_rotation",
                                      "punch_turn_it_moment", "punch_turn_it_rotation", "punch_y_displacement_2"}));
}

}  // namespace bemcontact

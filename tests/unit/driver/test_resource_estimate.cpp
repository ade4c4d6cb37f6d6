// The estimate printed before a run: its node count is the mesher's (every element kind),
// and its time model follows the documented constants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/dd/plate_strips.hpp"
#include "bemcontact/driver/resource_check.hpp"
#include "bemcontact/driver/run.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "support/example_text.hpp"

namespace bemcontact::driver {
namespace {

ResourceLimits memory_limit(double bytes) {
  ResourceLimits limits;
  limits.max_memory_bytes = bytes;
  return limits;
}

// The message of check_resources' refusal, "" when it passes.
template <class Problem>
std::string refusal(const Problem& problem, const ResourceLimits& limits) {
  try {
    check_resources(problem, limits);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ResourceEstimate, UnknownsAreTheMeshersForEveryElementKind) {
  // cantilever.toml: four boundaries, split corners, no corner transition.
  const auto file = io::parse_problem(test_support::example_text("cantilever.toml"), "cantilever.toml");
  for (const auto interpolation : {Interpolation::linear, Interpolation::quadratic})
    for (const bool discontinuous : {false, true}) {
      auto problem = file.problem;
      problem.mesh.interpolation = interpolation;
      if (discontinuous) geometry::use_discontinuous_elements(problem.mesh);
      const auto mesh = bem::mesh_body(problem);
      ASSERT_TRUE(mesh.transitions.empty());
      const auto estimate = estimate_resources(problem);
      EXPECT_EQ(estimate.unknowns, 2 * mesh.node_count()) << to_string(interpolation) << discontinuous;
      EXPECT_DOUBLE_EQ(estimate.bytes, 32.0 * std::pow(static_cast<double>(estimate.unknowns), 2));
    }
}

TEST(ResourceEstimate, TimeGrowsWithTheCubeOfTheUnknownsAndIsDescribed) {
  auto problem = io::parse_problem(test_support::example_text("plate_tension.toml"), "plate.toml").problem;
  problem.interior_points.clear();
  for (auto& piece : problem.body.pieces) piece.elements = 2000;
  problem.operator_choice.kind = bem::OperatorKind::dense;
  const auto estimate = estimate_resources(problem);
  EXPECT_FALSE(estimate.compressed);
  const double n = static_cast<double>(estimate.unknowns);  // 16 008
  const double threads = estimate.threads;
  const double expected = (8004.0 * 8000.0 * 0.27e-6 + 2.0 / 3.0 * n * n * n / 20e9) / threads;
  EXPECT_NEAR(estimate.seconds, expected, 1e-9 * expected);
  const std::string line = describe(estimate);
  EXPECT_NE(line.find("estimate: 16008 unknowns"), std::string::npos) << line;
  EXPECT_NE(line.find("GB of memory"), std::string::npos) << line;
}

// Above the threshold a body goes to hierarchical matrices by default, and its estimate
// follows the documented law: memory 14 MB + 1 450 B per N log2 N (20 % more when point
// constraints make the H-LU factor A^T too, as the plate's does), time N log2(N)^2 times
// 1.45 us + two kernel pairs per node pair + 0.47 us per factorisation, on one thread.
TEST(ResourceEstimate, LargeBodiesAreCompressedByDefault) {
  auto problem = io::parse_problem(test_support::example_text("plate_tension.toml"), "plate.toml").problem;
  problem.interior_points.clear();
  ASSERT_FALSE(problem.body.constraints.empty());
  for (auto& piece : problem.body.pieces) piece.elements = 2000;  // 16 008 unknowns
  const auto large = estimate_resources(problem);
  EXPECT_TRUE(large.compressed);
  const double n = static_cast<double>(large.unknowns), nodes = n / 2.0, elements = 8000.0;
  EXPECT_NEAR(large.bytes, 14e6 + 1.2 * 1450.0 * n * std::log2(n), 1e-9 * large.bytes);
  const double per_unit = 1.45e-6 + 2.0 * 0.27e-6 * elements / nodes + 2.0 * 0.47e-6;
  EXPECT_NEAR(large.seconds, n * std::log2(n) * std::log2(n) * per_unit, 1e-9 * large.seconds);
  EXPECT_NE(describe(large).find("(compressed)"), std::string::npos) << describe(large);
  // hmat-oss runs on one thread: the time does not divide by the threads.
  const int threads = omp_get_max_threads();
  omp_set_num_threads(threads == 1 ? 2 : 1);
  const double other_threads = estimate_resources(problem).seconds;
  omp_set_num_threads(threads);
  EXPECT_DOUBLE_EQ(other_threads, large.seconds);
  // Without point constraints, A alone is factored.
  auto held = problem;
  held.body.constraints.clear();
  const auto alone = estimate_resources(held);
  EXPECT_NEAR(alone.bytes, 14e6 + 1450.0 * n * std::log2(n), 1e-9 * alone.bytes);
  EXPECT_NEAR(large.seconds - alone.seconds, n * std::log2(n) * std::log2(n) * 0.47e-6, 1e-9 * large.seconds);
  for (auto& piece : problem.body.pieces) piece.elements = 500;  // 4 008: under the threshold
  EXPECT_FALSE(estimate_resources(problem).compressed);
  // An axisymmetric section of the same size is compressed too, and takes longer: its ring
  // kernels cost 1.6 us a pair against 0.27 us.
  for (auto& piece : problem.body.pieces) piece.elements = 2000;
  problem.analysis = AnalysisType::axisymmetric;
  const auto axisymmetric = estimate_resources(problem);
  EXPECT_TRUE(axisymmetric.compressed);
  EXPECT_NEAR(axisymmetric.seconds - large.seconds,
              n * std::log2(n) * std::log2(n) * 2.0 * (1.6e-6 - 0.27e-6) * elements / nodes, 1e-9 * large.seconds);
}

// A decomposition's subdomains (and a contact model's regions) decide as one body does: a
// large plane subdomain is estimated compressed (n log n, not 32 n^2) under "auto", so the
// memory check does not refuse what the run would compress; forced dense, the refusal names
// the compressed operator.
TEST(ResourceEstimate, LargeSubdomainsAreCompressedAndTheRefusalNamesTheOption) {
  auto problem = dd::plate_strips({2, 6});
  for (auto& subdomain : problem.subdomains)
    for (auto& piece : subdomain.body.pieces) piece.elements = 2500;  // 20 008 unknowns each
  const auto estimate = estimate_resources(problem);
  EXPECT_TRUE(estimate.compressed);
  // Two bodies held and one at its peak, each with its compressed operators and its
  // interface map (2 x 2 501 data); the interface's right-hand sides are applied through
  // the blocks, not held.
  const double n = static_cast<double>(estimate.unknowns), k = 2.0 * 2501.0;
  EXPECT_NEAR(estimate.bytes, 3.0 * (14e6 + 1450.0 * n * std::log2(n) + 8.0 * (2.0 * k * k)),
              1e-6 * estimate.bytes);
  const ResourceLimits limits = memory_limit(8e9);
  EXPECT_EQ(refusal(problem, limits), "");
  problem.operator_choice.kind = bem::OperatorKind::dense;
  const auto dense = estimate_resources(problem);
  EXPECT_FALSE(dense.compressed);
  EXPECT_TRUE(dense.could_compress);
  const std::string message = refusal(problem, limits);  // 20 000 dense unknowns twice in 8 GB
  EXPECT_NE(message.find("operator = \"compressed\""), std::string::npos) << message;
}

// A rigid cylinder pressed on a block (contact_compliant_cylinder.toml, unilateral) with n
// elements on its contact zone, the block's other boundaries as the example has them.
contact::ContactProblem rigid_cylinder(int n) {
  std::string text = test_support::example_text("contact_compliant_cylinder.toml");
  for (const char* key : {"kind = \"compliant\"\n", "normal_stiffness = \"cn\"\n", "normal_exponent = \"m\"\n"})
    text = test_support::replaced(text, key, "");
  return io::parse_contact_problem(text, "cylinder.toml", {{"n", static_cast<double>(n)}}).problem;
}

// A contact run's estimate holds its condensed operator, on the route the model takes: the
// formed M (2n x 2n) and the block's responses to the pairs, or the matrix-free route's
// coarse images and batches; a zone too fine for the formed operator is refused with the
// matrix-free route named, and passes on it.
TEST(ResourceEstimate, ContactOperatorIsCountedOnTheRouteTheModelTakes) {
  const auto small = rigid_cylinder(40);
  const auto formed = estimate_resources(small);
  EXPECT_EQ(formed.contact_pairs, 41);
  EXPECT_FALSE(formed.contact_matrix_free);
  const double pairs = 41.0;
  EXPECT_DOUBLE_EQ(formed.contact_bytes, 2.0 * 8.0 * (2.0 * pairs) * (2.0 * pairs));
  const contact::ContactModel model(small);
  EXPECT_EQ(model.condensed().matrix_free, nullptr);
  EXPECT_EQ(model.condensed().M.rows(), 2 * 41);
  EXPECT_GE(formed.contact_bytes, 8.0 * static_cast<double>(model.condensed().M.size()));
  EXPECT_NE(describe(formed).find("the contacts' 41 pairs on the formed operator included"), std::string::npos)
      << describe(formed);
  // Asked matrix-free, the model and the estimate agree.
  auto asked = small;
  asked.solver.contact_operator = contact::CondensedOperatorKind::matrix_free;
  EXPECT_TRUE(estimate_resources(asked).contact_matrix_free);
  EXPECT_NE(contact::ContactModel(asked).condensed().matrix_free, nullptr);

  // 16 001 pairs on the compressed block: matrix-free by default (about 0.5 GB, measured
  // 0.3 GB above the block's), formed 8 GB for M and the responses.
  auto large = rigid_cylinder(16000);
  const auto automatic = estimate_resources(large);
  EXPECT_TRUE(automatic.compressed);
  EXPECT_TRUE(automatic.contact_matrix_free);
  EXPECT_LT(automatic.contact_bytes, 0.6e9);
  const ResourceLimits limits = memory_limit(4e9);
  EXPECT_EQ(refusal(large, limits), "");
  large.solver.contact_operator = contact::CondensedOperatorKind::dense;
  const auto dense = estimate_resources(large);
  EXPECT_FALSE(dense.contact_matrix_free);
  EXPECT_GT(dense.contact_bytes, 8e9);
  const std::string message = refusal(large, limits);
  EXPECT_EQ(message.rfind("cylinder.toml:", 0), 0u) << message;  // at the contact zone's boundary
  EXPECT_NE(message.find("key 'body[1].boundary[4]'"), std::string::npos) << message;  // "contact"
  EXPECT_NE(message.find("the contacts' condensed operator (16001 pairs, formed)"), std::string::npos) << message;
  EXPECT_NE(message.find("contact_operator = \"matrix_free\""), std::string::npos) << message;
}

// Recording every load step keeps every step's pairs and boundary fields and writes them:
// the estimate covers the files written, and a history too long for the memory limit is
// refused before solving, at the record_steps key.
TEST(ResourceEstimate, RecordedStepsAreCountedAndWrittenIntoSteps) {
  const std::string text = test_support::replaced(test_support::example_text("contact_punch_halfplane.toml"),
                                                  "kind = \"unilateral\"",
                                                  "kind = \"unilateral\"\nincrements = 3\nrecord_steps = true");
  RunOptions options;
  const RunOutput output = run_problem(text, "punch.toml", options);
  double step_files = 0.0;
  for (const auto& file : output.files.files())
    if (file.name.rfind("steps/", 0) == 0) step_files += static_cast<double>(file.content.size());
  EXPECT_GT(step_files, 0.0);
  const double estimated = output.estimate.at("recorded_steps_bytes").get<double>();
  EXPECT_GE(estimated, step_files);        // the text of the files, at least
  EXPECT_LT(estimated, 3.0 * step_files);  // and of their order
  const std::string long_history = test_support::replaced(text, "increments = 3", "increments = 20000");
  options.limits.max_memory_bytes = 1e9;
  try {
    run_problem(long_history, "punch.toml", options);
    ADD_FAILURE() << "20 000 recorded steps fit in 1 GB?";
  } catch (const InputError& e) {
    const std::string message = e.what();
    const auto at = long_history.find("record_steps");
    const int line = 1 + static_cast<int>(std::count(long_history.begin(), long_history.begin() + static_cast<long>(at), '\n'));
    EXPECT_EQ(message.rfind("punch.toml:" + std::to_string(line) + ": key 'contact.record_steps'", 0), 0u) << message;
    EXPECT_NE(message.find("for up to 20001 steps"), std::string::npos) << message;
    EXPECT_NE(message.find("over the limit of 1 GB"), std::string::npos) << message;
    EXPECT_NE(message.find("--max-memory"), std::string::npos) << message;
  }
  // Meshing records nothing: the same file meshes.
  EXPECT_NO_THROW(mesh_problem(long_history, "punch.toml", options));
}

// An elastoplastic region's cells are made after meshing: the estimate does not claim
// them (it said "under a second" for a Brinell cycle of 100 s), it says so, and the summary
// counts the regions it leaves out.
TEST(ResourceEstimate, SaysTheCellsOfElastoplasticRegionsAreNotIncluded) {
  std::string ball = test_support::replaced(test_support::example_text("brinell.toml"), "cell = 0.16", "cell = 0.64");
  ball = test_support::replaced(test_support::replaced(ball, "end_time = 2.0", "end_time = 1.0"), "increments = 20",
                                "increments = 2");
  std::string notice;
  RunOptions options;
  options.notice = [&](const std::string& text) { notice += text; };
  const RunOutput output = run_problem(ball, "ball.toml", options);
  EXPECT_EQ(output.estimate.at("elastoplastic_regions_not_included").get<int>(), 1);
  EXPECT_NE(notice.find("the cells of the elastoplastic region not included"), std::string::npos) << notice;
  notice.clear();
  run_problem(test_support::example_text("contact_punch_halfplane.toml"), "punch.toml", options);
  EXPECT_EQ(notice.find("elastoplastic"), std::string::npos) << notice;
}

}  // namespace
}  // namespace bemcontact::driver

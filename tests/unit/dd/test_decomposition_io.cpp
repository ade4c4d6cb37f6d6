// Multi-subdomain problem files and the writers of a decomposed run.
#include <gtest/gtest.h>

#include "bemcontact/io/input/problem_text.hpp"
#include "bemcontact/io/file_names.hpp"

#include <filesystem>

#include "bemcontact/dd/plate_strips.hpp"
#include "bemcontact/dd/solver.hpp"
#include "bemcontact/io/input/decomposition_file.hpp"
#include "bemcontact/io/output/decomposition_writer.hpp"

namespace bemcontact::io {
namespace {

const std::string examples = BEMCONTACT_SOURCE_DIR "/examples/";

TEST(DdFile, RecognisesDecompositionFiles) {
  const auto kind = [](const std::string& file) { return problem_kind(read_problem_text(examples + file)); };
  EXPECT_EQ(kind("dd_strips_2.toml"), ProblemKind::decomposition);
  EXPECT_EQ(kind("dd_two_layer_ring.toml"), ProblemKind::decomposition);
  EXPECT_EQ(kind("plate_tension.toml"), ProblemKind::body);
  EXPECT_EQ(problem_kind("this is = = not toml"), ProblemKind::body);  // the one-body reader reports it
}

TEST(DdFile, StripsFileIsTheProblemBuiltInCode) {
  const auto file = read_decomposition_file(examples + "dd_strips_3.toml");
  const auto built = dd::plate_strips({3, 6});
  ASSERT_EQ(file.problem.subdomains.size(), 3u);
  EXPECT_EQ(file.problem.analysis, AnalysisType::plane_stress);
  EXPECT_EQ(file.problem.options.method, dd::InterfaceMethod::mixed);
  EXPECT_EQ(file.problem.options.restart, 20);
  EXPECT_EQ(file.problem.options.tolerance, 1e-8);
  EXPECT_EQ(file.problem.options.displacement_nodes, 3);
  const auto meshes_file = dd::mesh_subdomains(file.problem);
  const auto meshes_code = dd::mesh_subdomains(built);
  for (std::size_t s = 0; s < 3; ++s) {
    EXPECT_EQ(file.problem.subdomains[s].body.name, built.subdomains[s].body.name);
    EXPECT_EQ(file.problem.subdomains[s].piece_interface, built.subdomains[s].piece_interface);
    ASSERT_EQ(meshes_file[s].node_count(), meshes_code[s].node_count());
    for (Index i = 0; i < meshes_file[s].node_count(); ++i)
      EXPECT_LT((meshes_file[s].nodes[i].position - meshes_code[s].nodes[i].position).norm(), 1e-14);
  }
  // Interface pieces carry the interface signature (so the mesher splits their ends).
  EXPECT_EQ(file.problem.subdomains[1].body.pieces[0].condition_signature, "interface:y1");
  EXPECT_EQ(file.problem.subdomains[0].body.constraints.size(), 1u);
}

TEST(DdFile, ReadsSubdomainInteriorPoints) {
  const auto file = read_decomposition_file(examples + "dd_two_layer_ring.toml");
  ASSERT_EQ(file.problem.subdomains.size(), 2u);
  EXPECT_EQ(file.problem.subdomains[1].interior_points.size(), 2u);
  EXPECT_EQ(file.problem.subdomains[0].body.material.young_modulus, 200000.0);
  EXPECT_EQ(file.problem.subdomains[1].body.material.poisson_ratio, 0.33);
}

TEST(DdWriter, FilesHoldOneRowPerPairNodeAndIteration) {
  const auto problem = dd::plate_strips({2, 6});
  const auto result = dd::solve_decomposition(problem);
  const auto files = decomposition_files(result, "strips", true);
  std::vector<std::string> names;
  for (const auto& f : files) names.push_back(f.name);
  const std::vector<std::string> expected{"strip1_boundary.csv", "strip1_boundary.vtk", "strip2_boundary.csv",
                                          "strip2_boundary.vtk", "interface.csv",       "interface.vtk",
                                          "gmres.csv"};
  EXPECT_EQ(names, expected);
  const auto lines = [](const std::string& text) { return std::count(text.begin(), text.end(), '\n'); };
  EXPECT_EQ(lines(interface_csv(result)), 1 + 13);
  EXPECT_EQ(lines(gmres_history_csv(result.gmres)), 1 + static_cast<long>(result.gmres.residual_history.size()));
  EXPECT_NE(interface_vtk(result, "t").find("POINTS 13 double"), std::string::npos);
  // The jumps written are those of the solution (u_a - u_b and t_a + t_b, ~ tolerance).
  const std::string csv = interface_csv(result);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "interface,pair,kind,x,y,subdomain_a,node_a,subdomain_b,node_b,u1_a,u2_a,u1_b,u2_b,t1_a,t2_a,t1_b,t2_b,"
            "jump_u1,jump_u2,jump_t1,jump_t2");
  const auto json = decomposition_summary_json(problem, result);
  EXPECT_EQ(json["method"], "mixed");
  EXPECT_EQ(json["gmres"]["status"], "converged");
  EXPECT_EQ(json["interfaces"][0]["pairs"], 13);
  EXPECT_EQ(json["subdomains"].size(), 2u);
  EXPECT_TRUE(json["timings"].contains("phases"));
  EXPECT_EQ(file_stem("a b/c-d_e"), "a_b_c-d_e");
}

}  // namespace
}  // namespace bemcontact::io

namespace bemcontact::io {
namespace {

TEST(DdFile, EveryBundledDecompositionExampleSolves) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples)) {
    const std::string stem = entry.path().stem().string();
    if (entry.path().extension() != ".toml" || stem.rfind("dd_", 0) != 0) continue;
    ++count;
    const auto file = read_decomposition_file(entry.path());
    const auto result = dd::solve_decomposition(file.problem);
    EXPECT_TRUE(result.converged()) << entry.path() << ": " << result.gmres.message;
    for (const auto& jump : result.jumps) {
      EXPECT_LT(jump.jump_u, 1e-6) << entry.path() << " " << jump.name;
      EXPECT_LT(jump.jump_p, 1e-6) << entry.path() << " " << jump.name;
    }
  }
  EXPECT_GE(count, 4);
}

}  // namespace
}  // namespace bemcontact::io

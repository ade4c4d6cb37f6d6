// Decomposition of the plate in tension into strips (section IV.5): the exact field is
// linear, which linear elements reproduce to round-off on each subdomain, so every error
// left is the interface solve's: it must reach the GMRES tolerance (1e-10 here; the
// operator is well scaled, so errors of 1e-8 relative to the data and below are expected).
#include <gtest/gtest.h>

#include "bemcontact/dd/monolithic.hpp"
#include "bemcontact/dd/plate_strips.hpp"
#include "bemcontact/dd/solver.hpp"
#include "bemcontact/reference/uniaxial_tension.hpp"

namespace bemcontact::dd {
namespace {

struct Errors {
  double u = 0.0, p = 0.0;
};

// Max nodal error over every subdomain's boundary, relative to max |u| and to P.
Errors errors_against_exact(const DecompositionProblem& problem, const std::vector<geometry::BoundaryMesh>& meshes,
                            const std::vector<bem::BoundarySolution>& solutions) {
  const reference::PlateInTension exact{1.0, problem.subdomains[0].body.material, problem.analysis};
  Errors e;
  double u_scale = 0.0;
  for (std::size_t s = 0; s < meshes.size(); ++s)
    for (Index i = 0; i < meshes[s].node_count(); ++i) {
      const auto& node = meshes[s].nodes[i];
      u_scale = std::max(u_scale, exact.displacement(node.position).norm());
      e.u = std::max(e.u, (solutions[s].displacement[i] - exact.displacement(node.position)).norm());
      e.p = std::max(e.p, (solutions[s].traction[i] - exact.stress(node.position).traction(node.normal)).norm());
    }
  e.u /= u_scale;
  return e;
}

TEST(DdStrips, EveryMethodThatIsWellPosedReachesTheExactLinearField) {
  for (const auto method : {InterfaceMethod::conforming, InterfaceMethod::mixed}) {
    for (const int strips : {2, 3, 4}) {
      auto problem = plate_strips({strips, 6, 1.0, {100000.0, 0.1}, AnalysisType::plane_stress, method});
      problem.options.tolerance = 1e-10;
      problem.options.restart = 40;
      const auto result = solve_decomposition(problem);
      ASSERT_TRUE(result.converged()) << result.gmres.message;
      std::vector<geometry::BoundaryMesh> meshes;
      std::vector<bem::BoundarySolution> solutions;
      for (const auto& sub : result.subdomains) {
        meshes.push_back(sub.mesh);
        solutions.push_back(sub.boundary);
      }
      const Errors e = errors_against_exact(problem, meshes, solutions);
      EXPECT_LT(e.u, 1e-8) << to_string(method) << " " << strips;
      EXPECT_LT(e.p, 1e-8) << to_string(method) << " " << strips;
      for (const auto& jump : result.jumps) {
        EXPECT_LT(jump.jump_u, 1e-8) << jump.name;
        EXPECT_LT(jump.jump_p, 1e-8) << jump.name;
      }
      std::printf("%s strips=%d unknowns=%ld iterations=%d err_u=%.2e err_p=%.2e\n", to_string(method), strips,
                  static_cast<long>(result.interface_unknowns), result.gmres.iterations, e.u, e.p);
    }
  }
}

TEST(DdStrips, MonolithicMultiRegionSystemAgreesWithTheIterativeSolve) {
  auto problem = plate_strips({3, 6, 1.0, {100000.0, 0.1}, AnalysisType::plane_stress, InterfaceMethod::mixed});
  problem.options.tolerance = 1e-12;
  problem.options.restart = 60;
  const auto result = solve_decomposition(problem);
  ASSERT_TRUE(result.converged()) << result.gmres.message;
  std::vector<geometry::BoundaryMesh> meshes;
  for (const auto& sub : result.subdomains) meshes.push_back(sub.mesh);
  const auto mono = solve_monolithic(problem, meshes, result.connectivity);
  const Errors e = errors_against_exact(problem, meshes, mono.boundary);
  EXPECT_LT(e.u, 1e-9);
  EXPECT_LT(e.p, 1e-9);
}

TEST(DdStrips, HybridMethodRefusesFloatingStrips) {
  auto problem = plate_strips({2, 6, 1.0, {100000.0, 0.1}, AnalysisType::plane_stress, InterfaceMethod::hybrid});
  try {
    solve_decomposition(problem);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& error) {
    EXPECT_NE(std::string(error.what()).find("strip2"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace bemcontact::dd

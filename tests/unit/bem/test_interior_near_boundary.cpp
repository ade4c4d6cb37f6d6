// Interior stresses close to the boundary: the near-boundary treatment keeps the error at
// the level of the boundary stress, down to points a 1e-6 element length away.
#include <gtest/gtest.h>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/reference/lame.hpp"

using namespace bemcontact;

TEST(BemInteriorPoints, StressStaysAccurateApproachingTheBoundary) {
  auto file = io::read_problem_file(std::string(BEMCONTACT_SOURCE_DIR) + "/examples/thick_ring_plane_strain.toml");
  auto problem = file.problem;
  const double a = file.parameters.at("a"), b = file.parameters.at("b"), p = file.parameters.at("p");
  const reference::ThickCylinder exact{a, b, p, 0.0, problem.body.material, reference::CylinderEnds::plane_strain};
  // Along the ray at 30 degrees (between nodes), from mid-wall to the inner surface.
  const double h = a * (3.14159265358979 / 2) / 32;  // inner element length
  const Vec2 dir(std::cos(0.5236), std::sin(0.5236));
  problem.interior_points.clear();
  for (double d : {0.5 * (b - a), 2.0 * h, 0.5 * h, 0.1 * h, 1e-2 * h, 1e-4 * h, 1e-6 * h})
    problem.interior_points.push_back({(a + d) * dir, false});
  const auto result = bem::solve_body(problem);
  ASSERT_EQ(result.interior.points.size(), problem.interior_points.size());
  for (std::size_t k = 0; k < result.interior.points.size(); ++k) {
    const Vec2& x = result.interior.points[k];
    const auto s = exact.stress(x);
    const auto& c = result.interior.stress[k];
    // The boundary stress itself is within ~0.3 % of p on this mesh (validate case).
    const double error = std::max({std::abs(c.s11 - s.s11), std::abs(c.s22 - s.s22), std::abs(c.s12 - s.s12)});
    EXPECT_LT(error, 0.01 * p) << "distance " << x.norm() - a;
    EXPECT_LT((result.interior.displacement[k] - exact.displacement(x)).norm(),
              0.01 * exact.radial_displacement(a))
        << "distance " << x.norm() - a;
  }
}

// The numerics of `bemcontact probe` (bem/probe.hpp) on their own: principal stresses, the
// stress in a line's frame, the chord bulge of arcs and the linearisation of a section.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/probe.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "support/example_text.hpp"

namespace bemcontact::bem {
namespace {

TEST(ProbeNumerics, PrincipalStressesAreTheEigenvaluesLargestFirst) {
  const StressTensor s{1.0, -2.0, 0.7, 0.3};
  Eigen::Matrix3d sigma;
  sigma << s.s11, s.s12, 0.0, s.s12, s.s22, 0.0, 0.0, 0.0, s.s33;
  const Eigen::Vector3d eigen = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(sigma).eigenvalues();
  const auto p = s.principal();
  EXPECT_NEAR(p[0], eigen[2], 1e-14);
  EXPECT_NEAR(p[1], eigen[1], 1e-14);
  EXPECT_NEAR(p[2], eigen[0], 1e-14);
}

TEST(ProbeNumerics, StressInALinesFrame) {
  const StressTensor s{1.0, -2.0, 0.7, 0.3};
  const auto x = stress_in_frame(s, Vec2(1.0, 0.0));
  EXPECT_EQ(x.s11, 1.0);
  EXPECT_EQ(x.s22, -2.0);
  EXPECT_EQ(x.s12, 0.7);
  const auto y = stress_in_frame(s, Vec2(0.0, 1.0));  // along y, across -x
  EXPECT_NEAR(y.s11, -2.0, 1e-15);
  EXPECT_NEAR(y.s22, 1.0, 1e-15);
  EXPECT_NEAR(y.s12, -0.7, 1e-15);
  const auto d = stress_in_frame(s, Vec2(0.6, 0.8));
  EXPECT_NEAR(d.s11 + d.s22, s.s11 + s.s22, 1e-14);
  EXPECT_NEAR(d.von_mises(), s.von_mises(), 1e-14);
  EXPECT_EQ(d.s33, 0.3);
}

// Straight elements on an arc: the outer circle bulges beyond its chords by the sagitta
// R - sqrt(R^2 - L^2/4); a hole's arc lies inside the body's polygon (0), as lines do.
TEST(ProbeNumerics, ChordBulgesAreTheSagittasOfOutwardArcs) {
  const auto file = io::parse_problem(test_support::example_text("thick_ring_plane_strain.toml"), "ring.toml");
  const auto mesh = mesh_body(file.problem);
  const auto bulges = chord_bulges(mesh, file.problem.body.pieces);
  ASSERT_EQ(bulges.size(), mesh.elements.size());
  for (std::size_t k = 0; k < bulges.size(); ++k) {
    const auto& e = mesh.elements[k];
    const std::string& name = file.problem.body.pieces[e.piece].name;
    const double expected = name == "outer" ? 2.0 - std::sqrt(4.0 - 0.25 * e.length * e.length) : 0.0;
    EXPECT_NEAR(bulges[k], expected, 1e-15) << name << k;
  }
}

// The symmetry lines of a half or quarter model carry no elements and lie inside the whole
// body: points on them are inside (the winding number alone is ambiguous there), as points
// on the axis of an axisymmetric body always were.
TEST(ProbeNumerics, PointsOnSymmetryLinesAreInside) {
  const std::string quarter =
      "analysis = \"plane_stress\"\n[material]\nE = 1000.0\nnu = 0.25\n"
      "[[boundary]]\nfrom = [1.0, 0.0]\nto = [4.0, 0.0]\nsymmetry = true\n"
      "[[boundary]]\nfrom = [4.0, 0.0]\nto = [4.0, 4.0]\nelements = 5\n"
      "[[boundary]]\nfrom = [4.0, 4.0]\nto = [0.0, 4.0]\nelements = 5\nt2 = 1.0\n"
      "[[boundary]]\nfrom = [0.0, 4.0]\nto = [0.0, 1.0]\nsymmetry = true\n"
      "[[boundary]]\nshape = \"arc\"\nfrom = [0.0, 1.0]\nto = [1.0, 0.0]\ncenter = [0.0, 0.0]\ndirection = \"cw\"\n"
      "elements = 4\n";
  const auto mesh = mesh_body(io::parse_problem(quarter, "quarter.toml").problem);
  for (const Vec2& on_line : {Vec2(2.0, 0.0), Vec2(3.999, 0.0), Vec2(0.0, 2.5), Vec2(0.0, 1.2)})
    EXPECT_TRUE(point_inside(mesh, on_line, 1e-9)) << on_line.transpose();
  for (const Vec2& off : {Vec2(-0.5, 2.0), Vec2(2.0, -0.1), Vec2(0.0, 0.5), Vec2(5.0, 0.0)})
    EXPECT_FALSE(point_inside(mesh, off, 1e-9)) << off.transpose();
}

std::vector<double> uniform(int n, double t) {
  std::vector<double> s;
  for (int k = 0; k < n; ++k) s.push_back(t * k / (n - 1));
  return s;
}

// A linear sigma = alpha + beta s: membrane alpha + beta t/2, bending -beta t/2 (at the
// start); a quadratic s^2: t^2/3 and -t^2/2. Simpson's rules are exact for both, on odd
// and even counts; the linear interpolant (uneven samples) for the linear one; pieces on
// either side of an interface each exactly.
TEST(ProbeNumerics, LinearisationOfKnownProfiles) {
  const double t = 3.0;
  const auto profile = [](const std::vector<double>& s, auto f) {
    std::vector<StressTensor> out;
    for (const double x : s) out.push_back({f(x), 0.0, 0.0, 0.0});
    return out;
  };
  const auto linear = [](double x) { return 2.0 - 0.5 * x; };
  const auto quadratic = [](double x) { return x * x; };
  for (const int n : {2, 3, 4, 5, 8}) {
    const auto s = uniform(n, t);
    const auto l = linearised_stress(s, profile(s, linear));
    EXPECT_NEAR(l.membrane.s11, 2.0 - 0.25 * t, 1e-14) << n;
    EXPECT_NEAR(l.bending.s11, 0.25 * t, 1e-14) << n;
    if (n < 3) continue;
    const auto q = linearised_stress(s, profile(s, quadratic));
    EXPECT_NEAR(q.membrane.s11, t * t / 3.0, 1e-13) << n;
    EXPECT_NEAR(q.bending.s11, -t * t / 2.0, 1e-13) << n;
  }
  const std::vector<double> uneven{0.0, 0.4, 1.5, 2.0, 3.0};
  const auto l = linearised_stress(uneven, profile(uneven, linear));
  EXPECT_NEAR(l.membrane.s11, 2.0 - 0.25 * t, 1e-14);
  EXPECT_NEAR(l.bending.s11, 0.25 * t, 1e-14);
  // sigma = 1 on [0, 1], 4 on [1, 3] (an interface at s = 1, both sides' values there).
  const std::vector<double> split{0.0, 0.5, 1.0, 1.0, 2.0, 3.0};
  const std::vector<StressTensor> steps{{1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}, {4, 0, 0, 0}, {4, 0, 0, 0}, {4, 0, 0, 0}};
  const auto p = linearised_stress(split, steps);
  EXPECT_NEAR(p.membrane.s11, 3.0, 1e-14);  // (1 + 8) / 3
  // 6/t^2 (int_0^1 (1.5 - s) ds + 4 int_1^3 (1.5 - s) ds) = 6/9 (1 - 4) = -2
  EXPECT_NEAR(p.bending.s11, -2.0, 1e-14);
}

}  // namespace
}  // namespace bemcontact::bem

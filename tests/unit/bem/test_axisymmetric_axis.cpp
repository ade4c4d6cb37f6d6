// Axisymmetric solutions near the axis on a curved boundary: a sphere (radius 1, fine
// elements near the pole, coarse ones elsewhere) under the tractions of the exact uniform
// radial expansion u = s (r, 0). The coarse elements leave an O(h^2) discretization error
// everywhere; it must stay a smooth field near the axis (u_r error ~ r), not be divided by
// r_i into the diagonal blocks (an error that grew like 1/h at the first node, 15 % at 60
// elements, before the radial expansion's traction was taken on the straight elements).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/io/input/problem_file.hpp"

namespace bemcontact::bem {
namespace {

const std::string sphere = R"toml(analysis = "axisymmetric"
[parameters]
R = 1.0
rc = 0.1
theta = "asin(rc/R)"
E = 432000.0
nu = 0.32
s = 1e-3
mu = "E / (2 * (1 + nu))"
lam = "2 * mu * nu / (1 - 2 * nu)"
ne = 60
[material]
E = "E"
nu = "nu"
[vertices]
S = [0.0, 0.0]
Q = ["rc", "R - R*cos(theta)"]
N = [0.0, "2*R"]
[[boundary]]
name = "cap"
shape = "arc"
from = "S"
to = "Q"
center = [0.0, "R"]
elements = "ne"
t1 = "2 * (lam + mu) * s * r / R"
t2 = "2 * lam * s * (z - R) / R"
[[boundary]]
name = "rest"
shape = "arc"
from = "Q"
to = "N"
center = [0.0, "R"]
direction = "ccw"
elements = 40
grading = 8.0
refine = "start"
t1 = "2 * (lam + mu) * s * r / R"
t2 = "2 * lam * s * (z - R) / R"
[[boundary]]
name = "axis"
from = "N"
to = "S"
[[constraint]]
at = "N"
u2 = 0.0
)toml";

TEST(AxisymmetricAxis, RadialExpansionStaysSmoothAtThePole) {
  for (const double elements : {30.0, 120.0}) {
    const auto file = io::parse_problem(sphere, "sphere.toml", {{"ne", elements}});
    const auto result = solve_body(file.problem);
    const double s = file.parameters.at("s");
    // Nodes 1..3 of the cap, next to the pole (node 0, on the axis).
    for (Index i = 1; i <= 3; ++i) {
      const double r = result.mesh.nodes[i].position.x();
      ASSERT_GT(r, 0.0);
      EXPECT_LT(std::abs(result.boundary.displacement[i].x() - s * r), 0.01 * s * r)
          << "node " << i << " at r = " << r << " with " << elements << " cap elements";
    }
    // The pole's vertical displacement joins its neighbours' (no jump at the axis).
    const double jump = std::abs(result.boundary.displacement[1].y() - result.boundary.displacement[0].y());
    EXPECT_LT(jump, 1e-4 * s) << elements;
  }
}

}  // namespace
}  // namespace bemcontact::bem

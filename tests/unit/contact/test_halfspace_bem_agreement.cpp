// The BEM bodies against the independent half-space model in the half-space setting: two
// flat-topped cylinders (radius and height 8, 40 contact elements over r < 0.1) with
// Hertz's gap r^2 / 2R imposed on the pairs, pressed by P = 31.5 with beta = 0.1, give the
// stick ratio of the half-space model on the same nodes. This separates the BEM's
// flexibility (kernels, axis, finite bodies) from the ball's curvature, which moves c/a by
// O(a/R) in the thesis' geometry (docs/contact.md).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bemcontact/contact/condensed.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/halfspace_model.hpp"
#include "bemcontact/io/input/contact_file.hpp"

namespace bemcontact::contact {
namespace {

const std::string flat_on_flat = R"toml(analysis = "axisymmetric"
[parameters]
L = 8.0
rc = 0.1
E_ball = 432000.0
P = 31.5
ne = 60
[[body]]
name = "ball"
[body.material]
E = "E_ball"
nu = 0.32
[body.vertices]
F = [0.0, 0.0]
D = ["rc", 0.0]
C = ["L", 0.0]
B = ["L", "L"]
A = [0.0, "L"]
[[body.boundary]]
name = "contact"
from = "F"
to = "D"
elements = "ne"
[[body.boundary]]
name = "free"
from = "D"
to = "C"
elements = 16
grading = 60.0
refine = "start"
[[body.boundary]]
name = "side"
from = "C"
to = "B"
elements = 6
[[body.boundary]]
name = "top"
from = "B"
to = "A"
elements = 6
[[body.boundary]]
name = "axis"
from = "A"
to = "F"
[[body]]
name = "support"
[body.material]
E = 72000.0
nu = 0.32
[body.vertices]
A = [0.0, "-L"]
B = ["L", "-L"]
C = ["L", 0.0]
D = ["rc", 0.0]
F = [0.0, 0.0]
[[body.boundary]]
name = "base"
from = "A"
to = "B"
elements = 6
u1 = 0.0
u2 = 0.0
[[body.boundary]]
name = "side"
from = "B"
to = "C"
elements = 6
[[body.boundary]]
name = "top"
from = "C"
to = "D"
elements = 16
grading = 60.0
refine = "end"
[[body.boundary]]
name = "contact"
from = "D"
to = "F"
elements = "ne"
[[body.boundary]]
name = "axis"
from = "F"
to = "A"
[contact]
boundary1 = "contact"
boundary2 = "contact"
kind = "unilateral"
normal = "body2"
friction = 0.1
increments = 16
[contact.load]
body = "ball"
boundary = "top"
component = 2
force = "-P"
)toml";

double stick_ratio(const LoadHistory& history) { return history.summary.stick_ratio(); }

TEST(HalfSpaceModel, FlatBemBodiesWithHertzGapMatchTheHalfSpaceModel) {
  const double R = 1.0;
  const auto file = io::parse_contact_problem(flat_on_flat, "flat_on_flat.toml", {{"ne", 40.0}});
  const ContactModel bem(file.problem);
  auto condensed = bem.condensed();
  std::vector<double> radii;
  for (Index i = 0; i < condensed.pairs; ++i) {
    const double r = bem.pairs()[i].position2.x();
    condensed.gap[i] = r * r / (2.0 * R);
    radii.push_back(r);
  }
  const HalfSpaceSphereContact spec{file.problem.elastic(0).material, file.problem.elastic(1).material, R, 31.5, radii,
                                    true};
  const auto halfspace = halfspace_sphere_model(spec);
  for (const bool coupling : {true, false}) {
    auto bem_condensed = condensed;
    auto halfspace_condensed = halfspace.condensed;
    if (!coupling) {
      drop_tangential_coupling(bem_condensed);
      drop_tangential_coupling(halfspace_condensed);
    }
    const auto from_bem = solve_load_history(bem_condensed, bem.pairs(), file.problem);
    const auto from_halfspace = solve_load_history(halfspace_condensed, halfspace.pairs, file.problem);
    // Within a fifth of the pair spacing (0.0025 / 0.07 = 0.036 in c/a).
    EXPECT_NEAR(stick_ratio(from_bem), stick_ratio(from_halfspace), 0.007) << "coupling " << coupling;
    EXPECT_NEAR(from_bem.summary.contact_radius, from_halfspace.summary.contact_radius,
                0.005 * from_halfspace.summary.contact_radius);
  }
}

}  // namespace
}  // namespace bemcontact::contact

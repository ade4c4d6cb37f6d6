// Bodies held only by their contacts: the rigid motion reported for each (motions.csv) is
// the one nearest to the body's boundary displacement, in radians for a rotation, named by
// body and direction; checked against a rigid field (exact), the mirror symmetry of the
// roller between two plates, and the corners of a stiff block tilted by an eccentric load.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/free_motions.hpp"
#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/output/contact_writer.hpp"
#include "support/example_text.hpp"

namespace bemcontact::contact {
namespace {

// The displacement of the rigid motion (tx, ty, theta about `centre`) at every node.
std::vector<Vec2> rigid_field(const geometry::BoundaryMesh& mesh, const Vec2& centre, double tx, double ty,
                              double theta) {
  std::vector<Vec2> u;
  for (const auto& node : mesh.nodes) {
    const Vec2 r = node.position - centre;
    u.emplace_back(tx - theta * r.y(), ty + theta * r.x());
  }
  return u;
}

geometry::BoundaryMesh square_mesh() {
  std::vector<geometry::BoundaryPiece> pieces;
  const std::vector<Vec2> corners{{0.0, 0.0}, {3.0, 0.0}, {3.0, 2.0}, {0.0, 2.0}};
  for (std::size_t k = 0; k < corners.size(); ++k)
    pieces.push_back(geometry::line_piece("side" + std::to_string(k), corners[k], corners[(k + 1) % 4], 5));
  return geometry::mesh_boundary(pieces, {});
}

TEST(FreeMotions, ARigidFieldIsReportedExactly) {
  const auto mesh = square_mesh();
  FreeBody body;
  body.centre = {1.2, 0.7};  // any point: the rotation is about it
  body.scale = 3.0;
  body.free = Matrix::Identity(3, 3);
  body.reported = {0, 1, 2};
  const auto u = rigid_field(mesh, body.centre, 1e-3, -2e-3, 5e-4);
  const Vector v = rigid_motion(body, {&mesh}, {&u}, AnalysisType::plane_strain);
  ASSERT_EQ(v.size(), 3);
  EXPECT_NEAR(v[0], 1e-3, 1e-15);
  EXPECT_NEAR(v[1], -2e-3, 1e-15);
  EXPECT_NEAR(v[2], 5e-4, 1e-15);  // radians, whatever the scale
  // Held in x at (3, 2): free in y and in the rotation about that point (with its x part).
  const double ry = (2.0 - body.centre.y()) / body.scale;
  body.free = Matrix::Zero(3, 2);
  body.free(1, 0) = 1.0;
  body.free.col(1) << ry, 0.0, 1.0;
  body.free.col(1).normalize();
  body.reported = {1, 2};
  const double theta = -4e-4;
  const auto turned = rigid_field(mesh, body.centre, theta * (2.0 - body.centre.y()), 3e-3, theta);
  const Vector w = rigid_motion(body, {&mesh}, {&turned}, AnalysisType::plane_strain);
  ASSERT_EQ(w.size(), 2);
  EXPECT_NEAR(w[0], 3e-3, 1e-15);
  EXPECT_NEAR(w[1], theta, 1e-15);
}

// The roller between two plates is the mirror image of itself about its centre line
// y = R (bottom plate clamped at its base, top plate's platen moved by delta, both held in
// x): the roller moves by delta / 2, where the node it is pinned at does not (the roller
// is squeezed: the pin's own displacement is about 10 % smaller).
TEST(FreeMotions, TheRollerMovesByHalfThePlatensApproach) {
  const auto file = io::parse_contact_problem(test_support::example_text("contact_roller_plates.toml"), "roller.toml");
  const auto result = solve_contact(file.problem);
  ASSERT_EQ(result.free_motions.size(), 1u);
  EXPECT_EQ(file.problem.bodies[result.free_motions[0].body].name, "roller");
  EXPECT_EQ(result.free_motions[0].direction, "y");
  const auto& motions = result.records.back().motions;
  ASSERT_EQ(motions.size(), 2);
  EXPECT_LT(motions[0], 0.0);
  EXPECT_NEAR(motions[1], 0.5 * motions[0], 1e-9 * std::abs(motions[0]));
  EXPECT_EQ(io::motion_columns(file.problem, result),
            (std::vector<std::string>{"top_plate_top_y_force", "top_plate_top_y_displacement", "roller_y_displacement"}));
}

// A stiff block on a soft one, pressed by a traction that grows with x and held in x at one
// point of its top: free in y and in the rotation, which the contact holds. Being nearly
// rigid, two nodes of its top give the motion: the rotation (u2 right - u2 left) / distance,
// the centre's translation their mean (the nodes lie symmetric about x = 0).
TEST(FreeMotions, ATiltedBlockReportsItsRotationInRadians) {
  const std::string text = R"toml(analysis = "plane_strain"
[[body]]
name = "support"
[body.material]
E = 1.0
nu = 0.3
[body.vertices]
A = [-20.0, -20.0]
B = [20.0, -20.0]
C = [20.0, 0.0]
D = [1.0, 0.0]
E = [-1.0, 0.0]
F = [-20.0, 0.0]
[[body.boundary]]
name = "base"
from = "A"
to = "B"
elements = 10
u1 = 0.0
u2 = 0.0
[[body.boundary]]
name = "right"
from = "B"
to = "C"
elements = 8
[[body.boundary]]
name = "top right"
from = "C"
to = "D"
elements = 16
grading = 40.0
refine = "end"
[[body.boundary]]
name = "contact"
from = "D"
to = "E"
elements = 16
[[body.boundary]]
name = "top left"
from = "E"
to = "F"
elements = 16
grading = 40.0
refine = "start"
[[body.boundary]]
name = "left"
from = "F"
to = "A"
elements = 8
[[body]]
name = "tilted block"
[body.material]
E = 1.0e5
nu = 0.3
[body.vertices]
P = [-1.0, 0.0]
Q = [1.0, 0.0]
R = [1.0, 1.0]
S = [-1.0, 1.0]
[[body.boundary]]
name = "bottom"
from = "P"
to = "Q"
elements = 16
[[body.boundary]]
name = "right"
from = "Q"
to = "R"
elements = 6
[[body.boundary]]
name = "top"
from = "R"
to = "S"
elements = 8
t2 = "-0.01 * (1 + 0.5 * x)"
[[body.boundary]]
name = "left"
from = "S"
to = "P"
elements = 6
[[body.constraint]]
at = [0.5, 1.0]
u1 = 0.0
[[contact]]
body1 = "tilted block"
boundary1 = "bottom"
body2 = "support"
boundary2 = "contact"
normal = "body2"
)toml";
  const auto file = io::parse_contact_problem(text, "tilted.toml");
  const auto result = solve_contact(file.problem);
  ASSERT_EQ(result.free_motions.size(), 2u);
  EXPECT_EQ(result.free_motions[0].direction, "y");
  EXPECT_EQ(result.free_motions[1].direction, "rotation");
  EXPECT_EQ(io::motion_columns(file.problem, result),
            (std::vector<std::string>{"tilted_block_y_displacement", "tilted_block_rotation"}));
  // The block's top at x = +-0.75.
  int block = -1;
  for (std::size_t r = 0; r < result.body_names.size(); ++r)
    if (result.body_names[r] == "tilted block") block = static_cast<int>(r);
  ASSERT_GE(block, 0);
  const auto& mesh = result.meshes[block];
  const auto& u = result.boundary[block].displacement;
  const Index right = geometry::find_node_at(mesh, {0.75, 1.0}, 1e-9), left = geometry::find_node_at(mesh, {-0.75, 1.0}, 1e-9);
  ASSERT_GE(right, 0);
  ASSERT_GE(left, 0);
  const double rotation = (u[right].y() - u[left].y()) / 1.5;
  const auto& motions = result.records.back().motions;
  ASSERT_EQ(motions.size(), 2);
  EXPECT_LT(motions[1], 0.0);  // more load on the right: clockwise
  EXPECT_NEAR(motions[1], rotation, 1e-4 * std::abs(rotation));
  EXPECT_NEAR(motions[0], 0.5 * (u[right].y() + u[left].y()), 1e-4 * std::abs(motions[0]));
}

}  // namespace
}  // namespace bemcontact::contact

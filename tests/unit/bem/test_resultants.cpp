// Boundary resultants against closed forms: uniform and linearly varying tractions on a
// plane square (forces and moments), a uniform axial traction on an axisymmetric disc end
// (P pi R^2), pieces of one name adding up, and quadratic elements on an arc.
#include <gtest/gtest.h>

#include <numbers>

#include "bemcontact/bem/resultants.hpp"

using namespace bemcontact;
using namespace bemcontact::bem;

namespace {

geometry::BoundaryPiece side(const std::string& name, Vec2 a, Vec2 b, int elements) {
  geometry::BoundaryPiece p = geometry::line_piece(name, a, b, elements);
  p.condition_signature = name;
  return p;
}

BodyDefinition body_of(const std::vector<geometry::BoundaryPiece>& pieces) {
  BodyDefinition body;
  body.pieces = pieces;
  body.conditions.resize(pieces.size());
  return body;
}

// Nodal tractions of the stress field sigma(x) (a function of position).
template <class Stress>
BoundarySolution tractions_of(const geometry::BoundaryMesh& mesh, Stress sigma) {
  BoundarySolution s;
  for (const auto& node : mesh.nodes) {
    s.displacement.emplace_back(0.0, 0.0);
    s.traction.push_back(sigma(node.position) * node.normal);
  }
  return s;
}

}  // namespace

TEST(BemResultants, LinearStressOnASquareGivesExactForcesAndMoments) {
  // Square [0, 2] x [0, 1], bending-like field s11 = y, everything else 0: the right side
  // x = 2 carries t = (y, 0): F = (1/2, 0), M about the origin = -int y * y dy = -1/3.
  const std::vector<geometry::BoundaryPiece> pieces{side("bottom", {0, 0}, {2, 0}, 4), side("right", {2, 0}, {2, 1}, 3),
                                                    side("top", {2, 1}, {0, 1}, 4), side("left", {0, 1}, {0, 0}, 3)};
  auto body = body_of(pieces);
  body.conditions[3].kind = {ConditionKind::displacement, ConditionKind::traction};
  for (Interpolation order : {Interpolation::linear, Interpolation::quadratic}) {
    geometry::MeshOptions options;
    options.interpolation = order;
    const auto mesh = geometry::mesh_boundary(pieces, options);
    const auto solution = tractions_of(mesh, [](const Vec2& x) {
      Mat2 s;
      s << x.y(), 0.0, 0.0, 0.0;
      return s;
    });
    const auto r = boundary_resultants(mesh, solution, body, AnalysisType::plane_strain);
    ASSERT_EQ(r.size(), 4u);
    EXPECT_EQ(r[1].boundary, "right");
    EXPECT_NEAR(r[1].force.x(), 0.5, 1e-14);
    EXPECT_NEAR(r[1].force.y(), 0.0, 1e-14);
    EXPECT_NEAR(r[1].moment, -1.0 / 3.0, 1e-14);
    // The left side x = 0 carries t = (-y, 0): balances the right side's force; its moment
    // about the origin is +1/3. Only it prescribes a displacement.
    EXPECT_NEAR(r[3].force.x(), -0.5, 1e-14);
    EXPECT_NEAR(r[3].moment, 1.0 / 3.0, 1e-14);
    EXPECT_TRUE(r[3].prescribed_displacement);
    EXPECT_FALSE(r[1].prescribed_displacement);
    EXPECT_NEAR(r[0].force.norm() + r[2].force.norm(), 0.0, 1e-14);  // t = 0 on y = const
  }
}

TEST(BemResultants, AxialTractionOnADiscEndIsPTimesTheArea) {
  // Meridian of a solid cylinder r <= 2, 0 <= z <= 3; uniform s_zz = 5: the top carries
  // F_z = 5 pi 4, the bottom -5 pi 4; the radial component is 0 by symmetry.
  const std::vector<geometry::BoundaryPiece> pieces{side("bottom", {0, 0}, {2, 0}, 5), side("side", {2, 0}, {2, 3}, 4),
                                                    side("top", {2, 3}, {0, 3}, 5), side("axis", {0, 3}, {0, 0}, 1)};
  geometry::MeshOptions options;
  options.skip_axis_pieces = true;
  const auto mesh = geometry::mesh_boundary(pieces, options);
  const auto solution = tractions_of(mesh, [](const Vec2&) {
    Mat2 s;
    s << 0.0, 0.0, 0.0, 5.0;
    return s;
  });
  const auto r = boundary_resultants(mesh, solution, body_of(pieces), AnalysisType::axisymmetric);
  ASSERT_EQ(r.size(), 3u);  // the axis carries no elements
  EXPECT_NEAR(r[2].force.y(), 20.0 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(r[0].force.y(), -20.0 * std::numbers::pi, 1e-12);
  EXPECT_EQ(r[0].force.x(), 0.0);
  EXPECT_EQ(r[0].moment, 0.0);
}

TEST(BemResultants, PiecesOfOneNameAddUpAndArcsIntegrateTheirNormal) {
  // Quarter disc of radius 1 under the pressure 2 on its arc, cut in two pieces named
  // "rim": the arc's force is -2 * (chord vector rotated) = (-2, -2) (the pressure pushes
  // inward), whatever the cut.
  const double c = std::sqrt(0.5);
  geometry::BoundaryPiece rim1 = side("rim", {1, 0}, {c, c}, 3), rim2 = side("rim", {c, c}, {0, 1}, 5);
  for (auto* p : {&rim1, &rim2}) {
    p->shape = geometry::PieceShape::arc;
    p->center = Vec2::Zero();
  }
  const std::vector<geometry::BoundaryPiece> pieces{side("x", {0, 0}, {1, 0}, 2), rim1, rim2, side("y", {0, 1}, {0, 0}, 2)};
  geometry::MeshOptions options;
  options.interpolation = Interpolation::quadratic;
  const auto mesh = geometry::mesh_boundary(pieces, options);
  const auto solution = tractions_of(mesh, [](const Vec2&) { return Mat2(-2.0 * Mat2::Identity()); });
  const auto r = boundary_resultants(mesh, solution, body_of(pieces), AnalysisType::plane_stress);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[1].boundary, "rim");
  // Quadratic interpolation of n(s) on 8 elements of a quarter circle: O(h^3) ~ 1e-4.
  EXPECT_NEAR(r[1].force.x(), -2.0, 2e-4);
  EXPECT_NEAR(r[1].force.y(), -2.0, 2e-4);
}

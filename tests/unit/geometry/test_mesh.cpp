// Boundary mesher: contours, grading, split corners, geometry errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bemcontact/geometry/mesh.hpp"

using namespace bemcontact;
using namespace bemcontact::geometry;

namespace {

BoundaryPiece line(const std::string& name, Vec2 a, Vec2 b, int elements,
                   const std::string& signature = "free") {
  BoundaryPiece piece;
  piece.name = name;
  piece.start = a;
  piece.end = b;
  piece.elements = elements;
  piece.condition_signature = signature;
  return piece;
}

BoundaryPiece arc(const std::string& name, Vec2 a, Vec2 b, Vec2 c, bool ccw, int elements) {
  BoundaryPiece piece = line(name, a, b, elements);
  piece.shape = PieceShape::arc;
  piece.center = c;
  piece.counterclockwise = ccw;
  return piece;
}

std::vector<BoundaryPiece> unit_square(int per_side) {
  return {line("bottom", {0, 0}, {1, 0}, per_side), line("right", {1, 0}, {1, 1}, per_side),
          line("top", {1, 1}, {0, 1}, per_side), line("left", {0, 1}, {0, 0}, per_side)};
}

}  // namespace

TEST(GeometryMesh, SquareLinearSplitsEveryCorner) {
  const auto mesh = mesh_boundary(unit_square(3), {});
  ASSERT_EQ(mesh.element_count(), 12);
  // Each side: 3 elements, 4 nodes of which the 2 end ones are shifted corner nodes.
  EXPECT_EQ(mesh.node_count(), 16);
  int shifted = 0;
  for (const auto& node : mesh.nodes) shifted += node.shifted;
  EXPECT_EQ(shifted, 8);
  const auto& first = mesh.elements.front();
  EXPECT_NEAR(first.node_fraction[0], 0.2, 1e-15);
  EXPECT_NEAR(mesh.nodes[first.nodes[0]].position.x(), 0.2 / 3.0, 1e-15);
  // Outward normals of the bottom side point down.
  EXPECT_NEAR(first.normal.y(), -1.0, 1e-15);
  // Shape functions interpolate at the nodes and sum to one.
  for (const auto& e : mesh.elements) {
    EXPECT_NEAR(e.shape(0, e.node_fraction[0]), 1.0, 1e-15);
    EXPECT_NEAR(e.shape(1, e.node_fraction[0]), 0.0, 1e-15);
    EXPECT_NEAR(e.shape(0, 0.37) + e.shape(1, 0.37), 1.0, 1e-15);
  }
}

TEST(GeometryMesh, CollinearPiecesWithEqualConditionsShareTheNode) {
  std::vector<BoundaryPiece> pieces = {
      line("b1", {0, 0}, {0.5, 0}, 2), line("b2", {0.5, 0}, {1, 0}, 2),
      line("right", {1, 0}, {1, 1}, 2), line("top", {1, 1}, {0, 1}, 2),
      line("left", {0, 1}, {0, 0}, 2)};
  auto mesh = mesh_boundary(pieces, {});
  const Index v = find_vertex_at(mesh, {0.5, 0}, 1e-12);
  ASSERT_GE(v, 0);
  EXPECT_FALSE(mesh.vertices[v].split);
  EXPECT_GE(find_node_at(mesh, {0.5, 0}, 1e-12), 0);
  pieces[1].condition_signature = "global:u2=0";
  mesh = mesh_boundary(pieces, {});
  EXPECT_TRUE(mesh.vertices[find_vertex_at(mesh, {0.5, 0}, 1e-12)].split);
  EXPECT_LT(find_node_at(mesh, {0.5, 0}, 1e-12), 0);
}

TEST(GeometryMesh, GradingGivesTheRatioTowardTheChosenEnd) {
  auto piece = line("graded", {0, 0}, {1, 0}, 5);
  piece.grading = 16.0;
  auto s = element_breakpoints(piece);
  EXPECT_NEAR((s[5] - s[4]) / (s[1] - s[0]), 16.0, 1e-12);
  piece.refine_toward = RefineToward::end;
  s = element_breakpoints(piece);
  EXPECT_NEAR((s[1] - s[0]) / (s[5] - s[4]), 16.0, 1e-12);
}

TEST(GeometryMesh, QuarterPlateWithHoleNodesLieOnTheArc) {
  const double a = 1.0;
  std::vector<BoundaryPiece> pieces = {
      line("AB", {a, 0}, {4, 0}, 4), line("BC", {4, 0}, {4, 4}, 4), line("CD", {4, 4}, {0, 4}, 4),
      line("DE", {0, 4}, {0, a}, 4), arc("EA", {0, a}, {a, 0}, {0, 0}, false, 9)};
  const auto mesh = mesh_boundary(pieces, {});
  for (Index node : mesh.piece_nodes[4]) {
    const auto& n = mesh.nodes[node];
    if (n.shifted) continue;
    EXPECT_NEAR(n.position.norm(), a, 1e-14);
    // Outward normal of the body points into the hole, toward the centre.
    EXPECT_NEAR(n.normal.dot(n.position.normalized()), -1.0, 1e-14);
  }
  EXPECT_EQ(mesh.contours.size(), 1u);
}

TEST(GeometryMesh, ConstantElementsHaveMidpointNodes) {
  geometry::MeshOptions options;
  options.interpolation = Interpolation::constant;
  const auto mesh = mesh_boundary(unit_square(2), options);
  ASSERT_EQ(mesh.node_count(), 8);
  EXPECT_NEAR(mesh.nodes[0].position.x(), 0.25, 1e-15);
}

TEST(GeometryMesh, HoleMustRunClockwise) {
  auto pieces = unit_square(2);
  const double r = 0.2;
  pieces.push_back(arc("hole1", {0.5 + r, 0.5}, {0.5 - r, 0.5}, {0.5, 0.5}, true, 4));
  pieces.push_back(arc("hole2", {0.5 - r, 0.5}, {0.5 + r, 0.5}, {0.5, 0.5}, true, 4));
  try {
    mesh_boundary(pieces, {});
    FAIL() << "expected a GeometryError";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("clockwise"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("hole1"), std::string::npos) << e.what();
  }
  pieces[4].counterclockwise = pieces[5].counterclockwise = false;
  std::swap(pieces[4].start, pieces[4].end);
  std::swap(pieces[5].start, pieces[5].end);
  EXPECT_NO_THROW(mesh_boundary(pieces, {}));
}

TEST(GeometryMesh, OpenContourIsRejectedNamingTheBoundary) {
  auto pieces = unit_square(2);
  pieces[2].end = Vec2(0.1, 1.0);
  try {
    mesh_boundary(pieces, {});
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("open contour"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("top"), std::string::npos) << e.what();
  }
}

TEST(GeometryMesh, CrossingBoundariesAreRejected) {
  // A bow tie: two triangles meeting in a crossing.
  std::vector<BoundaryPiece> pieces = {line("a", {0, 0}, {1, 1}, 2), line("b", {1, 1}, {1, 0}, 2),
                                       line("c", {1, 0}, {0, 1}, 2), line("d", {0, 1}, {0, 0}, 2)};
  EXPECT_THROW(mesh_boundary(pieces, {}), GeometryError);
}

TEST(GeometryMesh, ZeroLengthAndBadArcAreRejected) {
  auto pieces = unit_square(1);
  pieces.insert(pieces.begin() + 1, line("dot", {1, 0}, {1, 0}, 1));
  EXPECT_THROW(mesh_boundary(pieces, {}), GeometryError);
  auto bad = unit_square(1);
  bad[1] = arc("bulge", {1, 0}, {1, 1}, {0.5, 0.1}, true, 3);  // end off the circle
  EXPECT_THROW(mesh_boundary(bad, {}), GeometryError);
}

TEST(GeometryMesh, AxisPiecesCarryNoElements) {
  MeshOptions options;
  options.skip_axis_pieces = true;
  const auto mesh = mesh_boundary(unit_square(2), options);
  EXPECT_EQ(mesh.element_count(), 6);
  // The two nodes on the axis are ordinary (unshifted) end nodes.
  EXPECT_GE(find_node_at(mesh, {0, 0}, 1e-12), 0);
  EXPECT_GE(find_node_at(mesh, {0, 1}, 1e-12), 0);
}

namespace {

std::string geometry_error(const std::vector<BoundaryPiece>& pieces) {
  try {
    build_contours(pieces);
  } catch (const GeometryError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace

TEST(GeometryChecks, BoundariesThatMeetAtElementEndsAreRefused) {
  // An hourglass whose two lobes touch at (1, 1), an element end of both diagonals.
  const std::vector<BoundaryPiece> pieces{line("bottom", {0, 0}, {2, 0}, 2), line("rise", {2, 0}, {0, 2}, 2),
                                          line("top", {0, 2}, {2, 2}, 2), line("fall", {2, 2}, {0, 0}, 2)};
  const std::string message = geometry_error(pieces);
  EXPECT_NE(message.find("'rise' and 'fall'"), std::string::npos) << message;
  EXPECT_NE(message.find("(1, 1)"), std::string::npos) << message;
}

TEST(GeometryChecks, AHoleOutsideTheBodyIsRefused) {
  auto pieces = unit_square(2);
  // A small clockwise square to the right of the body.
  pieces.push_back(line("h1", {3, 0.2}, {3, 0.8}, 1));
  pieces.push_back(line("h2", {3, 0.8}, {3.5, 0.8}, 1));
  pieces.push_back(line("h3", {3.5, 0.8}, {3.5, 0.2}, 1));
  pieces.push_back(line("h4", {3.5, 0.2}, {3, 0.2}, 1));
  const std::string message = geometry_error(pieces);
  EXPECT_NE(message.find("lies outside the outer contour"), std::string::npos) << message;
  EXPECT_NE(message.find("'h1'"), std::string::npos) << message;
}

TEST(GeometryChecks, ManyVerticalEdgesAreCheckedInLinearTime) {
  // A tall thin strip of 400 000 elements, all edges vertical but the ends: the old sweep
  // over x was quadratic here. Must finish well within the test's time.
  const std::vector<BoundaryPiece> pieces{line("bottom", {0, 0}, {1e-3, 0}, 1), line("right", {1e-3, 0}, {1e-3, 1}, 200000),
                                          line("top", {1e-3, 1}, {0, 1}, 1), line("left", {0, 1}, {0, 0}, 200000)};
  EXPECT_EQ(geometry_error(pieces), "no error");
}

TEST(GeometryChecks, WarningsNameAWideArcAndATinyBoundary) {
  // A quarter disc whose arc was given the wrong direction: a 270 degree lobe.
  const std::vector<BoundaryPiece> lobe{line("x", {0, 0}, {1, 0}, 4), arc("rim", {1, 0}, {0, 1}, {0, 0}, false, 8),
                                        line("y", {0, 1}, {0, 0}, 4)};
  const auto warnings = geometry_warnings(lobe);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'rim'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("270"), std::string::npos) << warnings[0];
  EXPECT_TRUE(geometry_warnings(unit_square(2)).empty());
  auto tiny = unit_square(2);
  tiny[1] = line("right", {1, 0}, {1, 1e-4}, 1);
  tiny.insert(tiny.begin() + 2, line("step", {1, 1e-4}, {1, 1}, 1));
  const auto found = geometry_warnings(tiny);
  ASSERT_FALSE(found.empty());
  EXPECT_NE(found[0].find("'right'"), std::string::npos) << found[0];
}

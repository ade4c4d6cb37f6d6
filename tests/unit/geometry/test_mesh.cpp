// Boundary mesher: contours, grading, split corners, geometry errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "bemcontact/geometry/mesh.hpp"

using namespace bemcontact;
using namespace bemcontact::geometry;

namespace {

BoundaryPiece line(const std::string& name, Vec2 a, Vec2 b, int elements,
                   const std::string& signature = "free") {
  BoundaryPiece piece = line_piece(name, a, b, elements);
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

TEST(GeometryMesh, DiscontinuousElementsOwnTheirNodesAtTheGaussPoints) {
  for (const Interpolation interpolation : {Interpolation::linear, Interpolation::quadratic}) {
    MeshOptions options;
    options.interpolation = interpolation;
    use_discontinuous_elements(options);
    const auto mesh = mesh_boundary(unit_square(3), options);
    const int per_element = interpolation == Interpolation::quadratic ? 3 : 2;
    ASSERT_EQ(mesh.element_count(), 12);
    EXPECT_EQ(mesh.node_count(), 12 * per_element);  // no node shared
    const double gauss = interpolation == Interpolation::quadratic ? 0.5 - 0.5 * std::sqrt(0.6)
                                                                   : 0.5 - 0.5 / std::sqrt(3.0);
    for (const auto& e : mesh.elements) {
      EXPECT_NEAR(e.node_fraction[0], gauss, 1e-15);
      EXPECT_NEAR(e.node_fraction[1], 1.0 - gauss, 1e-15);
      const Vec2 expected = e.start + gauss * (e.end - e.start);
      EXPECT_NEAR((mesh.nodes[e.nodes[0]].position - expected).norm(), 0.0, 1e-15);
      EXPECT_TRUE(mesh.nodes[e.nodes[0]].shifted && mesh.nodes[e.nodes[1]].shifted);
      // Linear functions are reproduced: the shapes sum to one and interpolate x.
      double sum = 0.0, x = 0.0;
      for (int a = 0; a < e.node_count; ++a) {
        sum += e.shape(a, 0.9);
        x += e.shape(a, 0.9) * mesh.nodes[e.nodes[a]].position.x();
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      EXPECT_NEAR(x, e.point(0.9).x(), 1e-14);
    }
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

namespace {

std::vector<double> element_lengths(const std::vector<double>& s, double length) {
  std::vector<double> h;
  for (std::size_t k = 0; k + 1 < s.size(); ++k) h.push_back((s[k + 1] - s[k]) * length);
  return h;
}

}  // namespace

TEST(GeometryTransition, WithoutACapTheBreakpointsAreThePieceOwn) {
  BoundaryPiece piece = line("p", {0, 0}, {2, 0}, 5);
  piece.grading = 4.0;
  const double none = std::numeric_limits<double>::infinity();
  EXPECT_EQ(transition_breakpoints(piece, none, none, 1.2), element_breakpoints(piece));
  // A cap larger than the end element changes nothing either.
  EXPECT_EQ(transition_breakpoints(piece, 10.0, 10.0, 1.2), element_breakpoints(piece));
}

TEST(GeometryTransition, ElementsGrowFromTheCapByTheFactorUntilThePieceSize) {
  const BoundaryPiece piece = line("p", {0, 0}, {1, 0}, 4);  // elements of 0.25
  const double none = std::numeric_limits<double>::infinity();
  const auto s = transition_breakpoints(piece, 1e-3, none, 1.2);
  ASSERT_EQ(s.front(), 0.0);
  ASSERT_EQ(s.back(), 1.0);
  const auto h = element_lengths(s, 1.0);
  // The first element is about the cap (a little less: the count is rounded up), every
  // neighbour ratio at most the growth factor (and the rounding), none above the piece's.
  EXPECT_GT(h.front(), 0.8e-3);
  EXPECT_LE(h.front(), 1.2e-3);
  for (std::size_t k = 0; k + 1 < h.size(); ++k) {
    EXPECT_GT(h[k + 1], 0.0);
    EXPECT_LE(h[k + 1] / h[k], 1.2 * 1.05) << "element " << k;
  }
  for (double x : h) EXPECT_LE(x, 0.25 * (1.0 + 1e-12));
  // Geometric growth from 1e-3 to 0.25 by 1.2 takes about ln(250)/ln(1.2) = 30 elements.
  EXPECT_GE(h.size(), 25u);
  EXPECT_LE(h.size(), 40u);
}

TEST(GeometryTransition, CapsAtBothEndsOfAShortPieceMeetInTheMiddle) {
  const BoundaryPiece piece = line("p", {0, 0}, {1, 0}, 1);
  const auto s = transition_breakpoints(piece, 0.01, 0.02, 1.5);
  const auto h = element_lengths(s, 1.0);
  EXPECT_LE(h.front(), 0.0105);
  EXPECT_LE(h.back(), 0.021);
  for (std::size_t k = 0; k + 1 < h.size(); ++k) {
    const double r = std::max(h[k + 1], h[k]) / std::min(h[k + 1], h[k]);
    EXPECT_LE(r, 1.5 * 1.1) << "element " << k;
  }
}

TEST(GeometryTransition, TheCoarsePieceIsGradedTowardTheFineOneButNotAFixedPiece) {
  // Bottom side with 64 elements, the others with 1: the right and left sides get graded
  // toward the bottom corners, and then the top toward their ends, finer than its one
  // element: no neighbour ratio above 2 remains anywhere.
  auto pieces = unit_square(1);
  pieces[0].elements = 64;
  const BoundaryMesh graded = mesh_boundary(pieces, MeshOptions{});
  ASSERT_EQ(graded.transitions.size(), 3u);
  EXPECT_EQ(graded.transitions[0].name, "right");
  EXPECT_EQ(graded.transitions[1].name, "top");
  EXPECT_EQ(graded.transitions[2].name, "left");
  EXPECT_EQ(graded.transitions[0].elements_asked, 1);
  EXPECT_EQ(graded.transitions[0].elements, static_cast<int>(graded.piece_elements[1].size()));
  const auto& first_right = graded.elements[graded.piece_elements[1].front()];
  EXPECT_LE(first_right.length, 1.0 / 64.0 * (1.0 + 1e-9));
  EXPECT_TRUE(mesh_quality_warnings(graded, 2.0 * 1.05).empty());

  MeshOptions off;
  off.corner_transition = 0.0;
  const BoundaryMesh plain = mesh_boundary(pieces, off);
  EXPECT_TRUE(plain.transitions.empty());
  EXPECT_EQ(plain.element_count(), 67);
  const auto warnings = mesh_quality_warnings(plain);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("'bottom' and 'right'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("factor 64"), std::string::npos) << warnings[0];

  pieces[1].fixed_mesh = true;  // e.g. a contact zone: its nodes are paired, keep them
  const BoundaryMesh fixed = mesh_boundary(pieces, MeshOptions{});
  for (const auto& t : fixed.transitions) EXPECT_NE(t.name, "right");
  EXPECT_EQ(fixed.piece_elements[1].size(), 1u);
  // The fixed coarse side stays next to the fine bottom (and to the graded top): reported.
  const auto left = mesh_quality_warnings(fixed);
  ASSERT_FALSE(left.empty());
  EXPECT_NE(left[0].find("'bottom' and 'right'"), std::string::npos) << left[0];
  for (const auto& w : left) EXPECT_EQ(w.find("'left'"), std::string::npos) << w;
}

TEST(GeometryTransition, AStrongGradingInsideABoundaryIsReported) {
  auto pieces = unit_square(8);
  pieces[2].elements = 3;
  pieces[2].grading = 100.0;  // neighbour ratio 10
  const auto warnings = mesh_quality_warnings(mesh_boundary(pieces, MeshOptions{}));
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].find("boundary 'top'"), std::string::npos) << warnings[0];
}

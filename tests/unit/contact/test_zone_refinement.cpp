// Adaptive contact zones (contact/zone_refinement.hpp, ZoneAdaptivity): the meshes a pass
// asks for, the zone found from a pass's pairs, and whole runs from candidate surfaces
// against Hertz; bad adaptivity keys and unresolvable zones are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/zone_refinement.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/geometry/boundary.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/reference/hertz.hpp"
#include "support/contact_input.hpp"
#include "support/example_text.hpp"

namespace bemcontact {
namespace {

using test_support::example_text;
using test_support::replaced;

std::string adaptive_ball() { return example_text("contact_hertz_sphere_adaptive.toml"); }

contact::ContactProblem adaptive_problem(const std::string& text) {
  auto problem = io::parse_contact_problem(text, "ball.toml").problem;
  problem.drop_interior_points();
  return problem;
}

std::string zone_input_error(const std::string& text) { return test_support::contact_input_error(text, "ball.toml"); }

std::string zone_solver_error(const std::string& text) {
  try {
    contact::solve_contact(adaptive_problem(text));
  } catch (const SolverError& error) {
    return error.what();
  }
  return "no error";
}

bool has(const std::string& text, const std::string& part) { return test_support::mentions(text, part); }

}  // namespace

// The stretch gets elements of at most the size asked, the rest grows by at most the
// factor from it, and the fractions run from 0 to 1 increasing.
TEST(ZoneRefinement, BreakpointsAreFineOnTheStretchAndGradedAway) {
  const double length = 8.0, from = 3.0, to = 3.5, size = 0.01, growth = 1.2, coarsest = 0.5;
  const auto s = geometry::zone_breakpoints(length, from, to, size, growth, coarsest);
  ASSERT_GE(s.size(), 52u);
  EXPECT_EQ(s.front(), 0.0);
  EXPECT_EQ(s.back(), 1.0);
  for (std::size_t k = 0; k + 1 < s.size(); ++k) {
    const double h = (s[k + 1] - s[k]) * length;
    ASSERT_GT(h, 0.0) << k;
    EXPECT_LE(h, coarsest * (1.0 + 1e-12)) << k;
    const double mid = 0.5 * (s[k] + s[k + 1]) * length;
    if (mid > from && mid < to) EXPECT_LE(h, size * (1.0 + 1e-12)) << k;
    if (k + 2 < s.size()) {
      const double next = (s[k + 2] - s[k + 1]) * length;
      EXPECT_LE(std::max(h, next) / std::min(h, next), growth * (1.0 + 1e-9)) << k;
    }
  }
  // A stretch reaching within one fine element of an end takes the end in.
  const auto at_start = geometry::zone_breakpoints(1.0, 0.005, 0.2, 0.01, 1.2, 0.1);
  EXPECT_NEAR(at_start[1], 0.2 / 20.0, 1e-12);
}

TEST(ZoneRefinement, ArcLengthInvertsPointOnPiece) {
  geometry::BoundaryPiece arc;
  arc.shape = geometry::PieceShape::arc;
  arc.center = Vec2(0.0, 1.0);
  arc.start = Vec2(0.0, 0.0);
  arc.end = Vec2(1.0, 1.0);  // the lower quarter, counterclockwise
  geometry::BoundaryPiece line = geometry::line_piece("top", Vec2(8.0, 0.0), Vec2(0.0, 0.0), 4);
  for (const auto* piece : {&arc, &line})
    for (const double f : {0.0, 0.1, 0.5, 0.93, 1.0})
      EXPECT_NEAR(geometry::arc_length_at(*piece, geometry::point_on_piece(*piece, f).position),
                  f * geometry::piece_length(*piece), 1e-12);
  // Off the piece: the nearer end.
  EXPECT_NEAR(geometry::arc_length_at(arc, Vec2(-0.5, 0.2)), 0.0, 1e-12);
  EXPECT_NEAR(geometry::arc_length_at(arc, Vec2(1.0, 1.5)), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(geometry::arc_length_at(line, Vec2(9.0, 1.0)), 0.0, 1e-12);
}

// The README's ball from its coarse candidates (16 elements on the hemisphere and on the
// support's top): resolved in a few passes, each finer at the edge, and within 0.3 % of
// Hertz (the edge is located to a fraction of the 0.02 a spacing); the breakpoints
// reported are the meshes the pairs stand on.
TEST(ZoneRefinement, HertzBallFromCandidateSurfaces) {
  const auto problem = adaptive_problem(adaptive_ball());
  const auto result = contact::solve_contact(problem);
  const auto& zone = result.zone;
  ASSERT_GE(zone.passes.size(), 2u);
  for (std::size_t k = 0; k + 1 < zone.passes.size(); ++k) {
    EXPECT_FALSE(zone.passes[k].resolved);
    EXPECT_LT(zone.passes[k].pairs, zone.passes[k + 1].pairs);
  }
  const auto& last = zone.passes.back();
  EXPECT_TRUE(last.resolved);
  EXPECT_LE(last.edge_spacing, 0.02 * last.width);
  EXPECT_EQ(last.pairs, static_cast<int>(result.pairs.size()));
  EXPECT_EQ(static_cast<int>(zone.breakpoints1.size()) - 1, last.elements1);
  EXPECT_EQ(static_cast<int>(zone.breakpoints2.size()) - 1, last.elements2);
  const auto hertz = reference::hertz_point_contact(31.5, 1.0, problem.elastic(0).material,
                                                    std::numeric_limits<double>::infinity(), problem.elastic(1).material);
  EXPECT_NEAR(result.summary.contact_radius / hertz.contact_radius(), 1.0, 3e-3);
  EXPECT_NEAR(result.summary.centre_pressure / hertz.max_pressure(), 1.0, 3e-3);
  // The first pass's mesh is the declared one.
  EXPECT_EQ(zone.passes.front().elements1, 16);
}

// A declared zone stays as meshed: no passes.
TEST(ZoneRefinement, DeclaredZonesHaveNoPasses) {
  auto problem = adaptive_problem(replaced(adaptive_ball(), "contact_resolution = \"resolution\"\n", ""));
  const auto result = contact::solve_contact(problem);
  EXPECT_TRUE(result.zone.passes.empty());
  EXPECT_TRUE(result.zone.breakpoints1.empty());
}

TEST(ZoneRefinement, BadKeysAreInputErrors) {
  for (const char* value : {"0.0", "1.0", "-0.1"}) {
    const auto message =
        zone_input_error(replaced(adaptive_ball(), "contact_resolution = \"resolution\"", std::string("contact_resolution = ") + value));
    EXPECT_TRUE(has(message, "ball.toml:")) << message;
    EXPECT_TRUE(has(message, "contact_resolution")) << message;
  }
  const auto limits = zone_input_error(
      replaced(adaptive_ball(), "contact_resolution = \"resolution\"", "max_adaptive_passes = 4"));
  EXPECT_TRUE(has(limits, "max_adaptive_passes")) << limits;
  EXPECT_TRUE(has(limits, "no effect")) << limits;
  const auto bilateral = zone_input_error(replaced(adaptive_ball(), "kind = \"unilateral\"", "kind = \"bilateral\""));
  EXPECT_TRUE(has(bilateral, "contact_resolution")) << bilateral;
  EXPECT_TRUE(has(bilateral, "bilateral")) << bilateral;
}

// Not resolved within the passes or the elements allowed: exit 3 naming the contact, its
// last pass and the key to change.
TEST(ZoneRefinement, UnresolvedZonesAreSolverErrors) {
  const auto passes = zone_solver_error(
      replaced(adaptive_ball(), "contact_resolution = \"resolution\"", "contact_resolution = 0.02\nmax_adaptive_passes = 1"));
  EXPECT_TRUE(has(passes, "contact 'contact' (boundary 'surface' of body 'ball')")) << passes;
  EXPECT_TRUE(has(passes, "not resolved to contact_resolution = 0.02 in 1 adaptive passes")) << passes;
  EXPECT_TRUE(has(passes, "max_adaptive_passes")) << passes;
  const auto elements = zone_solver_error(
      replaced(adaptive_ball(), "contact_resolution = \"resolution\"", "contact_resolution = 0.001\nmax_zone_elements = 200"));
  EXPECT_TRUE(has(elements, "over max_zone_elements = 200")) << elements;
  EXPECT_TRUE(has(elements, "pass ")) << elements;
}

}  // namespace bemcontact

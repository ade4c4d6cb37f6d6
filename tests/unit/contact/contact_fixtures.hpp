#pragma once
// Contact problems built in code for the contact tests (plane cases only, so they do not
// depend on the axisymmetric integration).
#include <cmath>

#include "bemcontact/contact/pairing.hpp"

namespace bemcontact::contact::testing {

// A force load on piece `piece` of body `body`'s first region (a rigid platen), along
// `component` (0: x, 1: y), at amplitude 1.
inline ForceLoad platen_force(int body, int piece, int component, double force) {
  ForceLoad load;
  load.body = body;
  load.piece = piece;
  load.component = component;
  load.force = force;
  return load;
}

inline geometry::BoundaryPiece line(const std::string& name, Vec2 a, Vec2 b, int elements, double grading = 1.0,
                                    geometry::RefineToward toward = geometry::RefineToward::start) {
  geometry::BoundaryPiece piece = geometry::line_piece(name, a, b, elements);
  piece.grading = grading;
  piece.refine_toward = toward;
  return piece;
}

inline bem::BoundaryCondition free_condition() { return {}; }

inline bem::BoundaryCondition displacement(double u1, double u2, const std::string& signature) {
  bem::BoundaryCondition c;
  c.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
  c.value = {[u1](const Vec2&) { return u1; }, [u2](const Vec2&) { return u2; }};
  c.signature = signature;
  return c;
}

inline void add(bem::BodyDefinition& body, geometry::BoundaryPiece piece, bem::BoundaryCondition condition) {
  piece.condition_signature = condition.signature;
  body.pieces.push_back(piece);
  body.conditions.push_back(condition);
}

// Stiff flat punch [-a, a] x [0, h] on a support [-W, W] x [-H, 0] (plane strain), bottom
// of the support clamped, punch top pressed by a force (platen) or a displacement.
inline ContactProblem flat_punch(double a, double W, int contact_elements, double force, bool bilateral = false) {
  ContactProblem problem = two_body_problem(0, 3);
  problem.analysis = AnalysisType::plane_strain;
  problem.bodies[0].name = "punch";
  auto& punch = problem.elastic(0);
  punch.name = "punch";
  punch.material = {1.0e5, 0.3};
  const double h = a;
  add(punch, line("bottom", {-a, 0.0}, {a, 0.0}, contact_elements), free_condition());
  add(punch, line("right", {a, 0.0}, {a, h}, 6), free_condition());
  add(punch, line("top", {a, h}, {-a, h}, 8), displacement(0.0, 0.0, "top"));
  add(punch, line("left", {-a, h}, {-a, 0.0}, 6), free_condition());
  problem.bodies[1].name = "support";
  auto& support = problem.elastic(1);
  support.name = "support";
  support.material = {1.0, 0.3};
  const double H = W;
  add(support, line("base", {-W, -H}, {W, -H}, 10), displacement(0.0, 0.0, "clamped"));
  add(support, line("right", {W, -H}, {W, 0.0}, 10), free_condition());
  add(support, line("top right", {W, 0.0}, {a, 0.0}, 16, W / a, geometry::RefineToward::end), free_condition());
  add(support, line("contact", {a, 0.0}, {-a, 0.0}, contact_elements), free_condition());
  add(support, line("top left", {-a, 0.0}, {-W, 0.0}, 16, W / a, geometry::RefineToward::start), free_condition());
  add(support, line("left", {-W, 0.0}, {-W, -H}, 10), free_condition());
  problem.contacts.front().law.kind = bilateral ? ContactKind::bilateral : ContactKind::unilateral;
  problem.forces = {platen_force(0, 2, 1, -force)};
  return problem;
}

inline geometry::BoundaryPiece arc(const std::string& name, Vec2 a, Vec2 b, Vec2 center, int elements) {
  geometry::BoundaryPiece piece = line(name, a, b, elements);
  piece.shape = geometry::PieceShape::arc;
  piece.center = center;
  piece.counterclockwise = true;
  return piece;
}

// Cylinder of radius R (lower half disk, centre (0, R)) on a support [-W, W] x [-W, 0],
// plane strain. The contact arc spans +-theta about the bottom; the support's contact
// segment ends where the common normals through the arc ends meet it: x = 2R tan(theta/2).
inline ContactProblem cylinder_on_block(double R, double theta, int contact_elements, double force,
                                        const Material& cylinder, const Material& block, double W = 10.0) {
  ContactProblem problem = two_body_problem(0, 3);
  problem.analysis = AnalysisType::plane_strain;
  problem.bodies[0].name = "cylinder";
  auto& ball = problem.elastic(0);
  ball.name = "cylinder";
  ball.material = cylinder;
  const Vec2 c(0.0, R);
  const Vec2 left(-R * std::sin(theta), R - R * std::cos(theta)), right(R * std::sin(theta), R - R * std::cos(theta));
  add(ball, arc("contact", left, right, c, contact_elements), free_condition());
  add(ball, arc("right arc", right, {R, R}, c, 12), free_condition());
  add(ball, line("top", {R, R}, {-R, R}, 12), displacement(0.0, 0.0, "top"));
  add(ball, arc("left arc", {-R, R}, left, c, 12), free_condition());
  problem.bodies[1].name = "support";
  auto& support = problem.elastic(1);
  support.name = "support";
  support.material = block;
  const double b = 2.0 * R * std::tan(0.5 * theta);
  add(support, line("base", {-W, -W}, {W, -W}, 10), displacement(0.0, 0.0, "clamped"));
  add(support, line("right", {W, -W}, {W, 0.0}, 10), free_condition());
  add(support, line("top right", {W, 0.0}, {b, 0.0}, 16, W / b, geometry::RefineToward::end), free_condition());
  add(support, line("contact", {b, 0.0}, {-b, 0.0}, contact_elements), free_condition());
  add(support, line("top left", {-b, 0.0}, {-W, 0.0}, 16, W / b, geometry::RefineToward::start), free_condition());
  add(support, line("left", {-W, 0.0}, {-W, -W}, 10), free_condition());
  problem.contacts.front().law.kind = ContactKind::unilateral;
  problem.forces = {platen_force(0, 2, 1, -force)};
  return problem;
}

}  // namespace bemcontact::contact::testing

#pragma once
// Contact problems built in code for the contact tests (plane cases only, so they do not
// depend on the axisymmetric integration).
#include "bemcontact/contact/contact_problem.hpp"

namespace bemcontact::contact::testing {

inline geometry::BoundaryPiece line(const std::string& name, Vec2 a, Vec2 b, int elements, double grading = 1.0,
                                    geometry::RefineToward toward = geometry::RefineToward::start) {
  geometry::BoundaryPiece piece;
  piece.name = name;
  piece.start = a;
  piece.end = b;
  piece.elements = elements;
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
  ContactProblem problem;
  problem.analysis = AnalysisType::plane_strain;
  auto& punch = problem.bodies[0];
  punch.name = "punch";
  punch.material = {1.0e5, 0.3};
  const double h = a;
  add(punch, line("bottom", {-a, 0.0}, {a, 0.0}, contact_elements), free_condition());
  add(punch, line("right", {a, 0.0}, {a, h}, 6), free_condition());
  add(punch, line("top", {a, h}, {-a, h}, 8), displacement(0.0, 0.0, "top"));
  add(punch, line("left", {-a, h}, {-a, 0.0}, 6), free_condition());
  auto& support = problem.bodies[1];
  support.name = "support";
  support.material = {1.0, 0.3};
  const double H = W;
  add(support, line("base", {-W, -H}, {W, -H}, 10), displacement(0.0, 0.0, "clamped"));
  add(support, line("right", {W, -H}, {W, 0.0}, 10), free_condition());
  add(support, line("top right", {W, 0.0}, {a, 0.0}, 16, W / a, geometry::RefineToward::end), free_condition());
  add(support, line("contact", {a, 0.0}, {-a, 0.0}, contact_elements), free_condition());
  add(support, line("top left", {-a, 0.0}, {-W, 0.0}, 16, W / a, geometry::RefineToward::start), free_condition());
  add(support, line("left", {-W, 0.0}, {-W, -H}, 10), free_condition());
  problem.contact_piece = {0, 3};
  problem.kind = bilateral ? ContactKind::bilateral : ContactKind::unilateral;
  ForceLoad load;
  load.body = 0;
  load.piece = 2;
  load.component = 1;
  load.force = -force;
  problem.force = load;
  return problem;
}

}  // namespace bemcontact::contact::testing

#pragma once
// Small problems built in code for the tests (no problem file involved).
#include <functional>

#include "bemcontact/bem/problem.hpp"

namespace bemcontact::test_support {

// Short names for a component's condition kind in the tables of the tests.
inline constexpr bem::ConditionKind U = bem::ConditionKind::displacement;
inline constexpr bem::ConditionKind T = bem::ConditionKind::traction;

using VectorField = std::function<Vec2(const Vec2&)>;

// A piece with a global-frame condition: kinds per component and values from fields.
inline void add_piece(bem::ProblemDefinition& problem, const std::string& name, Vec2 a, Vec2 b, int elements,
                      std::array<bem::ConditionKind, 2> kind, VectorField displacement, VectorField traction) {
  geometry::BoundaryPiece piece;
  piece.name = name;
  piece.start = a;
  piece.end = b;
  piece.elements = elements;
  bem::BoundaryCondition bc;
  bc.kind = kind;
  for (int c = 0; c < 2; ++c) {
    if (kind[c] == bem::ConditionKind::displacement)
      bc.value[c] = [displacement, c](const Vec2& x) { return displacement(x)[c]; };
    else
      bc.value[c] = [traction, c](const Vec2& x) { return traction(x)[c]; };
  }
  bc.signature = name;  // every piece distinct: nodes split at every vertex
  piece.condition_signature = bc.signature;
  problem.body.pieces.push_back(piece);
  problem.body.conditions.push_back(bc);
}

// Point constraints that hold only the rigid motion of a body loaded in equilibrium: u = 0
// at `origin`, u2 = 0 at `corner` (on the same horizontal line).
inline void hold_rigid_motion(bem::ProblemDefinition& problem, Vec2 origin, Vec2 corner) {
  bem::PointConstraint at_origin, at_corner;
  at_origin.position = origin;
  at_origin.displacement = {0.0, 0.0};
  at_origin.label = "origin";
  at_corner.position = corner;
  at_corner.displacement[1] = 0.0;
  at_corner.label = "corner";
  problem.body.constraints = {at_origin, at_corner};
}

// Homogeneous linear elastic field: u = E0 x with constant strain, its stress and tractions.
struct LinearField {
  Mat2 gradient;  // du_i/dx_j
  Material material;
  AnalysisType type = AnalysisType::plane_strain;
  Vec2 displacement(const Vec2& x) const { return gradient * x; }
  Mat2 stress() const {
    const double mu = material.shear_modulus();
    const double nu = kernel_poisson_ratio(type, material);
    const double lambda = 2.0 * mu * nu / (1.0 - 2.0 * nu);
    const Mat2 strain = 0.5 * (gradient + gradient.transpose());
    return lambda * strain.trace() * Mat2::Identity() + 2.0 * mu * strain;
  }
};

}  // namespace bemcontact::test_support

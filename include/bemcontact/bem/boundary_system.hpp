#pragma once
// From H u = G p and the boundary conditions to the square system A y = b of (II.12),
// and back from y to nodal displacements and tractions.
//
// Each node's unknowns are written in the frame of its condition (global, or local
// normal/tangent), and each component swaps its column to the unknown side.
// Point constraints add one row (the displacement at the point, extrapolated along the
// element when the point is a split corner) and one unknown: a reaction traction added to
// the nearest node, so the system stays square.
// Nodes on the axis of an axisymmetric body have u_r = 0 and p_r = 0 by symmetry; their
// radial equation is degenerate and is replaced by p_r = 0.
#include <string>
#include <vector>

#include "bemcontact/bem/assembly.hpp"
#include "bemcontact/bem/problem.hpp"
#include "bemcontact/bem/solution.hpp"

namespace bemcontact::bem {

struct NodeCondition {
  Mat2 frame = Mat2::Identity();  // columns: the condition's axes in global components
  std::array<ConditionKind, 2> kind{ConditionKind::traction, ConditionKind::traction};
  std::array<double, 2> value{0.0, 0.0};
  bool on_axis = false;
  int load_group = 0;  // BoundaryCondition::load_group of the node's piece
};

struct ConstraintEquation {
  std::vector<std::pair<Index, double>> displacement_terms;  // (dof in node frame, coefficient)
  double value = 0.0;
  Index reaction_node = -1;
  int reaction_component = 0;  // global component of the reaction traction
  std::string label;
};

// Conditions at every node, from the conditions of the pieces. Throws InputError
// (naming the piece's key) when a prescribed value is not finite at a node.
std::vector<NodeCondition> resolve_node_conditions(const geometry::BoundaryMesh& mesh,
                                                   const BodyDefinition& body,
                                                   AnalysisType type);

// Point constraints as equations; throws InputError when a point is not on the boundary
// or contradicts a prescribed displacement.
std::vector<ConstraintEquation> resolve_point_constraints(
    const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
    const std::vector<NodeCondition>& conditions);

// A node whose data are set from outside (a contact's tractions, a bond's or a platen's
// displacements): both components of one kind, in global components.
struct VariableNode {
  Index node = -1;
  ConditionKind kind = ConditionKind::traction;  // what is prescribed at the node
};

// A body's conditions with its variable nodes' and pins' data set from outside: the nodes'
// conditions as resolve_node_conditions gives them, each variable node's replaced (both
// components of its kind, global frame; on the axis u_r = p_r = 0 kept), and the point
// constraints with the pins after the body's own (one component each, their values data).
// Error naming `owner` for a node out of range or a pin of not exactly one component.
struct VariableConditions {
  std::vector<NodeCondition> nodes;
  std::vector<ConstraintEquation> constraints;
};
VariableConditions resolve_variable_conditions(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                               AnalysisType type, const std::vector<VariableNode>& variable,
                                               std::vector<PointConstraint> pins, const std::string& owner);

struct BoundarySystem {
  Matrix A;
  Vector b;
};

// Builds A y = b. H and G are rotated in place into the nodes' condition frames.
BoundarySystem build_boundary_system(InfluenceMatrices& matrices,
                                     const std::vector<NodeCondition>& conditions,
                                     const std::vector<ConstraintEquation>& constraints);

// Nodal displacements and tractions (global components) from the solution y.
BoundarySolution recover_boundary_values(const Vector& y,
                                         const std::vector<NodeCondition>& conditions,
                                         const std::vector<ConstraintEquation>& constraints);

// || H u - G p || / || G p || with the (frame-rotated) matrices of build_boundary_system.
double boundary_equation_residual(const InfluenceMatrices& rotated,
                                  const std::vector<NodeCondition>& conditions,
                                  const BoundarySolution& solution);

}  // namespace bemcontact::bem

#pragma once
// Rigid-body modes left free by a body's displacement conditions, and the treatment of
// point constraints that only fix those modes.
//
// When the point constraints exactly remove the free rigid modes (a body loaded by
// tractions and held at a few points), the exact reactions vanish; the discrete loads,
// however, are balanced only to discretisation accuracy, and a point-force reaction would
// carry that imbalance into the traction of one node, spoiling the local stresses. The
// constraints' multipliers then act along the left null space W of the unconstrained
// system instead: they absorb exactly the imbalance (the component of the load outside
// the range of the operator) and leave every nodal traction as prescribed.
#include <functional>

#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace bemcontact::bem {

// Rigid modes (columns, one value per dof in the nodes' condition frames) that satisfy
// every prescribed displacement: translations and the rotation in plane problems, the
// axial translation in axisymmetry.
Matrix free_rigid_modes(const geometry::BoundaryMesh& mesh, const std::vector<NodeCondition>& conditions,
                        AnalysisType type);

// True when the constraints fix exactly the free rigid modes (as many equations as free
// modes, independent on them).
bool constraints_fix_only_rigid_modes(const Matrix& free_modes, const std::vector<ConstraintEquation>& constraints);

// Given the factored bordered system M (point-force reaction columns) and its solution y,
// returns the solution with the multipliers along the left null space instead
// (Sherman-Morrison-Woodbury on the K reaction columns: K transposed and K direct solves).
// `reaction_columns` are the first 2N rows of M's last K columns.
Vector rigid_mode_consistent_solution(const operators::Factorization& system, const Matrix& reaction_columns,
                                      const Vector& y);

}  // namespace bemcontact::bem

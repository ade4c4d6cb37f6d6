#pragma once
// One-body elastostatic analysis: mesh, assemble, apply conditions, solve, post-process.
#include "bemcontact/bem/postprocess.hpp"
#include "bemcontact/bem/problem.hpp"

namespace bemcontact::bem {

struct BodyResult {
  geometry::BoundaryMesh mesh;
  BoundarySolution boundary;
  InteriorSolution interior;
  SolveReport report;
  PhaseTimings timings;
};

// Mesh options of a problem, with the axis handling of axisymmetry switched on.
geometry::MeshOptions effective_mesh_options(const ProblemDefinition& problem);

// Meshes the boundary and checks the conditions against it (e.g. point constraints).
geometry::BoundaryMesh mesh_body(const ProblemDefinition& problem);

BodyResult solve_body(const ProblemDefinition& problem, const ProgressCallback& progress = {});

}  // namespace bemcontact::bem

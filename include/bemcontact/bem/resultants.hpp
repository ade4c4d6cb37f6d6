#pragma once
// Resultants of the boundary tractions, boundary by boundary: the reactions of the
// boundaries with prescribed displacements (point-constraint reactions are part of their
// node's traction), and a check of the applied loads elsewhere. Computed with the boundary
// stresses (BoundarySolution::resultants); io/ only formats them.
#include <string>
#include <vector>

#include "bemcontact/bem/problem.hpp"
#include "bemcontact/bem/solution.hpp"

namespace bemcontact::bem {


// One entry per boundary name, in order of first appearance on the mesh (pieces of one
// name add up, e.g. a contact zone cut into pairs). The conditions are looked up in
// `body` by name. Exact for the interpolated tractions (Gauss rule of 5 points per element).
std::vector<BoundaryResultant> boundary_resultants(const geometry::BoundaryMesh& mesh,
                                                   const BoundarySolution& solution,
                                                   const BodyDefinition& body, AnalysisType type);

}  // namespace bemcontact::bem

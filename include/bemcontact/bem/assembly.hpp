#pragma once
// Assembly of the influence matrices H and G of (II.11): H u = G p, with 2 x 2 blocks per
// (source node, field node) pair and unknowns ordered (node 0: 1, 2; node 1: 1, 2; ...).
#include "bemcontact/bem/progress.hpp"
#include "bemcontact/geometry/mesh.hpp"
#include "bemcontact/integration/element_influence.hpp"
#include "bemcontact/integration/axisymmetric_element.hpp"

namespace bemcontact::bem {

// Chooses the element integrator of the analysis type: analytic for plane problems
// (Annex C), Gauss with log-singularity treatment for axisymmetry (section II.4.4.1).
class ElementIntegrator {
 public:
  ElementIntegrator(AnalysisType type, const Material& material);
  AnalysisType type() const { return type_; }
  const Material& material() const { return material_; }
  integration::ElementInfluence influence(const Vec2& source,
                                          const geometry::BoundaryElement& element,
                                          int source_node) const;

 private:
  AnalysisType type_;
  Material material_;
  kernels::KelvinPlane plane_;
  integration::AxisymmetricKelvin axisymmetric_;
};

struct InfluenceMatrices {
  Matrix H;  // including the free term c (diagonal blocks)
  Matrix G;
};

// Full H and G of one body. Diagonal blocks of H (free term + principal value) come from
// exact elastic fields: rigid translations in plane problems (section I.4.2, remark);
// axial translation and the uniform radial expansion u_r = r in axisymmetry.
InfluenceMatrices assemble_influence_matrices(const geometry::BoundaryMesh& mesh,
                                              const ElementIntegrator& integrator,
                                              const ProgressCallback& progress = {});

// Nodes on the axis r = 0 (axisymmetry only).
bool node_on_axis(const geometry::BoundaryMesh& mesh, Index node);

}  // namespace bemcontact::bem

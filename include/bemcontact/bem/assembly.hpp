#pragma once
#include <array>
#include <vector>
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

// With symmetry lines (geometry/symmetry.hpp) the assembled H folds each image k onto the
// element's own nodes (H'_k S_k). The diagonal blocks need the rigid translations of the
// whole symmetric body, which move image k by t, not S_k t: its sums over the nodes differ by
//   X_i = sum_k B_k,i (I - S_k),   B_k,i = sum_j H'_k,ij = -int over image k's symmetry segments of T(x_i, y),
// since image k's elements and segments close its boundary and x_i lies outside it (the
// rigid-body identity, section I.4.2). Returns X (2N x 2), zero without images.
Matrix image_translation_sums(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator);

// Nodes on the axis r = 0 (axisymmetry only).
bool node_on_axis(const geometry::BoundaryMesh& mesh, Index node);

// The traction of the uniform radial expansion u_r = r, u_z = 0 (axisymmetry) at each node
// of an element: sigma n_e on a straight element (constant); on a curved one it follows the
// normal through its nodal values.
std::array<Vec2, geometry::kMaxElementNodes> radial_expansion_traction(const Material& material,
                                                                        const geometry::BoundaryElement& element);

// The diagonal blocks H_ii (free term + principal value) from exact elastic fields, given
//   translation_sums (2N x 2): sum over j != i of H_ij, i.e. H' times the rigid translations;
//   radial_residual (2N, axisymmetry only): int U p - H' u for the radial expansion, its
//   traction taken element by element (radial_expansion_traction).
// Plane: rigid translations give no traction, H_ii = -sum_{j != i} H_ij (section I.4.2,
// remark). Axisymmetry: the axial translation (its only rigid mode, section II.3.3) gives the
// z column, the radial expansion the r column: H_ii[:, r] r_i = (int U p - H' u)_i.
std::vector<Mat2> diagonal_blocks_from_exact_fields(const geometry::BoundaryMesh& mesh, AnalysisType type,
                                                    const Matrix& translation_sums, const Vector& radial_residual);

}  // namespace bemcontact::bem

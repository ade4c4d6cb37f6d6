#pragma once
// Post-processing of a solved body: stress tensor at boundary nodes (section I.6),
// displacements and stresses at interior points (I.11, I.14), von Mises (section II.6).
#include <functional>
#include <vector>

#include "bemcontact/bem/assembly.hpp"
#include "bemcontact/bem/problem.hpp"
#include "bemcontact/bem/progress.hpp"
#include "bemcontact/bem/solution.hpp"
#include "bemcontact/plasticity/j2_material.hpp"

namespace bemcontact::bem {

// Stress at each boundary node from its traction (sigma n = p) and the tangential strain
// of the interpolated displacement, with Hooke's law written in the local frame (n, s):
//   sigma_ss = (nu' sigma_nn + 2 mu eps_ss) / (1 - nu')   (plane; nu' = kernel Poisson ratio)
// and in axisymmetry with the hoop strain u_r / r as well. With `plastic_strain` (per node:
// an elastoplastic region's cells), Hooke's law acts on eps - eps_p.
std::vector<StressTensor> boundary_stresses(const geometry::BoundaryMesh& mesh, AnalysisType type,
                                            const Material& material,
                                            const BoundarySolution& solution,
                                            const std::vector<plasticity::Mandel>* plastic_strain = nullptr);

// Winding-number test against the element polygon. Points closer to the boundary than
// `tolerance` count as outside (they are boundary points).
bool point_inside(const geometry::BoundaryMesh& mesh, const Vec2& point, double tolerance);

// Distance from a point to the element polygon, the closest element and the fraction
// along it.
struct BoundaryProjection {
  double distance = 0.0;
  Index element = -1;
  double fraction = 0.0;
};
BoundaryProjection project_on_boundary(const geometry::BoundaryMesh& mesh, const Vec2& point);

// Interpolated boundary values at a fraction along an element (linear through its nodes).
Vec2 interpolate_on_element(const geometry::BoundaryElement& element, const std::vector<Vec2>& nodal,
                            double fraction);

// Value at a geometric vertex: at a split corner there is no node, so each adjacent
// element's interpolation is extrapolated to the vertex and the two are averaged.
Vec2 vector_at_vertex(const geometry::BoundaryMesh& mesh, Index vertex, const std::vector<Vec2>& nodal);
StressTensor stress_at_vertex(const geometry::BoundaryMesh& mesh, Index vertex,
                              const std::vector<StressTensor>& nodal);

// Stress at a vertex that also honours the tractions prescribed there: the in-plane
// stress is the one closest to the mean of the two sides' extrapolations that satisfies
// sigma n = p for every traction component the conditions of either side prescribe at the
// vertex. At a corner where the two sides prescribe three independent components (a
// loaded end meeting a free face), the stress follows from the data alone.
StressTensor stress_at_vertex(const geometry::BoundaryMesh& mesh, const BodyDefinition& body, AnalysisType type,
                              Index vertex, const std::vector<StressTensor>& nodal);

// A field added to Somigliana's wherever it is evaluated (an elastoplastic region's cells:
// their initial stresses' displacement and stress at x).
using DomainTerm = std::function<void(const Vec2& x, Vec2& displacement, StressTensor& stress)>;

// Somigliana displacement and stress at interior points. Points closer to the boundary
// than half the local element length take the stress interpolated along the normal
// between the boundary stress and the value half an element inside, which keeps the
// error at the level of the boundary stress where the near-hypersingular integral of the
// piecewise-linear density would lose accuracy.
InteriorSolution interior_values(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                                 const BoundarySolution& solution, const std::vector<Vec2>& points,
                                 const ProgressCallback& progress = {}, const DomainTerm& domain_term = {});

// The points of `points` inside the body (with their grid indices) and the grid points
// outside it; listed points outside are returned for the caller to report.
struct InteriorSelection {
  std::vector<Vec2> inside;
  std::vector<std::array<int, 2>> grid_index;
  std::vector<Vec2> dropped;
  std::vector<const InteriorPoint*> listed_outside;
};
InteriorSelection select_interior_points(const geometry::BoundaryMesh& mesh, const std::vector<InteriorPoint>& points);

// interior_values at the selected points, with the grid indices and dropped points set, and
// a domain term if given.
InteriorSolution interior_values(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                                 const BoundarySolution& solution, InteriorSelection selection,
                                 const ProgressCallback& progress = {}, const DomainTerm& domain_term = {});

// Plane or axisymmetric Somigliana stress at one interior point, without the
// near-boundary treatment (exposed for tests).
StressTensor somigliana_stress(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                               const BoundarySolution& solution, const Vec2& point);
Vec2 somigliana_displacement(const geometry::BoundaryMesh& mesh, const ElementIntegrator& integrator,
                             const BoundarySolution& solution, const Vec2& point);

}  // namespace bemcontact::bem

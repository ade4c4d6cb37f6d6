#pragma once
// A body of one elastoplastic region under a load history (docs/plasticity.md): the cells
// made from the region's [cells] (plasticity/region_cells.hpp), the region solved step by
// step (bem/elastoplastic_region.hpp), and at each step's end the boundary values, the
// boundary stresses with the cells' plastic strain, and the resultants.
#include <optional>
#include <string>
#include <vector>

#include "bemcontact/bem/elastoplastic_region.hpp"
#include "bemcontact/bem/problem.hpp"
#include "bemcontact/bem/progress.hpp"
#include "bemcontact/bem/solution.hpp"

namespace bemcontact::bem {

struct ElastoplasticStep {
  double time = 0.0, amplitude = 0.0;
  IncrementReport report;
  int yielded_cells = 0;  // cells with plastic strain so far
  double max_equivalent_plastic_strain = 0.0;
  std::vector<BoundaryResultant> resultants;
  std::vector<Vec2> mean_displacement;  // per boundary: the mean of its nodes' displacements
};

struct ElastoplasticResult {
  geometry::BoundaryMesh mesh;
  std::vector<plasticity::Cell> cells;
  std::vector<ElastoplasticStep> steps;
  // At the last step's end (after unloading: the residual stresses and the permanent set).
  BoundarySolution boundary;
  std::vector<plasticity::J2State> states;
  std::vector<plasticity::Mandel> cell_stress;
  InteriorSolution interior;  // the [interior] points at the last step's end
  // Where the answer may be wrong without an error: the plastic zone reaching the side of
  // the cells' box inside the body (the material beyond stays elastic).
  std::vector<std::string> warnings;
  PhaseTimings timings;
};

// The closed polygons the boundary elements draw, one per contour (arcs of quadratic
// elements as chords of an eighth of the element; symmetry lines and the axis, which carry
// no elements, as their straight pieces).
std::vector<plasticity::RegionLoop> region_loops(const geometry::BoundaryMesh& mesh,
                                                const std::vector<geometry::BoundaryPiece>& pieces);

// The stress at each boundary node from its traction, the tangential strain of the
// displacement and the plastic strain of the cell the node borders (none: elastic), with
// Hooke's law on the elastic part in the local frame (n, s) (boundary_stresses without
// plastic strain).
std::vector<StressTensor> elastoplastic_boundary_stresses(const geometry::BoundaryMesh& mesh, AnalysisType type,
                                                          const Material& material, const BoundarySolution& solution,
                                                          const std::vector<plasticity::Cell>& cells,
                                                          const std::vector<plasticity::J2State>& states);

// The matrices' bytes of an elastoplastic region of `cells` cells and `nodes` nodes: the
// boundary's [b | B] and its solution, Somigliana's means, and the cell operator and Newton
// system: dense, at worst (every cell plastic); compressed ([cells] operator), the
// hierarchical matrix and the plastic block of a quarter of the cells. 3 components per cell
// in plane problems, 4 in axisymmetry.
double elastoplastic_region_bytes(Index cells, Index nodes, AnalysisType type, bool compressed_cells = false);

// The record of a step that has just ended in `region`: its report, the yielded cells and
// the largest equivalent plastic strain, each boundary's resultant and mean displacement;
// `boundary` receives the region's boundary solution with its resultants (no stresses).
ElastoplasticStep record_elastoplastic_step(double time, const IncrementReport& report,
                                            const ElastoplasticRegion& region, const geometry::BoundaryMesh& mesh,
                                            const BodyDefinition& body, AnalysisType type, BoundarySolution& boundary);

// The cells of an elastoplastic region from its [cells] (plasticity/region_cells.hpp).
// InputError at the [cells] table when they cannot be made, or when their dense matrices,
// with `used_bytes` of other elastoplastic regions already made, would take more than
// `memory_limit_bytes` (0: no limit).
std::vector<plasticity::Cell> region_cells_of(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                              AnalysisType type, double memory_limit_bytes, double used_bytes = 0.0);

// With [cells] nodes_at_cells (the default), the body with element end points added on its
// boundaries where the vertices of its cells on `mesh` lie on them
// (geometry::pieces_with_nodes_at); else the body as it is. A cell-wise constant plastic
// strain kinks the boundary's displacement at those points, and a collapse mechanism (a
// compatible plastic strain) leaves no stress only if the elements can follow it: with nodes
// elsewhere a band of plastic shear leaving the surface kept 2 to 13 % of G gamma as stress
// whatever the cell size, and the punch's load rose on past Prandtl's limit. Mesh the result
// again, and make the cells from that mesh. `vertices`: those points instead (a body's
// regions bonded: every elastoplastic region's, contact/pairing.cpp). InputError as
// region_cells_of.
BodyDefinition body_conforming_to_cells(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                        AnalysisType type, const std::vector<Vec2>& vertices = {});
// The vertices of the body's cells on `mesh` when nodes_at_cells asks for them; none else.
std::vector<Vec2> cell_vertices_to_conform(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                           AnalysisType type);

// The warning of a plastic zone that reaches a side of the cells' box where the body goes
// on (the answer too stiff there); none otherwise.
std::optional<std::string> plastic_zone_box_warning(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                                    const std::vector<plasticity::Cell>& cells,
                                                    const std::vector<plasticity::J2State>& states);

// InputError at the [cells] table when its cells cannot be made, or when they would take
// more than `memory_limit_bytes` (0: no limit; before anything large is allocated);
// SolverError (from the region) when an increment fails after its cuts.
// The body's mesh as solve_elastoplastic_body meshes it: as given, then (nodes_at_cells)
// meshed again with a node at every cell vertex on its straight pieces.
geometry::BoundaryMesh mesh_elastoplastic_body(const ProblemDefinition& problem);

ElastoplasticResult solve_elastoplastic_body(const ProblemDefinition& problem, const std::vector<double>& times,
                                             const std::vector<double>& amplitudes,
                                             const ProgressCallback& progress = {}, double memory_limit_bytes = 0.0);

}  // namespace bemcontact::bem

#include "bemcontact/bem/elastoplastic_analysis.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/postprocess.hpp"
#include "bemcontact/bem/resultants.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/core/limits.hpp"

namespace bemcontact::bem {

namespace {

// The plastic strain of the cell each node borders: the cell holding a point just inside
// the boundary from the node (zero where no cell does).
std::vector<plasticity::Mandel> nodal_plastic_strain(const geometry::BoundaryMesh& mesh,
                                                     const std::vector<plasticity::Cell>& cells,
                                                     const std::vector<plasticity::J2State>& states) {
  std::vector<plasticity::Mandel> out(mesh.nodes.size(), plasticity::Mandel::Zero());
  const double inset = 1e-7 * mesh.scale;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    const Vec2 probe = mesh.nodes[i].position - inset * mesh.nodes[i].normal;
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (cells[c].contains(probe)) {
        out[i] = states[c].plastic_strain;
        break;
      }
  }
  return out;
}

// A yielded cell on a side of the cells' box where the body goes on beyond it: the first
// such point, or none.
std::optional<Vec2> zone_at_box_side(const std::vector<plasticity::Cell>& cells,
                                     const std::vector<plasticity::J2State>& states,
                                     const plasticity::CellMeshOptions& options,
                                     const std::vector<plasticity::RegionLoop>& loops, double scale) {
  if (!options.box) return std::nullopt;
  const auto& [lo, hi] = *options.box;
  const double tolerance = 1e-9 * scale, step = 1e-6 * scale;
  const auto inside = [&](const Vec2& p) {
    bool in = false;  // the even-odd rule over every loop
    for (const auto& loop : loops)
      for (std::size_t k = 0, n = loop.points.size(); k < n; ++k) {
        const Vec2 &a = loop.points[k], &b = loop.points[(k + 1) % n];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x()))
          in = !in;
      }
    return in;
  };
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (!(states[c].equivalent_plastic_strain > 0.0)) continue;
    const auto& v = cells[c].vertices;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const Vec2 middle = 0.5 * (v[k] + v[(k + 1) % v.size()]);
      for (int axis = 0; axis < 2; ++axis)
        for (const double side : {-1.0, 1.0}) {
          const double bound = side < 0 ? lo[axis] : hi[axis];
          const Vec2 a = v[k], b = v[(k + 1) % v.size()];
          if (std::abs(a[axis] - bound) > tolerance || std::abs(b[axis] - bound) > tolerance) continue;
          Vec2 beyond = middle;
          beyond[axis] += side * step;
          if (inside(beyond)) return middle;
        }
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<plasticity::RegionLoop> region_loops(const geometry::BoundaryMesh& mesh,
                                                const std::vector<geometry::BoundaryPiece>& pieces) {
  std::vector<plasticity::RegionLoop> loops;
  for (const auto& contour : mesh.contours) {
    plasticity::RegionLoop loop;
    loop.hole = contour.is_hole;
    for (const int piece : contour.pieces) {
      const auto p = static_cast<std::size_t>(piece);
      if (mesh.piece_skipped[p]) {  // a symmetry line or the axis: straight, no elements
        loop.points.push_back(pieces[p].start);
        continue;
      }
      for (const Index e : mesh.piece_elements[p]) {
        const auto& element = mesh.elements[static_cast<std::size_t>(e)];
        const int chords = element.arc ? 8 : 1;
        for (int k = 0; k < chords; ++k) loop.points.push_back(element.point(static_cast<double>(k) / chords));
      }
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<StressTensor> elastoplastic_boundary_stresses(const geometry::BoundaryMesh& mesh, AnalysisType type,
                                                          const Material& material, const BoundarySolution& solution,
                                                          const std::vector<plasticity::Cell>& cells,
                                                          const std::vector<plasticity::J2State>& states) {
  const auto plastic = nodal_plastic_strain(mesh, cells, states);
  return boundary_stresses(mesh, type, material, solution, &plastic);
}

double elastoplastic_region_bytes(Index cells, Index nodes, AnalysisType type, bool compressed_cells) {
  const double components = type == AnalysisType::axisymmetric ? 4.0 : 3.0;
  const double unknowns = components * static_cast<double>(cells), values = 4.0 * static_cast<double>(nodes);
  // A^-1 [b | B], the nodal values V and Somigliana's rows R (about 4 x 4n x 3m), and: dense,
  // at worst (every cell yields) K's columns and the Newton system (2 (3m)^2); compressed,
  // the hierarchical matrix (200 N log2 N values: measured 140-190 at 1 090-4 162 cells) and
  // the kept block and Newton system of a quarter of the cells.
  const double cells_part = compressed_cells ? 200.0 * unknowns * std::log2(std::max(2.0, unknowns)) +
                                                   2.0 * (unknowns / 4.0) * (unknowns / 4.0)
                                             : 2.0 * unknowns * unknowns;
  return 8.0 * (cells_part + 4.0 * values * unknowns);
}

std::vector<plasticity::Cell> region_cells_of(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                              AnalysisType type, double memory_limit_bytes, double used_bytes) {
  const RegionPlasticity& plasticity = *body.plasticity;
  std::vector<plasticity::Cell> cells;
  try {
    cells = plasticity::region_cells(region_loops(mesh, body.pieces), plasticity.cells);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(plasticity.cells_where, e.what());
  }
  const double bytes = elastoplastic_region_bytes(static_cast<Index>(cells.size()), mesh.node_count(), type,
                                                  plasticity.cell_operator == OperatorKind::compressed);
  if (memory_limit_bytes > 0.0 && used_bytes + bytes > memory_limit_bytes)
    throw InputError(plasticity.cells_where,
                     std::to_string(cells.size()) + " cells would take about " + format_bytes(bytes) +
                         " of matrices" +
                         (used_bytes > 0.0 ? " (" + format_bytes(used_bytes + bytes) +
                                                 " with the other elastoplastic regions' cells)"
                                           : std::string()) +
                         ", over the limit of " + format_bytes(memory_limit_bytes) +
                         ": give larger cells or a box around where the body may yield, or raise the limit with "
                         "--max-memory (GB) on a larger machine");
  return cells;
}

std::vector<Vec2> cell_vertices_to_conform(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                           AnalysisType type) {
  std::vector<Vec2> vertices;
  if (!body.plasticity || !body.plasticity->nodes_at_cells) return vertices;
  for (const auto& cell : region_cells_of(mesh, body, type, 0.0))
    vertices.insert(vertices.end(), cell.vertices.begin(), cell.vertices.end());
  return vertices;
}

BodyDefinition body_conforming_to_cells(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                        AnalysisType type, const std::vector<Vec2>& vertices) {
  if (!body.plasticity || !body.plasticity->nodes_at_cells) return body;
  BodyDefinition out = body;
  out.pieces = geometry::pieces_with_nodes_at(
      mesh, body.pieces, vertices.empty() ? cell_vertices_to_conform(mesh, body, type) : vertices, 1e-9 * mesh.scale);
  return out;
}

std::optional<std::string> plastic_zone_box_warning(const geometry::BoundaryMesh& mesh, const BodyDefinition& body,
                                                    const std::vector<plasticity::Cell>& cells,
                                                    const std::vector<plasticity::J2State>& states) {
  const RegionPlasticity& plasticity = *body.plasticity;
  const auto at = zone_at_box_side(cells, states, plasticity.cells, region_loops(mesh, body.pieces), mesh.scale);
  if (!at) return std::nullopt;
  return plasticity.cells_where.describe() + ": the plastic zone reaches the side of the cells' box at " +
         point_text(*at) + ", where the body goes on: the material beyond the box stays elastic and the answer is "
         "too stiff; enlarge the box";
}

ElastoplasticStep record_elastoplastic_step(double time, const IncrementReport& report,
                                            const ElastoplasticRegion& region, const geometry::BoundaryMesh& mesh,
                                            const BodyDefinition& body, AnalysisType type, BoundarySolution& boundary) {
  ElastoplasticStep step;
  step.time = time;
  step.amplitude = report.amplitude;
  step.report = report;
  for (const auto& state : region.states()) {
    step.yielded_cells += state.equivalent_plastic_strain > 0.0;
    step.max_equivalent_plastic_strain = std::max(step.max_equivalent_plastic_strain, state.equivalent_plastic_strain);
  }
  boundary = region.boundary_solution();
  boundary.resultants = boundary_resultants(mesh, boundary, body, type);
  step.resultants = boundary.resultants;
  for (const auto& nodes : mesh.piece_nodes) {
    Vec2 mean = Vec2::Zero();
    for (const Index i : nodes) mean += boundary.displacement[static_cast<std::size_t>(i)];
    step.mean_displacement.push_back(nodes.empty() ? mean : mean / static_cast<double>(nodes.size()));
  }
  return step;
}

geometry::BoundaryMesh mesh_elastoplastic_body(const ProblemDefinition& problem) {
  geometry::BoundaryMesh mesh = mesh_body(problem);
  if (!problem.body.plasticity || !problem.body.plasticity->nodes_at_cells) return mesh;
  ProblemDefinition conformed = problem;
  conformed.body = body_conforming_to_cells(mesh, problem.body, problem.analysis);
  return mesh_body(conformed);
}

ElastoplasticResult solve_elastoplastic_body(const ProblemDefinition& problem, const std::vector<double>& times,
                                             const std::vector<double>& amplitudes, const ProgressCallback& progress,
                                             double memory_limit_bytes) {
  const BodyDefinition& body = problem.body;
  if (!body.plasticity) throw std::logic_error("solve_elastoplastic_body: the body has no yield stress");
  const RegionPlasticity& plasticity = *body.plasticity;
  ElastoplasticResult result;
  PhaseClock clock(result.timings);
  result.mesh = mesh_elastoplastic_body(problem);
  auto selection = select_interior_points(result.mesh, problem.interior_points);
  if (!selection.listed_outside.empty()) {
    const auto& p = *selection.listed_outside.front();
    throw InputError(p.where.file.empty() ? SourceLocation{problem.source_file, 0, "interior.points"} : p.where,
                     "point " + point_text(p.position) + " is not inside the body");
  }
  result.cells = region_cells_of(result.mesh, body, problem.analysis, memory_limit_bytes);
  clock.lap("mesh and cells");

  ElastoplasticRegion region(result.mesh, body, problem.analysis, plasticity.hardening, result.cells);
  clock.lap("set-up");

  PhaseProgress phase(progress, "load steps");
  phase.start();
  for (std::size_t k = 0; k < times.size(); ++k) {
    const IncrementReport report = region.advance(amplitudes[k]);
    result.steps.push_back(record_elastoplastic_step(times[k], report, region, result.mesh, body, problem.analysis,
                                                     result.boundary));
    phase.report(static_cast<double>(k + 1) / static_cast<double>(times.size()));
  }
  // The last step's boundary stresses, with the plastic strain of the cells the nodes border.
  result.boundary.stress = elastoplastic_boundary_stresses(result.mesh, problem.analysis, body.material,
                                                           result.boundary, result.cells, region.states());
  result.states = region.states();
  result.cell_stress = region.cell_stress();
  clock.lap("load steps");
  if (auto warning = plastic_zone_box_warning(result.mesh, body, result.cells, result.states))
    result.warnings.push_back(std::move(*warning));
  if (!problem.interior_points.empty()) {
    const ElementIntegrator integrator(problem.analysis, body.material);
    const PlasticCellFields fields = region.cell_fields();
    result.interior = interior_values(result.mesh, integrator, result.boundary, std::move(selection), progress,
                                      [&](const Vec2& x, Vec2& u, StressTensor& s) { fields.add_at(x, u, s); });
    clock.lap("interior points");
  }
  return result;
}

}  // namespace bemcontact::bem

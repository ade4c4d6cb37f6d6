#include "bemcontact/bem/elastoplastic_analysis.hpp"

#include <algorithm>
#include <string>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/postprocess.hpp"
#include "bemcontact/bem/resultants.hpp"
#include "bemcontact/core/error.hpp"

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

ElastoplasticResult solve_elastoplastic_body(const ProblemDefinition& problem, const std::vector<double>& times,
                                             const std::vector<double>& amplitudes, const ProgressCallback& progress) {
  const BodyDefinition& body = problem.body;
  if (!body.plasticity) throw std::logic_error("solve_elastoplastic_body: the body has no yield stress");
  const RegionPlasticity& plasticity = *body.plasticity;
  ElastoplasticResult result;
  PhaseClock clock(result.timings);
  result.mesh = mesh_body(problem);
  auto selection = select_interior_points(result.mesh, problem.interior_points);
  if (!selection.listed_outside.empty()) {
    const auto& p = *selection.listed_outside.front();
    throw InputError(p.where.file.empty() ? SourceLocation{problem.source_file, 0, "interior.points"} : p.where,
                     "point " + point_text(p.position) + " is not inside the body");
  }
  try {
    result.cells = plasticity::region_cells(region_loops(result.mesh, body.pieces), plasticity.cells);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(plasticity.cells_where, e.what());
  }
  clock.lap("mesh and cells");

  ElastoplasticRegion region(result.mesh, body, problem.analysis, plasticity.hardening, result.cells);
  clock.lap("set-up");

  PhaseProgress phase(progress, "load steps");
  phase.start();
  for (std::size_t k = 0; k < times.size(); ++k) {
    ElastoplasticStep step;
    step.time = times[k];
    step.amplitude = amplitudes[k];
    step.report = region.advance(amplitudes[k]);
    for (const auto& state : region.states()) {
      step.yielded_cells += state.equivalent_plastic_strain > 0.0;
      step.max_equivalent_plastic_strain = std::max(step.max_equivalent_plastic_strain, state.equivalent_plastic_strain);
    }
    BoundarySolution boundary = region.boundary_solution();
    boundary.stress = elastoplastic_boundary_stresses(result.mesh, problem.analysis, body.material, boundary,
                                                      result.cells, region.states());
    boundary.resultants = boundary_resultants(result.mesh, boundary, body, problem.analysis);
    step.resultants = boundary.resultants;
    for (const auto& nodes : result.mesh.piece_nodes) {
      Vec2 mean = Vec2::Zero();
      for (const Index i : nodes) mean += boundary.displacement[static_cast<std::size_t>(i)];
      step.mean_displacement.push_back(nodes.empty() ? mean : mean / static_cast<double>(nodes.size()));
    }
    result.steps.push_back(std::move(step));
    if (k + 1 == times.size()) result.boundary = std::move(boundary);
    phase.report(static_cast<double>(k + 1) / static_cast<double>(times.size()));
  }
  result.states = region.states();
  result.cell_stress = region.cell_stress();
  clock.lap("load steps");
  if (!problem.interior_points.empty()) {
    const ElementIntegrator integrator(problem.analysis, body.material);
    result.interior = interior_values(result.mesh, integrator, result.boundary, std::move(selection), progress,
                                      [&](const Vec2& x, Vec2& u, StressTensor& s) { region.add_cell_fields_at(x, u, s); });
    clock.lap("interior points");
  }
  return result;
}

}  // namespace bemcontact::bem

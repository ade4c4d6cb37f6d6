// Elastoplastic regions (bem/elastoplastic_region.hpp) against an independent
// computation: the thick tube in plane strain under internal pressure
// (examples/thick_ring_plane_strain.toml, a = 1, b = 2), cells over a <= r <= 1.6 on the
// inner arc's 32 angles, loaded in steps of 0.1 of the first-yield pressure p_y to 1.5 p_y
// and unloaded, against the one-dimensional finite-element tube of
// reference/plastic_cylinder.hpp (400 elements).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/elastoplastic_analysis.hpp"
#include "bemcontact/contact/contact_problem.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/io/input/problem_reader.hpp"
#include "bemcontact/io/input/problem_text.hpp"
#include "bemcontact/io/text_format.hpp"
#include "bemcontact/plasticity/cell_meshes.hpp"
#include "bemcontact/bem/elastoplastic_region.hpp"
#include "bemcontact/reference/plastic_cylinder.hpp"
#include "bemcontact/validation/case_groups.hpp"
#include "bemcontact/validation/case_support.hpp"
#include "bemcontact/validation/contact_support.hpp"

namespace bemcontact::validation {
namespace {

constexpr double kInner = 1.0, kOuter = 2.0, kCellsTo = 1.6;

struct TubeErrors {
  double plastic_displacement = 0.0;  // the bore's displacement beyond the elastic response, at 1.5 p_y
  double residual_displacement = 0.0;  // the bore's after unloading
  double mean_hoop = 0.0;              // the cells' hoop stress at 1.5 p_y, mean |error| / Y
  double plastic_radius = 0.0;         // the outermost plastic cell's outer radius
  int newton_iterations = 0, held_cells = 0;
};

TubeErrors run_tube(const bem::ProblemDefinition& problem, const geometry::BoundaryMesh& mesh,
                    const plasticity::J2Hardening& hardening, int rings,
                    const std::vector<double>& pressures,
                    const std::vector<reference::PlasticCylinderState>& reference) {
  const Index bore = node_at(mesh, Vec2(kInner * std::sqrt(0.5), kInner * std::sqrt(0.5)));
  bem::ElastoplasticRegion region(
      mesh, problem.body, problem.analysis, hardening,
      plasticity::annular_sector_cells(Vec2::Zero(), kInner, kCellsTo, 0.0, 0.5 * std::numbers::pi, rings, 32));
  const Vec2 radial = mesh.nodes[static_cast<std::size_t>(bore)].position.normalized();
  TubeErrors out;
  double elastic = 0.0;
  const std::size_t peak = pressures.size() - 2;  // 1.5 p_y, before the unloading
  for (std::size_t k = 0; k < pressures.size(); ++k) {
    const auto report = region.advance(pressures[k]);
    out.newton_iterations = std::max(out.newton_iterations, report.newton_iterations);
    out.held_cells += report.held_cells;
    const double ur = region.boundary_solution().displacement[static_cast<std::size_t>(bore)].dot(radial);
    if (k == 0) elastic = ur;
    if (k == peak) {
      const double scale = pressures[k] / pressures[0];
      out.plastic_displacement = (ur - scale * elastic) /
                                     (reference[k].inner_displacement - scale * reference[0].inner_displacement) - 1.0;
      std::vector<Vec2> centroids;
      for (const auto& cell : region.cells()) centroids.push_back(cell.centroid());
      out.mean_hoop = reference[k].mean_hoop_error(centroids, region.cell_stress(), hardening.yield_stress);
      for (std::size_t e = 0; e < region.cells().size(); ++e) {
        if (region.states()[e].equivalent_plastic_strain > 0.0)
          for (const Vec2& v : region.cells()[e].vertices) out.plastic_radius = std::max(out.plastic_radius, v.norm());
      }
    }
    if (k + 1 == pressures.size()) out.residual_displacement = ur / reference[k].inner_displacement - 1.0;
  }
  return out;
}

// The radial displacement of boundary 'inner' (a bore, where it is uniform) at each step of
// an elastoplastic run: its nodes' mean displacement along their mean radial direction.
std::size_t piece_named(const geometry::BoundaryMesh& mesh, const std::string& name) {
  std::size_t piece = 0;
  while (mesh.piece_names.at(piece) != name) ++piece;
  return piece;
}

std::vector<double> bore_displacements(const bem::ElastoplasticResult& result) {
  const std::size_t inner = piece_named(result.mesh, "inner");
  Vec2 radial = Vec2::Zero();
  for (const Index i : result.mesh.piece_nodes[inner])
    radial += result.mesh.nodes[static_cast<std::size_t>(i)].position.normalized();
  radial /= static_cast<double>(result.mesh.piece_nodes[inner].size());
  std::vector<double> out;
  for (const auto& step : result.steps) out.push_back(step.mean_displacement[inner].dot(radial) / radial.squaredNorm());
  return out;
}

// The bore's displacement beyond the elastic response at the peak pressure (the first step
// elastic, scaled), and after unloading, each relative to the reference's minus 1.
struct BoreErrors {
  double plastic = 0.0, residual = 0.0;
};
BoreErrors bore_errors(const bem::ElastoplasticResult& result, const std::vector<double>& pressures,
                       const std::vector<reference::PlasticCylinderState>& reference) {
  const auto bore = bore_displacements(result);
  std::size_t peak = 0;
  for (std::size_t k = 0; k < pressures.size(); ++k)
    if (pressures[k] > pressures[peak]) peak = k;
  const double scale = pressures[peak] / pressures[0];
  return {(bore[peak] - scale * bore[0]) /
                  (reference[peak].inner_displacement - scale * reference[0].inner_displacement) - 1.0,
          bore.back() / reference.back().inner_displacement - 1.0};
}

// examples/plastic_tube.toml as a user runs it: the cells made from [cells] size (the
// whole quarter tube, cut by its arcs), the steps from [history], at two cell sizes.
void add_tube_from_file(const Context& context, std::vector<Record>& records) {
  const std::string path = context.examples_dir + "/plastic_tube.toml";
  const auto input = io::read_problem(io::read_problem_text(path), path);
  auto history = contact::elastoplastic_history(input.model);
  auto& body = history.problem.body;
  const auto& hardening = body.plasticity->hardening;
  const double py = input.parameters.at("py");
  std::vector<double> pressures;
  for (const double amplitude : history.amplitudes) pressures.push_back(amplitude * py);
  const auto reference = reference::plastic_thick_cylinder(kInner, kOuter, body.material, hardening, pressures, 400);
  // Interior points on the 45 degree ray: in the plastic zone (c = 1.33) and beyond it.
  const std::vector<double> interior_radii{1.15, 1.25, 1.6, 1.85};
  history.problem.interior_points.clear();  // the example's grid: not these checks'
  for (const double r : interior_radii)
    history.problem.interior_points.push_back(bem::InteriorPoint{r * Vec2(1.0, 1.0).normalized(), false, {}});
  double previous = 0.0, previous_hoop = 0.0;
  for (const double size : {0.16, 0.08}) {
    const std::size_t first = records.size();
    body.plasticity->cells.size = size;
    const auto result = bem::solve_elastoplastic_body(history.problem, history.times, history.amplitudes);
    const auto [plastic, residual] = bore_errors(result, pressures, reference);
    std::vector<Vec2> centroids;
    for (const auto& cell : result.cells) centroids.push_back(cell.centroid());
    const double hoop = reference.back().mean_hoop_error(centroids, result.cell_stress, hardening.yield_stress);
    // Cells of 0.16 are two across the plastic zone (c - a = 0.33): a first-order error of
    // about a quarter of a cell over c - a; the pair's ratio is checked below.
    records.push_back(compare_scaled("plastic_bore_displacement", plastic, 0.0, 1.0, size > 0.1 ? 0.10 : 0.04));
    records.push_back(compare_scaled("residual_bore_displacement", residual, 0.0, 1.0, size > 0.1 ? 0.10 : 0.04));
    records.push_back(compare_scaled("mean_residual_hoop_stress_error_over_Y", hoop, 0.0, 1.0, size > 0.1 ? 0.02 : 0.01));
    // The bore's residual hoop stress from the boundary stresses with the plastic strain of
    // the cells the nodes border (away from the rollers' corners): first order in the cell
    // size, as the cells' constant plastic strain against its steep rise at the bore.
    double bore_hoop = 0.0;
    int nodes = 0;
    for (const Index i : result.mesh.piece_nodes[piece_named(result.mesh, "inner")]) {
      const Vec2 x = result.mesh.nodes[static_cast<std::size_t>(i)].position;
      const double angle = std::atan2(x.y(), x.x());
      if (angle < 0.3 || angle > 1.27) continue;
      const Vec2 t(-std::sin(angle), std::cos(angle));
      const auto& stress = result.boundary.stress[static_cast<std::size_t>(i)];
      bore_hoop += t.x() * t.x() * stress.s11 + t.y() * t.y() * stress.s22 + 2 * t.x() * t.y() * stress.s12;
      ++nodes;
    }
    bore_hoop /= nodes;
    const double hoop_reference = reference.back().stress.front()[1];  // (rr, tt, zz) at the bore's Gauss point
    records.push_back(compare_scaled("residual_bore_hoop_stress", bore_hoop, hoop_reference, hardening.yield_stress,
                                     size > 0.1 ? 0.12 : 0.04));
    // The residual hoop stress at the interior points: Somigliana's with the cells' fields.
    for (std::size_t k = 0; k < interior_radii.size(); ++k) {
      const auto& stress = result.interior.stress[k];
      const double hoop = 0.5 * (stress.s11 + stress.s22) - stress.s12;  // at 45 degrees: t = (-1, 1)/sqrt2
      const auto& states = reference.back();
      std::size_t nearest = 0;
      for (std::size_t g = 0; g < states.radii.size(); ++g)
        if (std::abs(states.radii[g] - interior_radii[k]) < std::abs(states.radii[nearest] - interior_radii[k])) nearest = g;
      records.push_back(compare_scaled("residual_hoop_stress_at_r=" + io::format_number(interior_radii[k]), hoop,
                                       states.stress[nearest][1], hardening.yield_stress, size > 0.1 ? 0.03 : 0.012));
    }
    if (previous_hoop > 0.0)
      records.push_back(compare_scaled("bore_hoop_error_ratio_on_halving",
                                       std::abs(bore_hoop - hoop_reference) / previous_hoop, 0.0, 1.0, 0.5));
    previous_hoop = std::abs(bore_hoop - hoop_reference);
    // Cut cells are irregular: a few at the plastic front may cycle and be held on the yield
    // surface. Their negative plastic increment (the complementarity's violation) must stay
    // below 5 % of the largest plastic strain, under the discretisation error of this size.
    int held = 0, cuts = 0;
    double violation = 0.0;
    for (const auto& step : result.steps) {
      held += step.report.held_cells, cuts += step.report.cuts;
      violation = std::min(violation, step.report.held_increment);
    }
    const double strain_scale = hardening.yield_stress / body.material.young_modulus;
    records.push_back(report_value("cells_held_on_the_surface", held));
    records.push_back(compare_scaled("held_violation_over_largest_plastic_strain",
                                     -violation * strain_scale / result.steps.back().max_equivalent_plastic_strain, 0.0,
                                     1.0, 0.05));
    records.push_back(report_value("cuts", cuts));
    records.push_back(report_value("cells", static_cast<double>(result.cells.size())));
    if (previous > 0.0)
      records.push_back(compare_scaled("plastic_displacement_error_ratio_on_halving", std::abs(plastic) / previous,
                                       0.0, 1.0, 0.8));
    previous = std::abs(plastic);
    tag(records, first, "plastic-cylinder", {{"input", "examples/plastic_tube.toml"}, {"cell_size", std::to_string(size)}});
  }
}

// examples/plastic_tube_bonded.toml: the same tube as an elastoplastic inner ring bonded to
// an elastic outer ring (docs/plasticity.md, "Bonded to other regions"), through the contact
// model without contacts, at two cell sizes: the bore's and the outer surface's residual
// displacements and the cells' residual hoop stress against the 1D reference, within the
// one-region tube's bounds and falling on halving.
void add_bonded_tube(const Context& context, std::vector<Record>& records) {
  double previous_bore = 0.0, previous_hoop = 0.0;
  for (const double size : {0.16, 0.08}) {
    const std::size_t first = records.size();
    const auto file = load_contact_example(context, "plastic_tube_bonded.toml", {{"cell", size}});
    auto problem = file.problem;
    problem.drop_interior_points();
    const auto result = contact::solve_contact(problem, context.progress);
    const auto& inner = result.plastic.at(0).result;
    const auto& hardening = problem.bodies[0].regions[0].body.plasticity->hardening;
    const Material& material = problem.bodies[0].regions[0].body.material;
    std::vector<double> pressures;
    for (const auto& step : inner.steps) pressures.push_back(step.amplitude * file.parameters.at("py"));
    const auto reference = reference::plastic_thick_cylinder(kInner, kOuter, material, hardening, pressures, 400);
    const auto [plastic, residual] = bore_errors(inner, pressures, reference);
    // The outer ring's outer surface after unloading: its nodes' mean radial displacement.
    const auto& mesh = result.meshes.at(1);
    double outside = 0.0;
    const auto& nodes = mesh.piece_nodes[piece_named(mesh, "outer")];
    for (const Index i : nodes)
      outside += result.boundary.at(1).displacement[static_cast<std::size_t>(i)].dot(
          mesh.nodes[static_cast<std::size_t>(i)].position.normalized());
    outside /= static_cast<double>(nodes.size());
    std::vector<Vec2> centroids;
    for (const auto& cell : inner.cells) centroids.push_back(cell.centroid());
    const double hoop = reference.back().mean_hoop_error(centroids, inner.cell_stress, hardening.yield_stress);
    records.push_back(compare_scaled("residual_bore_displacement", residual, 0.0, 1.0, size > 0.1 ? 0.10 : 0.04));
    records.push_back(compare_scaled("residual_outer_displacement", outside / reference.back().outer_displacement - 1.0,
                                     0.0, 1.0, size > 0.1 ? 0.10 : 0.04));
    records.push_back(compare_scaled("mean_residual_hoop_stress_error_over_Y", hoop, 0.0, 1.0, size > 0.1 ? 0.02 : 0.01));
    records.push_back(report_value("plastic_bore_displacement_error", plastic));
    records.push_back(report_value("cells", static_cast<double>(inner.cells.size())));
    if (previous_bore > 0.0) {
      records.push_back(compare_scaled("bore_error_ratio_on_halving", std::abs(residual) / previous_bore, 0.0, 1.0, 0.8));
      records.push_back(compare_scaled("hoop_error_ratio_on_halving", hoop / previous_hoop, 0.0, 1.0, 0.8));
    }
    previous_bore = std::abs(residual), previous_hoop = hoop;
    tag(records, first, "plastic-cylinder",
        {{"input", "examples/plastic_tube_bonded.toml"}, {"cell_size", std::to_string(size)}});
  }
}

// examples/plastic_sphere.toml as a user runs it (axisymmetric, cells from [cells] size),
// at two cell sizes, against the 1D sphere (reference/plastic_cylinder.hpp) and Hill's
// plastic radius c = 1.3 at the peak pressure.
std::vector<Record> run_plastic_sphere(const Context& context) {
  if (context.operator_kind == bem::OperatorKind::compressed) return skipped_on_compressed("plastic-sphere");
  std::vector<Record> records;
  const std::string path = context.examples_dir + "/plastic_sphere.toml";
  const auto input = io::read_problem(io::read_problem_text(path), path);
  auto history = contact::elastoplastic_history(input.model);
  auto& body = history.problem.body;
  history.problem.interior_points.clear();
  const auto& hardening = body.plasticity->hardening;
  const double peak_pressure = input.parameters.at("p"), c = input.parameters.at("c");
  const double a = input.parameters.at("a"), b = input.parameters.at("b");
  std::vector<double> pressures;
  for (const double amplitude : history.amplitudes) pressures.push_back(amplitude * peak_pressure);
  const auto reference = reference::plastic_thick_sphere(a, b, body.material, hardening, pressures, 400);
  double previous = 0.0;
  for (const double size : {0.25, 0.125}) {
    const std::size_t first = records.size();
    body.plasticity->cells.size = size;
    const auto result = bem::solve_elastoplastic_body(history.problem, history.times, history.amplitudes);
    const auto [plastic, residual] = bore_errors(result, pressures, reference);
    double hoop = 0.0, plastic_radius = a;
    for (std::size_t e = 0; e < result.cells.size(); ++e) {
      const double r = result.cells[e].centroid().norm();
      const auto& state = reference.back();
      std::size_t g = 0;
      for (std::size_t q = 0; q < state.radii.size(); ++q)
        if (std::abs(state.radii[q] - r) < std::abs(state.radii[g] - r)) g = q;
      hoop += std::abs(result.cell_stress[e][2] - state.stress[g][1]);  // the hoop stress: Mandel 33
      if (result.states[e].equivalent_plastic_strain > 0.0)
        for (const Vec2& v : result.cells[e].vertices) plastic_radius = std::max(plastic_radius, v.norm());
    }
    hoop /= hardening.yield_stress * static_cast<double>(result.cells.size());
    // Cells of 0.25 are about two across the plastic zone (c - a = 0.3): a first-order error
    // of a quarter of a cell over c - a; the pair's ratio is checked below.
    records.push_back(compare_scaled("plastic_bore_displacement", plastic, 0.0, 1.0, size > 0.2 ? 0.22 : 0.07));
    records.push_back(compare_scaled("residual_bore_displacement", residual, 0.0, 1.0, size > 0.2 ? 0.22 : 0.07));
    records.push_back(compare_scaled("mean_residual_hoop_stress_error_over_Y", hoop, 0.0, 1.0, size > 0.2 ? 0.025 : 0.008));
    // The plastic zone ends within a cell's diagonal of Hill's radius.
    records.push_back(compare_scaled("plastic_radius_hill", plastic_radius, c, std::sqrt(2.0) * size, 1.0));
    records.push_back(report_value("cells", static_cast<double>(result.cells.size())));
    if (previous > 0.0)
      records.push_back(compare_scaled("plastic_displacement_error_ratio_on_halving", std::abs(plastic) / previous,
                                       0.0, 1.0, 0.5));
    previous = std::abs(plastic);
    tag(records, first, "plastic-sphere", {{"input", "examples/plastic_sphere.toml"}, {"cell_size", std::to_string(size)}});
  }
  return records;
}

std::vector<Record> run_plastic_cylinder(const Context& context) {
  // The region is dense only (no compressed domain operator yet): under --operator
  // compressed the case would repeat itself.
  if (context.operator_kind == bem::OperatorKind::compressed) return skipped_on_compressed("plastic-cylinder");
  // The pressure p = 1: the increments' amplitudes are the pressures.
  auto file = io::read_problem_file(context.examples_dir + "/thick_ring_plane_strain.toml", {{"p", 1.0}});
  auto& problem = file.problem;
  for (auto& piece : problem.body.pieces)
    if (piece.name == "AB" || piece.name == "CD") piece.elements = 64;  // the cells' centroids 2 elements away
  const auto mesh = bem::mesh_body(problem);
  const Material& material = problem.body.material;
  std::vector<Record> records;
  // 24 rings (768 cells) take 9 s more: measured -0.80 % and 0.15 % of Y (docs/plasticity.md).
  const std::vector<std::pair<double, std::vector<int>>> variants{{0.0, {6, 12}}, {0.01, {6}}, {0.05, {6}}};
  for (const auto& [hardening_share, levels] : variants) {
    const plasticity::J2Hardening hardening{250.0, hardening_share * material.young_modulus, 0.0};
    const double py = reference::first_yield_pressure(kInner, kOuter, material, hardening.yield_stress);
    std::vector<double> pressures{0.5 * py};
    for (int k = 9; k <= 15; ++k) pressures.push_back(0.1 * k * py);
    pressures.push_back(0.0);
    const auto reference = reference::plastic_thick_cylinder(kInner, kOuter, material, hardening, pressures, 400);
    const double c_reference = reference[pressures.size() - 2].plastic_radius;
    double previous = 0.0;
    for (const int rings : levels) {
      const std::size_t first = records.size();
      const TubeErrors e = run_tube(problem, mesh, hardening, rings, pressures, reference);
      const double cell = (kCellsTo - kInner) / rings;
      records.push_back(compare_scaled("plastic_bore_displacement", e.plastic_displacement, 0.0, 1.0,
                                       rings <= 6 ? 0.06 : rings <= 12 ? 0.03 : 0.015));
      records.push_back(compare_scaled("residual_bore_displacement", e.residual_displacement, 0.0, 1.0,
                                       rings <= 6 ? 0.06 : rings <= 12 ? 0.03 : 0.015));
      records.push_back(compare_scaled("mean_hoop_stress_error_over_Y", e.mean_hoop, 0.0, 1.0,
                                       rings <= 6 ? 0.006 : rings <= 12 ? 0.004 : 0.003));
      // The plastic zone ends within a cell of the reference's radius.
      records.push_back(compare_scaled("plastic_radius", e.plastic_radius, c_reference, cell, 1.0));
      records.push_back(compare_scaled("cells_held_on_the_surface", e.held_cells, 0.0, 1.0, 0.0));
      records.push_back(report_value("largest_newton_iterations", e.newton_iterations));
      if (previous > 0.0)
        records.push_back(report_value("plastic_displacement_order",
                                       std::log(previous / std::abs(e.plastic_displacement)) / std::log(2.0)));
      previous = std::abs(e.plastic_displacement);
      tag(records, first, "plastic-cylinder",
          {{"hardening_over_E", std::to_string(hardening_share)}, {"rings", std::to_string(rings)}});
    }
  }
  add_tube_from_file(context, records);
  add_bonded_tube(context, records);
  return records;
}

// examples/prandtl_punch.toml as a user runs it, at two cell sizes at the punch's edge
// (0.1a and 0.05a: 612 and 879 cells; at 0.025a, 1.010 in about 4 minutes, docs/plasticity.md):
// the mean pressure under the punch against Prandtl's limit (2 + pi) k, k = Y / sqrt 3
// [Prandtl1920; Hill1950, ch. VIII] on the curve's plateau (the mean of its last quarter),
// the plateau level (its rise over that quarter), and its excess over the
// limit falling as the edge's cells refine.
std::vector<Record> run_punch_limit_load(const Context& context) {
  if (context.operator_kind == bem::OperatorKind::compressed) return skipped_on_compressed("punch-limit-load");
  std::vector<Record> records;
  const std::string path = context.examples_dir + "/prandtl_punch.toml";
  double previous_excess = 0.0;
  for (const double fine : {0.1, 0.05}) {
    const std::size_t first = records.size();
    const auto input = io::read_problem(io::read_problem_text(path), path, {{"fine", fine}});
    const auto history = contact::elastoplastic_history(input.model);
    const auto result = bem::solve_elastoplastic_body(history.problem, history.times, history.amplitudes);
    const double a = input.parameters.at("a"), Y = input.parameters.at("Y");
    const double limit = (2.0 + std::numbers::pi) * Y / std::sqrt(3.0);
    std::vector<double> pressure;  // the mean pressure under the half punch, per step
    int iterations = 0, cuts = 0;
    for (const auto& step : result.steps) {
      for (const auto& r : step.resultants)
        if (r.boundary == "face") pressure.push_back(-r.force.y() / a / limit);
      iterations += step.report.newton_iterations, cuts += step.report.cuts;
    }
    const std::size_t n = pressure.size(), quarter = std::max<std::size_t>(1, n / 4);
    double plateau = 0.0;
    for (std::size_t k = n - quarter; k < n; ++k) plateau += pressure[k] / static_cast<double>(quarter);
    // Measured 1.0385 and 1.0213: first order in the edge's cell size (1.010 at 0.025a).
    records.push_back(compare_relative("plateau_pressure_over_prandtl", plateau, 1.0, fine > 0.07 ? 0.05 : 0.03));
    // Levelled over the plateau (0.0525a to 0.07a; measured within 0.01 % at both sizes):
    // elements that cannot follow the mechanism (nodes_at_cells = false) rise by 0.65 % of the
    // limit over the same stretch of a run to 0.08a at 0.05a, still going (1.050 at 0.08a),
    // and rectangles (locking) by 3 to 4 % (1.27 at 0.08a).
    records.push_back(compare_scaled("rise_over_last_quarter_over_prandtl", pressure[n - 1] - pressure[n - 1 - quarter],
                                     0.0, 1.0, 0.002));
    const double excess = plateau - 1.0;
    if (previous_excess > 0.0)
      records.push_back(compare_scaled("excess_ratio_on_halving", excess / previous_excess, 0.0, 1.0, 0.8));
    previous_excess = excess;
    records.push_back(report_value("cells", static_cast<double>(result.cells.size())));
    records.push_back(report_value("newton_iterations", iterations));
    records.push_back(report_value("cuts", cuts));
    tag(records, first, "punch-limit-load", {{"input", "examples/prandtl_punch.toml"}, {"fine", std::to_string(fine)}});
  }
  return records;
}

}  // namespace

std::vector<Case> plasticity_cases() {
  return {{"plastic-sphere", "Conclusion (perspective); Hill 1950",
           "elastoplastic thick sphere in axisymmetry, loaded until Hill's plastic radius is 1.3 and unloaded, against "
           "a 1D finite-element reference",
           run_plastic_sphere},
          {"plastic-cylinder", "Conclusion (perspective); Hill 1950",
           "elastoplastic thick tube in plane strain, perfectly plastic and hardening, loading and unloading, against "
           "a 1D finite-element reference",
           run_plastic_cylinder},
          {"punch-limit-load", "Conclusion (perspective); Prandtl 1920",
           "rigid flat punch on an elastic-perfectly plastic block (plane strain): the load-approach curve levels at "
           "Prandtl's limit pressure (2 + pi) k, converging as the cells at the punch's edge refine",
           run_punch_limit_load}};
}

}  // namespace bemcontact::validation

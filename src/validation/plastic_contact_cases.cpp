// Elastoplastic bodies in contact (contact/plastic_coupling.hpp) against what does not come
// from the boundary element code: the first yield of the closed-form Hertz fields
// (reference/hertz.hpp, checked against an independent computation of the whole fields),
// and the Brinell cycle against Tabor's fully plastic mean pressure and Sneddon's elastic
// unloading stiffness.
#include <algorithm>
#include <cmath>
#include <string>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/indentation.hpp"
#include "bemcontact/plasticity/j2_material.hpp"
#include "bemcontact/reference/hertz.hpp"
#include "bemcontact/validation/case_groups.hpp"
#include "bemcontact/validation/case_support.hpp"
#include "bemcontact/validation/contact_support.hpp"

namespace bemcontact::validation {
namespace {

// What the cells show after a load below or above first yield.
struct OnsetRun {
  int yielded = 0;
  double largest_von_mises = 0.0;  // of the cells' stresses, over Y
  double first_depth = 0.0;        // depth of the cell with the largest plastic strain (0: none)
};

OnsetRun run_onset(const Context& context, io::ContactFile file, double yield_stress, double a, bool symmetric) {
  auto& body = file.problem.bodies.front().regions.front().body;
  bem::RegionPlasticity plasticity;
  plasticity.hardening = {yield_stress, 0.0, 0.0};
  plasticity.cells.size = 0.1 * a;  // the depth of the maximum within 0.05 a of a centroid
  plasticity.cells.box = std::array<Vec2, 2>{Vec2(symmetric ? -0.9 * a : 0.0, -1.3 * a), Vec2(0.9 * a, 0.0)};
  body.plasticity = plasticity;
  const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
  OnsetRun out;
  const auto& plastic = result.plastic.at(0).result;
  double kappa = 0.0;
  for (std::size_t e = 0; e < plastic.cells.size(); ++e) {
    out.largest_von_mises = std::max(out.largest_von_mises, plasticity::von_mises(plastic.cell_stress[e]) / yield_stress);
    if (!(plastic.states[e].equivalent_plastic_strain > 0.0)) continue;
    ++out.yielded;
    if (plastic.states[e].equivalent_plastic_strain > kappa)
      kappa = plastic.states[e].equivalent_plastic_strain, out.first_depth = -plastic.cells[e].centroid().y();
  }
  return out;
}

// The Hertz contacts of contact_rigid_sphere.toml (axisymmetric) and of
// contact_compliant_cylinder.toml made unilateral on an elastic block (plane strain), nu =
// 0.3, with cells of 0.1 a over the zone where the closed form's von Mises stress peaks; the
// yield stress set so that the Hertz peak pressure is 0.98 and 1.02 of the first-yield one.
std::vector<Record> run_yield_onset(const Context& context) {
  if (context.operator_kind == bem::OperatorKind::compressed) return skipped_on_compressed("yield-onset");
  std::vector<Record> records;
  for (const bool sphere : {true, false}) {
    io::ContactFile file = sphere ? load_contact_example(context, "contact_rigid_sphere.toml", {{"n", 40}})
                                  : load_contact_example(context, "contact_compliant_cylinder.toml",
                                                         {{"E_block", 70000.0}, {"P", 148.0}});
    auto& material = file.problem.bodies.front().regions.front().body.material;
    material.poisson_ratio = 0.3;
    if (!sphere) file.problem.contacts.front().law = contact::ContactLaw{};
    const double P = file.parameters.at("P"), R = file.parameters.at("R");
    const double E_star = reference::contact_modulus(material, file.problem.analysis);
    double a = 0.0, p0 = 0.0;
    reference::FirstYield onset;
    if (sphere) {
      const reference::HertzPointContact hertz{P, R, E_star};
      a = hertz.contact_radius(), p0 = hertz.max_pressure();
      onset = reference::hertz_sphere_first_yield(0.3);
    } else {
      const reference::HertzLineContact hertz{P, R, E_star};
      a = hertz.half_width(), p0 = hertz.max_pressure();
      onset = reference::hertz_cylinder_first_yield(0.3);
    }
    const std::string shape = sphere ? "sphere (axisymmetric)" : "cylinder (plane strain)";
    for (const double share : {0.98, 1.02}) {
      const std::size_t first = records.size();
      const double yield_stress = p0 / (onset.p0_over_yield() * share);
      const OnsetRun run = run_onset(context, file, yield_stress, a, !sphere);
      records.push_back(report_value("largest_cell_von_mises_over_Y", run.largest_von_mises));
      if (share < 1.0) {
        records.push_back(compare_scaled("yielded_cells", run.yielded, 0.0, 1.0, 0.0));
      } else {
        records.push_back(require_at_least("yielded_cells", run.yielded, 1.0));
        // The first plastic strain where the closed form's maximum is, within one cell.
        records.push_back(compare_scaled("first_yield_depth_over_a", run.first_depth / a, onset.depth_over_a, 0.1, 1.0));
      }
      tag(records, first, "yield-onset",
          {{"contact", shape}, {"load_over_first_yield", share == 1.02 ? "1.02" : "0.98"},
           {"p0_over_Y_first_yield", std::to_string(onset.p0_over_yield())}});
    }
  }
  return records;
}

// examples/brinell.toml as a user runs it, at two cell sizes: loaded to a fully plastic
// indentation (E* a / (Y R) about 70) and unloaded.
std::vector<Record> run_brinell(const Context& context) {
  if (context.operator_kind == bem::OperatorKind::compressed) return skipped_on_compressed("brinell");
  std::vector<Record> records;
  double previous_excess = 0.0;
  for (const double cell : {0.32, 0.16}) {
    const std::size_t first = records.size();
    const auto file = load_contact_example(context, "brinell.toml", {{"cell", cell}});
    const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
    const auto report = *contact::indentation_report(file.problem, result);
    const double Y = file.parameters.at("Y"), R = file.parameters.at("R");
    const double meyer = report.meyer / Y;
    records.push_back(report_value("meyer_hardness_over_Y", meyer));
    records.push_back(report_value("a_over_R", report.contact_radius / R));
    records.push_back(report_value("brinell_hardness", report.brinell));
    records.push_back(report_value("dent_depth_over_peak_depth", report.residual_depth / report.peak_depth));
    // Unloading is elastic: Sneddon's 2 E* a for the contact radius at the peak (the first
    // step out is 0.5 % of the depth).
    records.push_back(compare_relative("unloading_stiffness", report.unloading_stiffness,
                                       report.elastic_unloading_stiffness, 0.06));
    // After unloading the residual stresses carry no net force: the base's reaction.
    double base = 0.0;
    for (const auto& r : result.boundary.front().resultants)
      if (r.boundary == "base") base = r.force.y();
    records.push_back(compare_scaled("residual_base_reaction_over_peak_load", base / report.peak_load, 0.0, 1.0, 2e-3));
    // Tabor: about 2.8-3 Y when fully plastic; the excess over 3 Y shrinks as the cells refine.
    const double excess = meyer - 3.0;
    if (previous_excess > 0.0) records.push_back(require_at_least("excess_over_tabor_ratio_on_halving", previous_excess / excess, 1.3));
    previous_excess = excess;
    tag(records, first, "brinell", {{"input", "examples/brinell.toml"}, {"cell_size", std::to_string(cell)}});
  }
  return records;
}

}  // namespace

std::vector<Case> plastic_contact_cases() {
  return {{"yield-onset", "Conclusion (perspective); Johnson 1985, 6.2",
           "first yield under a rigid sphere (axisymmetric) and a rigid cylinder (plane strain) at 0.98 and 1.02 of "
           "the load at which the closed-form Hertz field's von Mises stress reaches Y: no plastic strain below, "
           "plastic strain at the right depth above",
           run_yield_onset},
          {"brinell", "Section V.5.2.3 (a first approach to the Brinell test); Tabor 1951",
           "rigid ball into an elastic-perfectly plastic block and out: Meyer hardness against Tabor's 2.8-3 Y under "
           "refinement, elastic unloading against Sneddon's 2 E* a, self-equilibrated residual stresses, HB",
           run_brinell}};
}

}  // namespace bemcontact::validation

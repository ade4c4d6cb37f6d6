#include "bemcontact/io/output/contact_writer.hpp"
#include "bemcontact/io/file_names.hpp"

#include <algorithm>
#include <optional>

#include <cctype>
#include <charconv>

#include <cmath>
#include <cstdio>
#include <limits>

#include "bemcontact/contact/indentation.hpp"
#include "bemcontact/io/output/json_writer.hpp"
#include "bemcontact/io/output/plasticity_writer.hpp"
#include "bemcontact/reference/hertz.hpp"
#include "bemcontact/io/output/results_writer.hpp"

namespace bemcontact::io {
namespace {

// Every recorded load step's files go into this sub-folder of the output folder.
constexpr const char* steps_folder = "steps/";

}  // namespace


namespace {

nlohmann::json summary_json(const contact::ContactSummary& s) {
  return {{"time", s.time},
          {"a", s.contact_radius},
          {"c", s.stick_radius},
          {"c_over_a", s.stick_ratio()},
          {"peak_pressure", s.peak_pressure},
          {"centre_pressure", s.centre_pressure},
          {"normal_force", s.normal_force},
          {"tangential_force", s.tangential_force},
          {"approach", s.approach},
          {"pairs_in_contact", s.pairs_in_contact},
          {"contact_fraction", s.contact_fraction},
          {"contact_spots", s.contact_spots},
          {"mean_gap", s.mean_gap},
          {"stick_zone", {s.stick_start, s.stick_end}},
          {"stick_offset", s.stick_offset},
          {"contact_zone", {s.contact_start, s.contact_end}},
          {"dissipated_energy", s.dissipated_energy},
          {"iterations",
           {{"newton", s.newton_iterations},
            {"kalker", s.kalker_iterations},
            {"threshold", s.threshold_iterations},
            {"gmres_cycles", s.gmres_cycles},
            {"matrix_free_products", s.matrix_free_products}}},
          {"residual", s.residual}};
}

}  // namespace


// The contact files' numbers: std::to_chars' shortest text (CsvTable::compact).
CsvTable contact_table(const std::vector<contact::PairResult>& pairs) {
  constexpr auto c = CsvTable::compact;
  CsvTable table({{"pair", CsvTable::integer}, {"x", c}, {"y", c}, {"coordinate", c}, {"nx", c}, {"ny", c},
                  {"gap", c}, {"p_n", c}, {"p_t", c}, {"slip_ratio", c}, {"jump_n", c}, {"jump_t", c},
                  {"status", CsvTable::text}});
  table.reserve(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto& p = pairs[i];
    table.row() << static_cast<double>(i) << p.position.x() << p.position.y() << p.coordinate << p.normal.x()
                << p.normal.y() << p.gap << p.p_n << p.p_t << p.slip_ratio << p.jump_n << p.jump_t
                << contact::to_string(p.status);
  }
  return table;
}

std::string contact_csv(const std::vector<contact::PairResult>& pairs) { return csv_text(contact_table(pairs)); }

namespace {

// The pairs' point data: tractions, gap, slip, jumps, status (0 open, 1 stick, 2 slip).
struct PairFields {
  std::vector<Vec2> points, normals;
  std::vector<std::pair<std::string, std::vector<double>>> scalars;
};

PairFields pair_fields(const std::vector<contact::PairResult>& pairs) {
  PairFields f;
  std::vector<double> gap, p_n, p_t, slip_ratio, jump_n, jump_t, status;
  for (const auto& p : pairs) {
    f.points.push_back(p.position);
    f.normals.push_back(p.normal);
    gap.push_back(p.gap), p_n.push_back(p.p_n), p_t.push_back(p.p_t), slip_ratio.push_back(p.slip_ratio);
    jump_n.push_back(p.jump_n), jump_t.push_back(p.jump_t), status.push_back(static_cast<double>(p.status));
  }
  f.scalars = {{"p_n", p_n}, {"p_t", p_t}, {"gap", gap}, {"slip_ratio", slip_ratio}, {"jump_n", jump_n},
               {"jump_t", jump_t}, {"status", status}};
  return f;
}

}  // namespace

std::string contact_vtk(const std::vector<contact::PairResult>& pairs, std::string_view title) {
  const auto f = pair_fields(pairs);
  return point_cloud_vtk(title, f.points, f.scalars, {{"normal", f.normals}},
                         {"status_names", {contact::to_string(contact::PairStatus::open),
                                           contact::to_string(contact::PairStatus::stick),
                                           contact::to_string(contact::PairStatus::slip)}});
}

std::string contact_vtp(const std::vector<contact::PairResult>& pairs) {
  const auto f = pair_fields(pairs);
  return point_cloud_vtp(f.points, f.scalars, {{"normal", f.normals}});
}

CsvTable contact_steps_table(const contact::ContactInterfaceResult& result) {
  constexpr auto c = CsvTable::compact;
  constexpr auto i = CsvTable::integer;
  CsvTable table({{"step", i},
                  {"time", c},
                  {"a", c},
                  {"c", c},
                  {"stick_start", c},
                  {"stick_end", c},
                  {"stick_offset", c},
                  {"contact_start", c},
                  {"contact_end", c},
                  {"peak_pressure", c},
                  {"centre_pressure", c},
                  {"normal_force", c},
                  {"tangential_force", c},
                  {"approach", c},
                  {"pairs_in_contact", i},
                  {"contact_fraction", c},
                  {"contact_spots", i},
                  {"mean_gap", c},
                  {"dissipated_energy", c},
                  {"newton_iterations", i},
                  {"kalker_iterations", i},
                  {"threshold_iterations", i},
                  {"gmres_cycles", i},
                  {"residual", c}});
  const bool worn = !result.wear.empty();
  if (worn) {
    table.add_column("worn_volume1", c);
    table.add_column("worn_volume2", c);
  }
  table.reserve(result.steps.size());
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    const auto& s = result.steps[k];
    auto row = table.row();
    row << static_cast<double>(k + 1) << s.time << s.contact_radius << s.stick_radius << s.stick_start
                << s.stick_end << s.stick_offset << s.contact_start << s.contact_end << s.peak_pressure
                << s.centre_pressure << s.normal_force << s.tangential_force << s.approach
                << static_cast<double>(s.pairs_in_contact) << s.contact_fraction
                << static_cast<double>(s.contact_spots) << s.mean_gap << s.dissipated_energy
                << static_cast<double>(s.newton_iterations) << static_cast<double>(s.kalker_iterations)
                << static_cast<double>(s.threshold_iterations) << static_cast<double>(s.gmres_cycles) << s.residual;
    if (worn) row << s.worn_volume1 << s.worn_volume2;
  }
  return table;
}

namespace {
// The deepest point of a scar (0 for none).
double deepest(const std::vector<double>& depth) {
  return depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end());
}

// A wearing contact's computed cycles (contact/wear.hpp): the cycles each stands for, the
// worn volumes and deepest points of both sides, and the contact at the cycle's end.
CsvTable wear_table(const contact::ContactInterfaceResult& result) {
  constexpr auto c = CsvTable::compact;
  constexpr auto i = CsvTable::integer;
  CsvTable table({{"cycle", i},
                  {"computed", i},
                  {"jump", i},
                  {"pressure_change", c},
                  {"worn_volume1", c},
                  {"worn_volume2", c},
                  {"max_depth1", c},
                  {"max_depth2", c},
                  {"a", c},
                  {"contact_start", c},
                  {"contact_end", c},
                  {"c", c},
                  {"peak_pressure", c},
                  {"centre_pressure", c},
                  {"pairs_in_contact", i}});
  for (const auto& w : result.wear) {
    const auto& s = w.summary;
    const double max1 = deepest(w.depth1), max2 = deepest(w.depth2);
    table.row() << static_cast<double>(w.cycle) << static_cast<double>(w.computed) << static_cast<double>(w.jump)
                << w.pressure_change << s.worn_volume1 << s.worn_volume2 << max1 << max2 << s.contact_radius
                << s.contact_start << s.contact_end << s.stick_radius << s.peak_pressure << s.centre_pressure
                << static_cast<double>(s.pairs_in_contact);
  }
  return table;
}

// The scar of every computed cycle, pair by pair: depth of each side, tractions, status.
CsvTable wear_profile_table(const contact::ContactInterfaceResult& result) {
  constexpr auto c = CsvTable::compact;
  CsvTable table({{"cycle", CsvTable::integer}, {"pair", CsvTable::integer}, {"x", c}, {"y", c}, {"coordinate", c},
                  {"depth1", c}, {"depth2", c}, {"p_n", c}, {"p_t", c}, {"status", CsvTable::text}});
  for (const auto& w : result.wear)
    for (std::size_t k = 0; k < w.pairs.size(); ++k) {
      const auto& p = w.pairs[k];
      table.row() << static_cast<double>(w.cycle) << static_cast<double>(k) << p.position.x() << p.position.y()
                  << p.coordinate << w.depth1[k] << w.depth2[k] << p.p_n << p.p_t << contact::to_string(p.status);
    }
  return table;
}

}  // namespace

std::string contact_steps_csv(const contact::ContactInterfaceResult& result) {
  return csv_text(contact_steps_table(result));
}

namespace {

// An adaptive zone's passes and final meshes (the probe meshes the run again from them).
nlohmann::json zone_json(const contact::AdaptedZone& zone) {
  nlohmann::json passes = nlohmann::json::array();
  for (const auto& p : zone.passes)
    passes.push_back({{"pass", p.pass},
                      {"pairs", p.pairs},
                      {"elements1", p.elements1},
                      {"elements2", p.elements2},
                      {"width", p.width},
                      {"edge_spacing", p.edge_spacing},
                      {"resolved", p.resolved}});
  return {{"passes", passes}, {"breakpoints1", zone.breakpoints1}, {"breakpoints2", zone.breakpoints2}};
}

nlohmann::json interface_json(const contact::ContactInterfaceResult& result) {
  nlohmann::json j = summary_json(result.summary);
  j["name"] = result.name;
  j["pairs"] = result.pairs.size();
  if (!result.zone.passes.empty()) j["zone"] = zone_json(result.zone);
  if (!result.wear.empty()) {
    nlohmann::json cycles = nlohmann::json::array();
    for (const auto& w : result.wear)
      cycles.push_back({{"cycle", w.cycle},
                        {"computed", w.computed},
                        {"jump", w.jump},
                        {"pressure_change", w.pressure_change},
                        {"worn_volume1", w.summary.worn_volume1},
                        {"worn_volume2", w.summary.worn_volume2},
                        {"a", w.summary.contact_radius},
                        {"c", w.summary.stick_radius},
                        {"peak_pressure", w.summary.peak_pressure}});
    j["wear"] = {{"cycles", cycles}};
  }
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : result.steps) steps.push_back(summary_json(s));
  j["steps"] = steps;
  return j;
}

std::string body_label(const contact::ContactProblem& problem, const contact::BoundaryRef& side) {
  return problem.bodies[side.body].name;
}

// Hertz's solution for an axisymmetric ball (an arc zone on side 1 facing a straight
// elastic zone, or a flat zone facing a rigid sphere) pressed by a force; none otherwise.
struct HertzReference {
  double R, a, p0, approach;
};

std::optional<HertzReference> hertz_reference(const contact::ContactProblem& problem) {
  if (problem.analysis != AnalysisType::axisymmetric || problem.forces.size() != 1 || problem.contacts.size() != 1)
    return std::nullopt;
  const auto& contact = problem.contacts.front();
  if (contact.side1.pieces.size() != 1 || contact.side2.pieces.size() > 1) return std::nullopt;  // one arc, one line
  const auto& side1 = problem.region(contact.side1).body;
  const auto& zone1 = side1.pieces[contact.side1.pieces.front()];
  const auto& body2 = problem.bodies[contact.side2.body];
  double R = 0.0;
  Material material2{std::numeric_limits<double>::infinity(), 0.3};  // rigid: E* from side 1 alone
  if (body2.rigid) {
    if (body2.rigid->profile != "sphere" || zone1.shape != geometry::PieceShape::line) return std::nullopt;
    R = geometry::arc_radius(body2.rigid->contour.front());
  } else {
    const auto& zone2 = problem.region(contact.side2).body.pieces[contact.side2.pieces.front()];
    if (zone1.shape != geometry::PieceShape::arc || zone2.shape != geometry::PieceShape::line) return std::nullopt;
    R = geometry::arc_radius(zone1);
    material2 = problem.region(contact.side2).body.material;
  }
  // The force at the end of the history (its amplitude there).
  const auto& load = problem.forces.front();
  const double P = std::abs(load.force * load.amplitude.at(problem.end_time));
  if (P == 0.0) return std::nullopt;
  const auto hertz = reference::hertz_point_contact(P, R, side1.material, std::numeric_limits<double>::infinity(),
                                                    material2);
  return HertzReference{R, hertz.contact_radius(), hertz.max_pressure(), hertz.approach()};
}

// Hertz's a, p0 and delta next to the computed ones, when hertz_reference applies.
std::string hertz_comparison(const contact::ContactProblem& problem, const contact::ContactSummary& s) {
  const auto hertz = hertz_reference(problem);
  if (!hertz) return "";
  char line[256];
  std::string out;
  std::snprintf(line, sizeof line, "  Hertz (R = %.6g): a = %.6g (computed %.6g, %+.2f %%)\n", hertz->R, hertz->a,
                s.contact_radius, 100.0 * (s.contact_radius / hertz->a - 1.0));
  out += line;
  std::snprintf(line, sizeof line, "                   p0 = %.6g (centre %.6g, %+.2f %%)\n", hertz->p0,
                s.centre_pressure, 100.0 * (s.centre_pressure / hertz->p0 - 1.0));
  out += line;
  std::snprintf(line, sizeof line, "                   delta = %.6g (computed %.6g, %+.2f %%)\n", hertz->approach,
                std::abs(s.approach), 100.0 * (std::abs(s.approach) / hertz->approach - 1.0));
  out += line;
  return out;
}

// The contact law: kind and friction of every contact (null when the contacts differ:
// `contacts` then gives each one's), and the tangential coupling.
nlohmann::json law_json(const contact::ContactProblem& problem) {
  // Without contacts: the default law (no contact has another).
  const auto common = problem.contacts.empty() ? std::optional(contact::ContactLaw{}) : problem.common_law();
  nlohmann::json law = {{"kind", common ? nlohmann::json(contact::to_string(common->kind)) : nlohmann::json()},
                        {"friction", common ? nlohmann::json(common->friction) : nlohmann::json()},
                        {"tangential_coupling", problem.tangential_coupling}};
  if (problem.contacts.empty()) return law;
  nlohmann::json contacts = nlohmann::json::array();
  for (const auto& contact : problem.contacts) {
    nlohmann::json entry = {{"name", contact.name},
                            {"kind", contact::to_string(contact.law.kind)},
                            {"friction", contact.law.friction}};
    if (contact.law.kind == contact::ContactKind::compliant) {
      const auto& c = contact.law.compliance;
      entry["normal_compliance"] = {{"normal_stiffness", c.stiffness},
                                    {"normal_exponent", c.exponent},
                                    {"friction_stiffness", c.friction_stiffness},
                                    {"friction_exponent", c.friction_exponent}};
    }
    contacts.push_back(entry);
  }
  law["contacts"] = contacts;
  return law;
}

}  // namespace

nlohmann::json contact_summary_json(const contact::ContactProblem& problem, const contact::ContactResult& result) {
  nlohmann::json j = interface_json(result);
  const auto law = law_json(problem);
  j["kind"] = law["kind"];
  j["algorithm"] = contact::to_string(problem.solver.algorithm);
  if (problem.solver.algorithm == contact::Algorithm::thesis) {
    j["gmres_restart"] = problem.solver.gmres_restart;
    j["max_gmres_cycles"] = problem.solver.max_gmres_cycles;
    j["xi"] = problem.solver.xi;
  } else {
    j["tolerance"] = problem.solver.tolerance;
  }
  j["friction"] = law["friction"];
  j["tangential_coupling"] = problem.tangential_coupling;
  j["increments"] = problem.increments;
  j["history"] = {{"end_time", problem.end_time},
                  {"adaptive", problem.adaptive && problem.has_friction()},
                  {"steps_taken", result.steps_taken},
                  {"rejected_steps", result.rejected_steps},
                  {"steps_at_shortest", result.steps_at_shortest},
                  {"rule", "a step in which more than max_state_changes pairs of one contact change state (open, "
                           "stick, slip) is redone shorter; each next step is the last one scaled by 0.75 "
                           "max_state_changes / its changes (within 1/8 and 2)"},
                  {"max_state_changes", problem.max_state_changes},
                  {"newton_systems",
                   {{"factored", result.newton_systems.factored},
                    {"updated", result.newton_systems.updated},
                    {"reused", result.newton_systems.reused}}}};
  j["unknowns"] = result.unknowns;
  if (result.matrix_free) j["matrix_free_images"] = result.matrix_free_images;
  if (result.products_compression > 0.0) j["products_compression"] = result.products_compression;
  // The closed form the plots draw next to the pressure (Hertz: p0 sqrt(1 - (r/a)^2)).
  if (const auto hertz = hertz_reference(problem))
    j["reference"] = {{"name", "hertz_sphere"}, {"R", hertz->R}, {"a", hertz->a}, {"p0", hertz->p0},
                      {"approach", hertz->approach}};
  if (!problem.contacts.empty()) {
    const auto& first = problem.contacts.front();
    j["bodies"] = {body_label(problem, first.side1), body_label(problem, first.side2)};
  }
  j["timings"] = timings_json(result.timings);
  return j;
}

namespace {

// "zone found in 3 passes (pairs 17, 40, 92): width 0.07, edge spacing 0.0012 = 0.017 of it"
std::string zone_text(const contact::ContactInterface& contact, const contact::AdaptedZone& zone) {
  std::string pairs;
  for (const auto& pass : zone.passes) pairs += (pairs.empty() ? "" : ", ") + std::to_string(pass.pairs);
  const auto& last = zone.passes.back();
  char line[320];
  std::snprintf(line, sizeof line,
                "  zone found in %zu pass%s (pairs %s; contact_resolution %.4g): width %.6g, edge spacing %.4g = "
                "%.4g of the width; %d elements on side 1, %d on side 2\n",
                zone.passes.size(), zone.passes.size() == 1 ? "" : "es", pairs.c_str(), contact.adaptivity.resolution,
                last.width, last.edge_spacing, last.width > 0.0 ? last.edge_spacing / last.width : 0.0, last.elements1,
                last.elements2);
  return line;
}

}  // namespace

namespace {

// A wearing contact's cycles and scar, in two lines.
std::string wear_text(const contact::ContactInterfaceResult& contact, int rejected_jumps) {
  const auto& first = contact.wear.front();
  const auto& last = contact.wear.back();
  long longest = 1;
  for (const auto& w : contact.wear) longest = std::max(longest, w.jump);
  char line[320];
  std::snprintf(line, sizeof line,
                "  wear: %ld load cycle%s in %d computed (jumps up to %ld cycles, %d undone); worn volume %.6g (side "
                "1), %.6g (side 2); deepest %.6g, %.6g\n",
                last.cycle, last.cycle == 1 ? "" : "s", last.computed, longest, rejected_jumps,
                last.summary.worn_volume1, last.summary.worn_volume2, deepest(last.depth1), deepest(last.depth2));
  std::string out = line;
  std::snprintf(line, sizeof line, "  wear: peak pressure %.6g after cycle 1, %.6g after cycle %ld; a %.6g, %.6g\n",
                first.summary.peak_pressure, last.summary.peak_pressure, last.cycle, first.summary.contact_radius,
                last.summary.contact_radius);
  return out + line;
}

}  // namespace

std::string contact_report_text(const contact::ContactProblem& problem, const contact::ContactResult& result) {
  char line[256];
  std::string out = problem.title + " (" + to_string(problem.analysis) +
                    "; units: those of the file, a consistent set such as mm, N, MPa)\n";
  for (std::size_t c = 0; c < result.contacts.size(); ++c) {
    const auto& contact = result.contacts[c];
    const auto& s = contact.summary;
    const std::string label =
        result.contacts.size() == 1 ? std::string("contact")
                                    : "contact '" + contact.name + "' (" + body_label(problem, problem.contacts[c].side1) +
                                          " / " + body_label(problem, problem.contacts[c].side2) + ")";
    if (s.pairs_in_contact == 0)  // no zone to describe (a history that ends unloaded)
      std::snprintf(line, sizeof line, "%s: %zu pairs, none in contact at the end\n", label.c_str(),
                    contact.pairs.size());
    else if (c < problem.contacts.size() && problem.contacts[c].law.friction > 0.0)
      std::snprintf(line, sizeof line,
                    "%s: %zu pairs, %d in contact over [%.6g, %.6g], a = %.6g, stick zone [%.6g, %.6g] (half-width c = "
                    "%.6g, offset %.6g, c/a = %.4f)\n",
                    label.c_str(), contact.pairs.size(), s.pairs_in_contact, s.contact_start, s.contact_end,
                    s.contact_radius, s.stick_start, s.stick_end, s.stick_radius, s.stick_offset, s.stick_ratio());
    else
      std::snprintf(line, sizeof line, "%s: %zu pairs, %d in contact over [%.6g, %.6g], a = %.6g (frictionless)\n",
                    label.c_str(), contact.pairs.size(), s.pairs_in_contact, s.contact_start, s.contact_end,
                    s.contact_radius);
    out += line;
    std::snprintf(line, sizeof line,
                  "  peak pressure %.6g, centre pressure %.6g, normal force %.6g, tangential force %.6g, approach %.6g\n",
                  s.peak_pressure, s.centre_pressure, s.normal_force, s.tangential_force, s.approach);
    out += line;
    std::snprintf(line, sizeof line, "  contact fraction %.4g of the zone in %d spot%s, mean gap %.6g\n",
                  s.contact_fraction, s.contact_spots, s.contact_spots == 1 ? "" : "s", s.mean_gap);
    out += line;
    if (!contact.zone.passes.empty()) out += zone_text(problem.contacts[c], contact.zone);
    if (!contact.wear.empty()) out += wear_text(contact, result.rejected_jumps);
  }
  if (problem.contacts.empty() && result.plastic.empty()) return out;
  const auto& s = result.summary;
  if (!problem.contacts.empty()) {
    std::snprintf(line, sizeof line, "  %s algorithm, %d load step%s (%d redone shorter): newton %d, kalker %d, threshold %d, gmres cycles %d\n",
                  contact::to_string(problem.solver.algorithm), result.steps_taken, result.steps_taken == 1 ? "" : "s",
                  result.rejected_steps, s.newton_iterations,
                  s.kalker_iterations, s.threshold_iterations, s.gmres_cycles);
    out += line;
    if (result.matrix_free) {
      std::snprintf(line, sizeof line, "  condensed operator applied matrix-free: %ld products, %ld coarse images\n",
                    s.matrix_free_products, result.matrix_free_images);
      out += line;
    } else if (result.products_compression > 0.0) {
      std::snprintf(line, sizeof line, "  condensed operator formed, its products through a compressed copy (%.3g of its size)\n",
                    result.products_compression);
      out += line;
    }
    if (result.steps_past_state_limit > 0) {
      std::snprintf(line, sizeof line,
                    "  %d step%s changed more pairs than max_state_changes: %s halves did not converge\n",
                    result.steps_past_state_limit, result.steps_past_state_limit == 1 ? "" : "s",
                    result.steps_past_state_limit == 1 ? "its" : "their");
      out += line;
    }
    if (result.steps_at_shortest > 0) {
      std::snprintf(line, sizeof line,
                    "  %d of the steps changed more pairs than max_state_changes at the shortest step (%s)\n",
                    result.steps_at_shortest,
                    20 * result.steps_at_shortest > result.steps_taken
                        ? "over 5 %: raise max_steps"
                        : "a few, after first touch and the amplitudes' corners, are expected");
      out += line;
    }
  }
  if (result.plastic.empty()) {
    out += hertz_comparison(problem, s);  // an elastic closed form
    return out;
  }
  for (const auto& [region, plastic] : result.plastic) {
    int iterations = 0, yielded = 0;
    double kappa = 0.0;
    for (const auto& step : plastic.steps) iterations += step.report.newton_iterations;
    for (const auto& state : plastic.states) {
      yielded += state.equivalent_plastic_strain > 0.0;
      kappa = std::max(kappa, state.equivalent_plastic_strain);
    }
    std::snprintf(line, sizeof line,
                  "  elastoplastic %s: %zu cells, %d Newton iterations over the steps; %d cells yielded, largest "
                  "equivalent plastic strain %.4g\n",
                  result.region_labels[static_cast<std::size_t>(region)].c_str(), plastic.cells.size(), iterations,
                  yielded, kappa);
    out += line;
  }
  if (const auto indentation = contact::indentation_report(problem, result)) {
    const auto& r = *indentation;
    std::snprintf(line, sizeof line,
                  "  indentation: peak load %.6g at depth %.6g, contact radius %.6g (d/D = %.4g): Meyer hardness "
                  "P/(pi a^2) = %.6g, ",
                  r.peak_load, r.peak_depth, r.contact_radius, 2.0 * r.contact_radius / r.ball_diameter, r.meyer);
    out += line;
    if (std::isfinite(r.brinell))
      std::snprintf(line, sizeof line, "HB = %.6g (stress units of the file; in N and mm, HB in kgf/mm^2 = %.4g)",
                    r.brinell, r.brinell / 9.80665);
    else
      std::snprintf(line, sizeof line, "HB undefined (d >= D)");
    out += line;
    std::snprintf(line, sizeof line, "; dent depth after the last step %.6g\n", r.residual_depth);
    out += line;
    if (r.unloading_stiffness > 0.0 && r.elastic_unloading_stiffness > 0.0) {
      std::snprintf(line, sizeof line, "  initial unloading stiffness %.6g (elastic 2 E* a = %.6g: ratio %.4g)\n",
                    r.unloading_stiffness, r.elastic_unloading_stiffness,
                    r.unloading_stiffness / r.elastic_unloading_stiffness);
      out += line;
    } else if (r.unloading_stiffness > 0.0) {
      std::snprintf(line, sizeof line,
                    "  initial unloading stiffness %.6g (a body of several regions: no elastic closed form)\n",
                    r.unloading_stiffness);
      out += line;
    }
  }
  return out;
}

std::vector<std::string> motion_columns(const contact::ContactProblem& problem, const contact::ContactResult& result) {
  const bool axisymmetric = problem.analysis == AnalysisType::axisymmetric;
  std::vector<std::string> columns;
  for (const auto& load : problem.forces) {
    std::string stem = problem.bodies[load.body].name;
    if (load.named) {
      stem += "_" + load.name;
    } else {
      if (load.piece >= 0) stem += "_" + problem.bodies[load.body].regions[load.region].body.pieces[load.piece].name;
      if (load.component == 0) stem += axisymmetric ? "_r" : "_x";
      if (load.component == 1) stem += axisymmetric ? "_z" : "_y";
    }
    stem = file_stem(stem);
    columns.push_back(stem + (load.component == 2 ? "_moment" : "_force"));
    columns.push_back(stem + (load.component == 2 ? "_rotation" : "_displacement"));
  }
  for (const auto& motion : result.free_motions)
    columns.push_back(file_stem(problem.bodies[motion.body].name) + "_" + motion.direction +
                      (motion.direction == "rotation" ? "" : "_displacement"));
  // A name met again (a load named like a direction of a free body) gets _2, _3, ...
  std::vector<std::string> unique;
  for (const auto& column : columns) {
    std::string name = column;
    for (int k = 2; std::find(unique.begin(), unique.end(), name) != unique.end(); ++k)
      name = column + "_" + std::to_string(k);
    unique.push_back(name);
  }
  return unique;
}

std::vector<OutputFile> contact_output_files(const contact::ContactProblem& problem,
                                             const contact::ContactResult& result, bool vtk) {
  std::vector<OutputFile> files;
  const auto add = [&](std::string name, auto content) { files.push_back({std::move(name), std::move(content)}); };
  for (const auto& contact : result.contacts) {
    const std::string stem = file_stem(contact.name);
    add(stem + ".csv", contact_table(contact.pairs));
    if (vtk) add(stem + ".vtk", contact_vtk(contact.pairs, problem.title + ": contact " + contact.name));
    add(stem + "_steps.csv", contact_steps_table(contact));
    if (!contact.wear.empty()) {
      add(stem + "_wear.csv", wear_table(contact));
      add(stem + "_wear_profile.csv", wear_profile_table(contact));
    }
    if (vtk && !contact.wear.empty()) {
      // The scar cycle by cycle as a ParaView series (time: the cycle count).
      std::vector<std::pair<double, std::string>> series;
      for (const auto& w : contact.wear) {
        const std::string name = "wear/" + stem + "_cycle" + std::to_string(w.cycle) + ".vtp";
        auto fields = pair_fields(w.pairs);
        fields.scalars.emplace_back("depth1", w.depth1);
        fields.scalars.emplace_back("depth2", w.depth2);
        add(name, point_cloud_vtp(fields.points, fields.scalars, {{"normal", fields.normals}}));
        series.emplace_back(static_cast<double>(w.cycle), name);
      }
      add(stem + "_wear.pvd", time_series_pvd(series));
    }
    for (std::size_t k = 0; k < contact.step_pairs.size(); ++k)
      add(steps_folder + stem + "_step" + std::to_string(k + 1) + ".csv", contact_table(contact.step_pairs[k]));
    if (vtk && !contact.step_pairs.empty()) {
      // Every step's pairs as a ParaView time series.
      std::vector<std::pair<double, std::string>> series;
      for (std::size_t k = 0; k < contact.step_pairs.size(); ++k) {
        const std::string name = steps_folder + stem + "_step" + std::to_string(k + 1) + ".vtp";
        add(name, contact_vtp(contact.step_pairs[k]));
        series.emplace_back(contact.steps[k].time, name);
      }
      add(stem + ".pvd", time_series_pvd(series));
    }
  }
  if (!result.records.empty() && result.records.front().motions.size() > 0) {
    CsvTable table({{"step", CsvTable::integer}, {"time", CsvTable::compact}});
    for (const auto& column : motion_columns(problem, result)) table.add_column(column, CsvTable::compact);
    const Index K = result.records.front().motions.size();
    table.reserve(result.records.size());
    for (std::size_t s = 0; s < result.records.size(); ++s) {
      const auto& r = result.records[s];
      auto row = table.row();
      row << static_cast<double>(s + 1) << r.time;
      for (Index k = 0; k < K; ++k) {
        if (k < static_cast<Index>(problem.forces.size())) row << r.forces[k];
        row << r.motions[k];
      }
    }
    add("motions.csv", std::move(table));
  }
  if (const auto indentation = contact::indentation_report(problem, result)) {
    constexpr auto c = CsvTable::compact;
    CsvTable table({{"step", CsvTable::integer}, {"time", c}, {"depth", c}, {"load", c}});
    for (std::size_t k = 0; k < indentation->times.size(); ++k)
      table.row() << static_cast<double>(k + 1) << indentation->times[k] << indentation->depths[k]
                  << indentation->loads[k];
    add("indentation.csv", std::move(table));
  }
  for (const auto& [region, plastic] : result.plastic) {  // each elastoplastic region's cells and steps
    const std::string stem = file_stem(result.body_names[static_cast<std::size_t>(region)]);
    add(stem + "_cells.csv", cells_table(plastic));
    add(stem + "_plastic_steps.csv", elastoplastic_steps_table(plastic));
    if (vtk) add(stem + "_cells.vtk", cells_vtk(plastic, problem.title));
  }
  for (std::size_t r = 0; r < result.meshes.size(); ++r) {
    const std::string stem = file_stem(result.body_names[r]);
    add(stem + "_boundary.csv", boundary_table(result.meshes[r], result.boundary[r]));
    if (vtk) add(stem + "_boundary.vtk", boundary_vtk(result.meshes[r], result.boundary[r], problem.title));
    if (!result.interior[r].points.empty()) {
      add(stem + "_interior.csv", interior_table(result.interior[r]));
      if (vtk) add(stem + "_interior.vtk", interior_vtk(result.interior[r], problem.title));
    }
    for (std::size_t k = 0; k < result.step_boundary.size(); ++k)
      add(steps_folder + stem + "_boundary_step" + std::to_string(k + 1) + ".csv",
          boundary_table(result.meshes[r], result.step_boundary[k][r]));
    if (vtk && !result.step_boundary.empty()) {
      // Every step's boundary fields as a ParaView time series.
      std::vector<std::pair<double, std::string>> series;
      for (std::size_t k = 0; k < result.step_boundary.size(); ++k) {
        const std::string name = steps_folder + stem + "_boundary_step" + std::to_string(k + 1) + ".vtp";
        add(name, boundary_vtp(result.meshes[r], result.step_boundary[k][r]));
        series.emplace_back(result.records[k].time, name);
      }
      add(stem + "_boundary.pvd", time_series_pvd(series));
    }
  }
  return files;
}

void fill_contact_summary(RunSummary& summary, const contact::ContactProblem& problem,
                          const contact::ContactResult& result) {
  int rigid = 0;
  for (const auto& body : problem.bodies) rigid += body.rigid.has_value();
  summary.kind = problem.contacts.empty() ? "bodies" : "contact";
  summary.problem = {{"bodies", problem.bodies.size()},
                     {"rigid_bodies", rigid},
                     {"regions", result.meshes.size()},
                     {"contacts", problem.contacts.size()},
                     {"force_loads", problem.forces.size()}};
  const auto& solver = problem.solver;
  summary.options.update(
      {{"mesh", mesh_options_json(problem.mesh)},
       {"law", law_json(problem)},
       {"solver", {{"algorithm", contact::to_string(solver.algorithm)},
                   {"contact_operator", contact::to_string(solver.contact_operator)},
                   {"tolerance", solver.tolerance},
                   {"max_iterations", solver.max_iterations},
                   {"gmres_restart", solver.gmres_restart},
                   {"xi", solver.xi},
                   {"max_gmres_cycles", solver.max_gmres_cycles},
                   {"max_threshold_iterations", solver.max_threshold_iterations}}},
       {"history", {{"end_time", problem.end_time},
                    {"increments", problem.increments},
                    {"adaptive", problem.adaptive && problem.has_friction()},
                    {"max_state_changes", problem.max_state_changes},
                    {"max_steps", problem.max_steps},
                    {"record_steps", problem.record_steps}}}});
  Index nodes = 0, elements = 0;
  nlohmann::json regions = nlohmann::json::object();
  for (std::size_t r = 0; r < result.meshes.size(); ++r) {
    const auto& mesh = result.meshes[r];
    nodes += mesh.node_count();
    elements += mesh.element_count();
    regions[result.body_names[r]] = {{"nodes", mesh.node_count()},
                                     {"elements", mesh.element_count()},
                                     {"graded_toward_vertices", mesh_transitions_json(mesh)}};
    // Per region, the contact zones included (the resultant of the contact tractions).
    summary.reactions[result.body_names[r]] = resultants_json(result.boundary[r].resultants, problem.analysis);
  }
  summary.mesh = {{"nodes", nodes}, {"elements", elements}, {"regions", regions}};
  summary.timings = timings_json(result.timings);
  if (!problem.contacts.empty()) summary.results["contact"] = contact_summary_json(problem, result);
  nlohmann::json contacts = nlohmann::json::array();
  for (const auto& contact : result.contacts) contacts.push_back(interface_json(contact));
  summary.results["contacts"] = contacts;
  // One elastoplastic region: its object; several: an array of them; each with its region's name.
  if (result.plastic.size() == 1) {
    summary.results["elastoplastic"] = elastoplastic_summary_json(result.plastic[0].result);
    summary.results["elastoplastic"]["region"] = result.body_names[static_cast<std::size_t>(result.plastic[0].region)];
  }
  if (result.plastic.size() > 1) {
    nlohmann::json regions = nlohmann::json::array();
    for (const auto& [region, plastic] : result.plastic) {
      auto entry = elastoplastic_summary_json(plastic);
      entry["region"] = result.body_names[static_cast<std::size_t>(region)];
      regions.push_back(std::move(entry));
    }
    summary.results["elastoplastic"] = regions;
  }
  if (const auto indentation = contact::indentation_report(problem, result)) {
    const auto& r = *indentation;
    summary.results["indentation"] = {
        {"ball_diameter", r.ball_diameter},
        {"peak_load", r.peak_load},
        {"peak_depth", r.peak_depth},
        {"contact_radius", r.contact_radius},
        {"impression_diameter", 2.0 * r.contact_radius},
        {"meyer_hardness", r.meyer},
        {"brinell_hardness", std::isfinite(r.brinell) ? nlohmann::json(r.brinell) : nlohmann::json(nullptr)},
        {"unloading_stiffness", r.unloading_stiffness},
        {"elastic_unloading_stiffness", r.elastic_unloading_stiffness > 0.0 ? nlohmann::json(r.elastic_unloading_stiffness)
                                                                          : nlohmann::json(nullptr)},
        {"residual_depth", r.residual_depth}};
  }
}

std::vector<OutputFile> contact_mesh_files(const contact::ContactProblem& problem,
                                           const contact::PreparedContact& prepared) {
  std::vector<OutputFile> files;
  const auto add = [&](std::string name, auto content) { files.push_back({std::move(name), std::move(content)}); };
  for (const auto& region : prepared.regions) {
    const auto& body = problem.bodies[region.body];
    const std::string stem = file_stem(body.regions.size() == 1 ? body.name : region.definition.name);
    add(stem + "_mesh_nodes.csv", mesh_nodes_table(region.mesh));
    add(stem + "_mesh_elements.csv", mesh_elements_table(region.mesh));
    add(stem + "_mesh.vtk", mesh_vtk(region.mesh, problem.title));
  }
  for (std::size_t c = 0; c < prepared.contacts.size(); ++c) {
    constexpr auto n = CsvTable::compact;
    CsvTable table({{"pair", CsvTable::integer}, {"x1", n}, {"y1", n}, {"x2", n}, {"y2", n}, {"nx", n}, {"ny", n},
                    {"gap", n}, {"weight", n}});
    const auto& pairs = prepared.contacts[c].pairs;
    table.reserve(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const auto& p = pairs[i];
      table.row() << static_cast<double>(i) << p.position1.x() << p.position1.y() << p.position2.x()
                  << p.position2.y() << p.normal.x() << p.normal.y() << p.gap << p.weight;
    }
    add(file_stem(problem.contacts[c].name) + "_pairs.csv", std::move(table));
  }
  return files;
}

}  // namespace bemcontact::io

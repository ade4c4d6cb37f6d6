// Partial slip under a tangential load history (examples/fretting_cylinder.toml): a
// cylinder pressed on a block by P, then Q. Elastically similar bodies, plane strain,
// against the half-plane theory (reference/fretting.hpp). The theory holds for a/R -> 0:
// the cylinder's curvature couples the normal pressure into the tangential displacements
// by O(a/R) (measured, Q = 0.6 mu P, 60 elements: the shear error away from the stick edge
// is 10.6, 4.2, 2.3, 0.9 and 0.5 % of mu p0 at a/R = 0.07, 0.035, 0.0175, 0.005 and
// 0.00125), so the cases run the example at a/R = 0.00125 (P scaled by (a/R / 0.07)^2, the
// zones by a/R / 0.07).
#include <cmath>
#include <sstream>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/reference/fretting.hpp"
#include "bemcontact/reference/nonlocal_cattaneo.hpp"
#include "bemcontact/validation/case_groups.hpp"
#include "bemcontact/validation/contact_support.hpp"

namespace bemcontact::validation {
namespace {


struct Fretting {
  io::ContactFile file;
  reference::PartialSlipLine theory;
  double mu_p0 = 0.0;
  double Q_star = 0.0;
};

constexpr double kContactOverRadius = 0.00125;  // a/R of the cases (the example's: 0.07)
constexpr double kScale = kContactOverRadius / 0.07;

// The example at a/R = 0.00125 with Q* = ratio mu P and the given amplitude of Q.
Fretting load_fretting(const Context& context, double ratio, const std::vector<Vec2>& q_amplitude, int elements) {
  const double scale = kScale;
  Fretting f;
  f.file = load_contact_example(context, "fretting_cylinder.toml",
                                 {{"P", 148.0 * scale * scale}, {"rc", 0.085 * scale}, {"Q_ratio", ratio},
                                  {"n", static_cast<double>(elements)}});
  auto& problem = f.file.problem;
  problem.forces.at(1).amplitude.points = q_amplitude;
  problem.end_time = q_amplitude.back().x();
  problem.record_steps = true;
  problem.drop_interior_points();
  const double P = -problem.forces.at(0).force, R = f.file.parameters.at("R");
  f.theory.hertz = {P, R, reference::contact_modulus(problem.elastic(0).material, problem.elastic(1).material, problem.analysis)};
  f.theory.friction = problem.contacts.front().law.friction;
  f.mu_p0 = f.theory.friction * f.theory.hertz.max_pressure();
  f.Q_star = problem.forces.at(1).force;
  return f;
}

// The shear on the cylinder opposes Q: q = -p_t (the pair tangent is +x). Over |x| <= 0.95a
// (the pair at the contact edge carries the normal problem's edge error) and outside
// 0.05a of every edge where the exact traction has an infinite slope (a sqrt(c - |x|)
// term): the stick edge c, and after a reversal both the new edge c' and the old c, whose
// Cattaneo term stays in the traction. A pair at distance d from such an edge is off by up
// to about mu p0 sqrt(2 c d) / a whatever the mesh (docs/contact.md), so those pairs are
// reported apart.
template <class Exact>
double max_shear_error(const std::vector<contact::PairResult>& pairs, double a, double mu_p0, Exact exact,
                       const std::vector<double>& edges, bool near_edge_only = false) {
  double worst = 0.0;
  for (const auto& pair : pairs) {
    const double r = std::abs(pair.coordinate);
    if (r > 0.95 * a) continue;
    bool near_edge = false;
    for (const double edge : edges) near_edge = near_edge || std::abs(r - edge) < 0.05 * a;
    if (near_edge != near_edge_only) continue;
    worst = std::max(worst, std::abs(-pair.p_t - exact(pair.coordinate)) / mu_p0);
  }
  return worst;
}

// The stick zone's half-width c (ContactSummary: its ends located between pairs).
double stick_half_width(const contact::ContactSummary& s) { return s.stick_radius; }

const contact::ContactInterfaceResult& only(const contact::ContactResult& result) { return result.contacts.front(); }

std::size_t step_at(const contact::ContactResult& result, double time) {
  for (std::size_t k = 0; k < result.steps.size(); ++k)
    if (std::abs(result.steps[k].time - time) < 1e-9) return k;
  throw Error("fretting case: no step ends at t = " + number_text(time));
}

// P, then Q raised to Q* = 0.3, 0.6, 0.9 mu P: c/a = sqrt(1 - Q*/mu P) within 0.02 and the
// shear within 2 % of mu p0 (max_shear_error above).
std::vector<Record> run_cattaneo_mindlin(const Context& context) {
  std::vector<Record> records;
  for (const double ratio : {0.3, 0.6, 0.9}) {
    const auto f = load_fretting(context, ratio, {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}}, 60);
    const auto result = contact::solve_contact(with_operator(context, f.file.problem), context.progress);
    const double a = f.theory.hertz.half_width();
    const std::size_t first = records.size();
    // The stick zone's half-width, its ends located between pairs (contact_summary.hpp):
    // within 1 % of Cattaneo's; at Q = 0.9 mu P the zone spans 16 pair spacings at 60
    // elements (2.2 % off), so that ratio is checked at 120 (0.4 %) below.
    const double c_over_a = stick_half_width(result.summary) / a;
    records.push_back(ratio < 0.9 ? compare_relative("c_over_a", c_over_a, f.theory.stick_ratio(f.Q_star), 0.01)
                                  : report_only("c_over_a", c_over_a, f.theory.stick_ratio(f.Q_star)));
    const double c = f.theory.stick_ratio(f.Q_star) * a;
    auto exact = [&](double x) { return f.theory.shear(x, f.Q_star); };
    records.push_back(compare_scaled("max_shear_error", max_shear_error(result.pairs, a, f.mu_p0, exact, {c}), 0.0, 1.0, 0.02));
    records.push_back(report_value("max_shear_error_at_stick_edge", max_shear_error(result.pairs, a, f.mu_p0, exact, {c}, true)));
    // Q reaches the contact whole (the shear on the cylinder, -p_t, sums to Q): the
    // boundary-element equilibrium of the cylinder, whose shortfall moves c (docs/contact.md):
    // within 0.2 %, which keeps c/a within 0.003 of its value for the whole Q (measured 0.1 %).
    records.push_back(compare_relative("tangential_force", -result.summary.tangential_force, f.Q_star, 2e-3));
    records.push_back(report_value("steps", result.steps_taken));
    tag(records, first, "cattaneo-mindlin", {{"Q_over_muP", number_text(ratio)}, {"a_over_R", number_text(kContactOverRadius)}});
    if (ratio == 0.9) {
      const int elements = 120;
      const auto fine = load_fretting(context, ratio, {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}}, elements);
      const auto r = contact::solve_contact(with_operator(context, fine.file.problem), context.progress);
      const std::size_t at = records.size();
      records.push_back(compare_relative("c_over_a", stick_half_width(r.summary) / a, f.theory.stick_ratio(f.Q_star), 0.01));
      tag(records, at, "cattaneo-mindlin", {{"Q_over_muP", number_text(ratio)}, {"contact_elements", std::to_string(elements)}});
    }
  }
  return records;
}

// The non-local law (nonlocal_friction.hpp) in Cattaneo's problem: P, then Q up to 0.6 mu P
// on the same material (Hertz's pressure whatever the shear), rho = 0.05 a and 0.2 a (each
// kernel spanning at least 8 pair spacings: 400 and 100 elements), against the independent
// solution of the half-plane's singular integral equation (reference/nonlocal_cattaneo.hpp,
// Gauss-Chebyshev, no boundary elements): the shear within 1 % of mu p0 away from the stick
// edges (max_shear_error; measured 0.29 %, 0.57 %), c/a within half a pair spacing. The conventions both share: the
// C-infinity bump of unit integral on the whole line (the zone, |x| <= 1.21 a, reaches past
// a + rho), p_n = 0 outside the contact, and Q against Hertz's P; renormalising the kernel
// over the contact instead moves c/a by a few hundredths, more than the numerics.
std::vector<Record> run_nonlocal_cattaneo(const Context& context) {
  std::vector<Record> records;
  const double ratio = 0.6;
  for (const auto& [rho_over_a, elements] : std::vector<std::pair<double, int>>{{0.05, 400}, {0.2, 100}}) {
    auto f = load_fretting(context, ratio, {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}}, elements);
    const double a = f.theory.hertz.half_width();
    f.file.problem.contacts.front().law.nonlocal_radius = rho_over_a * a;
    // Monotone loading (the slip zones only grow, each slipping the same way): equal steps
    // reach the same state as the adaptive ones, in a fraction of the steps at 400 pairs.
    f.file.problem.adaptive = false;
    f.file.problem.increments = 16;
    const auto result = contact::solve_contact(with_operator(context, f.file.problem), context.progress);
    const reference::NonlocalCattaneo exact(a, f.theory.hertz.max_pressure(), f.theory.friction, rho_over_a * a, ratio);
    const double c = exact.stick_half_width();
    const double spacing = 2.0 * f.file.parameters.at("rc") / elements;
    const std::size_t first = records.size();
    auto shear = [&](double x) { return exact.shear(x); };
    records.push_back(compare_scaled("max_shear_error", max_shear_error(result.pairs, a, f.mu_p0, shear, {c}), 0.0, 1.0, 0.01));
    records.push_back(report_value("max_shear_error_at_stick_edge", max_shear_error(result.pairs, a, f.mu_p0, shear, {c}, true)));
    records.push_back(compare_scaled("c_over_a", stick_half_width(result.summary) / a, c / a, 0.5 * spacing / a, 1.0));
    records.push_back(report_only("c_over_a_local_law", std::sqrt(1.0 - ratio), c / a));
    tag(records, first, "nonlocal-cattaneo", {{"rho_over_a", number_text(rho_over_a)}, {"contact_elements", std::to_string(elements)}});
  }
  return records;
}

// P, then Q up to Q* = 0.6 mu P, down to -Q* and back up (one cycle): at Q = 0 and at
// Q = -Q* the shear against Mindlin-Deresiewicz (2 % of mu p0) and the reversal stick
// zone c'/a (0.02); the loop closes (the state at the end of the cycle is the one at its
// start: shear within 0.5 % of mu p0, the tangential motion within 0.5 %); the energy
// dissipated over the cycle against the half-plane result (docs/contact.md).
std::vector<Record> run_mindlin_unloading(const Context& context) {
  std::vector<Record> records;
  const double ratio = 0.6;
  const auto f = load_fretting(context, ratio,
                               {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}, {2.5, 0.0}, {3.0, -1.0}, {3.5, 0.0}, {4.0, 1.0}}, 60);
  const auto result = contact::solve_contact(with_operator(context, f.file.problem), context.progress);
  const auto& contact = only(result);
  const double a = f.theory.hertz.half_width();
  for (const double Q_over : {0.0, -1.0}) {
    const std::size_t k = step_at(result, Q_over == 0.0 ? 2.5 : 3.0);
    const double Q = Q_over * f.Q_star;
    const std::size_t first = records.size();
    const double c = f.theory.reversal_stick_ratio(f.Q_star, Q) * a;
    auto exact = [&](double x) { return f.theory.unloading_shear(x, f.Q_star, Q); };
    const std::vector<double> edges = {c, f.theory.stick_ratio(f.Q_star) * a};
    records.push_back(compare_scaled("max_shear_error", max_shear_error(contact.step_pairs[k], a, f.mu_p0, exact, edges), 0.0, 1.0, 0.02));
    records.push_back(report_value("max_shear_error_at_stick_edge",
                                   max_shear_error(contact.step_pairs[k], a, f.mu_p0, exact, edges, true)));
    // c'/a at Q = 0 spans 2 x 21 pair spacings at 60 elements (1.4 % off; checked at 120 below).
    const double reversal = stick_half_width(contact.steps[k]) / a, expected = f.theory.reversal_stick_ratio(f.Q_star, Q);
    records.push_back(Q_over == 0.0 ? report_only("reversal_c_over_a", reversal, expected)
                                    : compare_relative("reversal_c_over_a", reversal, expected, 0.01));
    tag(records, first, "mindlin-unloading", {{"Q_over_Qstar", number_text(Q_over)}, {"Q_star_over_muP", number_text(ratio)}});
  }
  {
    // Unloading from Q* to 0 at 120 elements: c'/a within 1 % (measured 0.05 %).
    const auto fine = load_fretting(context, ratio, {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}, {2.5, 0.0}}, 120);
    const auto r = contact::solve_contact(with_operator(context, fine.file.problem), context.progress);
    const std::size_t first = records.size();
    records.push_back(compare_relative("reversal_c_over_a", stick_half_width(r.summary) / a,
                                       f.theory.reversal_stick_ratio(f.Q_star, 0.0), 0.01));
    tag(records, first, "mindlin-unloading",
        {{"Q_over_Qstar", "0"}, {"Q_star_over_muP", number_text(ratio)}, {"contact_elements", "120"}});
  }
  const std::size_t start = step_at(result, 2.0), end = step_at(result, 4.0);
  double loop = 0.0;
  for (std::size_t i = 0; i < contact.step_pairs[end].size(); ++i)
    loop = std::max(loop, std::abs(contact.step_pairs[end][i].p_t - contact.step_pairs[start][i].p_t) / f.mu_p0);
  const double q_motion_start = result.records[start].motions[1], q_motion_end = result.records[end].motions[1];
  const double energy = contact.steps[end].dissipated_energy - contact.steps[start].dissipated_energy;
  const std::size_t first = records.size();
  records.push_back(compare_scaled("loop_shear_difference", loop, 0.0, 1.0, 5e-3));
  records.push_back(compare_relative("loop_tangential_motion", q_motion_end, q_motion_start, 5e-3));
  records.push_back(compare_relative("dissipated_energy_per_cycle", energy, f.theory.dissipated_energy_per_cycle(f.Q_star), 0.03));
  records.push_back(report_value("steps", result.steps_taken));
  tag(records, first, "mindlin-unloading", {{"Q_star_over_muP", number_text(ratio)}, {"cycle", "Q* -> -Q* -> Q*"}});
  return records;
}

// P, then Q = 0.5 mu P and a bulk stress sigma_B = 0.396 mu p0 in the block together
// (examples/fretting_bulk_stress.toml, a/R = 0.00125, 120 elements per zone): the stick zone
// keeps c/a = sqrt(1 - Q/(mu P)) (within 1 %) and moves by e/a = sigma_B / (4 mu p0) (Nowell
// and Hills; within 0.005: a quarter of the pair spacing, the ends being located between
// pairs; measured 0.25 % and 0.0017).
std::vector<Record> run_nowell_hills(const Context& context) {
  const double scale = kScale;
  const auto file = load_contact_example(context, "fretting_bulk_stress.toml",
                                          {{"P", 148.0 * scale * scale}, {"rc", 0.085 * scale},
                                           {"sigma_B", 160.0 * scale}, {"n", 120.0}});
  const auto& problem = file.problem;
  const double P = -problem.forces.at(0).force, Q = problem.forces.at(1).force, R = file.parameters.at("R");
  reference::PartialSlipLine theory;
  theory.hertz = {P, R, reference::contact_modulus(problem.elastic(0).material, problem.elastic(1).material, problem.analysis)};
  theory.friction = problem.contacts.front().law.friction;
  const double a = theory.hertz.half_width(), mu_p0 = theory.friction * theory.hertz.max_pressure();
  const double sigma_B = file.parameters.at("sigma_B");
  const auto result = contact::solve_contact(with_operator(context, problem), context.progress);
  std::vector<Record> records;
  records.push_back(compare_scaled("e_over_a", result.summary.stick_offset / a, sigma_B / (4.0 * mu_p0), 1.0, 0.005));
  records.push_back(compare_relative("c_over_a", result.summary.stick_radius / a, theory.stick_ratio(Q), 0.01));
  records.push_back(report_value("steps", result.steps_taken));
  tag(records, 0, "nowell-hills", {{"Q_over_muP", number_text(Q / (theory.friction * P))}, {"sigma_B_over_4mup0", number_text(sigma_B / (4.0 * mu_p0))}});
  return records;
}

}  // namespace

std::vector<Case> fretting_cases() {
  return {
      {"nonlocal-cattaneo", "Oden-Pires 1983", "Cattaneo with the non-local law against an independent Gauss-Chebyshev solution",
       run_nonlocal_cattaneo},
      {"cattaneo-mindlin", "Johnson 7.2", "cylinder on a block, P then monotone Q: stick zone and shear traction",
       run_cattaneo_mindlin},
      {"mindlin-unloading", "Johnson 7.2", "P then a cycle of Q: reversal slip, loop closure, energy per cycle",
       run_mindlin_unloading},
      {"nowell-hills", "Nowell-Hills 1987", "P then Q with a bulk stress in the block: the stick zone's offset",
       run_nowell_hills},
  };
}

}  // namespace bemcontact::validation

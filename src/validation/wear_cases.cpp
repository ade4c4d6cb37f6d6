// Archard wear over repeated load cycles (contact/wear.hpp): the bookkeeping of the worn
// volume, the steady state of a rigid punch in gross slip, cycle jumping against computing
// every cycle, and partial slip's unworn stick zone.
#include <algorithm>
#include <cmath>
#include <string>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/pairing.hpp"
#include "bemcontact/validation/case_groups.hpp"
#include "bemcontact/validation/contact_support.hpp"

namespace bemcontact::validation {
namespace {

// examples/wear_punch_gross_slip.toml with n elements under the punch, k, N cycles and a
// fixed cycle jump (0: adaptive).
io::ContactFile punch_wear(const Context& context, int n, double k, long cycles, long jump) {
  auto file = load_contact_example(context, "wear_punch_gross_slip.toml",
                                   {{"n", n}, {"k", k}, {"N", static_cast<double>(cycles)}});
  auto& problem = file.problem;
  problem.drop_interior_points();
  problem.cycles.fixed_jump = jump;
  return file;
}

// The largest difference between two scars' depths (side 1), over the deeper scar's depth.
double depth_difference(const contact::WearCycle& a, const contact::WearCycle& b) {
  double difference = 0.0, deepest = 0.0;
  for (std::size_t i = 0; i < a.depth1.size(); ++i) {
    difference = std::max(difference, std::abs(a.depth1[i] - b.depth1[i]));
    deepest = std::max({deepest, a.depth1[i], b.depth1[i]});
  }
  return difference / deepest;
}

// (i) Each step's worn volume against k sum_i w_i p_i |ds_i| from the step's own pair results
// (the pairs' weights from the pairing, their pressures and tangential jumps), over three
// computed cycles (the first steps after a jump carry it: tests/unit/contact/test_wear.cpp
// checks the jump), to 1e-10: the sums are the same in another order.
std::vector<Record> run_wear_bookkeeping(const Context& context) {
  std::vector<Record> records;
  const double k = 1e-8;
  auto file = punch_wear(context, 20, k, 12, 10);  // cycles 1, 11 (a jump of 10) and 12
  file.problem.record_steps = true;
  const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
  const auto weights = contact::prepare_contact(file.problem).contacts.front().pairs;
  const auto& contact = result.contacts.front();
  double worst = 0.0, scale = 0.0;
  for (std::size_t s = 1; s < contact.steps.size(); ++s) {
    // The jump of 10 cycles is made between the first cycle's end (t = 4) and the next step.
    const bool jumped = std::abs(contact.steps[s - 1].time - 4.0) < 1e-9;
    double expected = 0.0;
    for (std::size_t i = 0; i < weights.size(); ++i)
      expected += k * weights[i].weight * std::max(0.0, -contact.step_pairs[s][i].p_n) *
                  std::abs(contact.step_pairs[s][i].jump_t - contact.step_pairs[s - 1][i].jump_t);
    if (jumped) continue;
    const double computed = contact.steps[s].worn_volume1 - contact.steps[s - 1].worn_volume1;
    worst = std::max(worst, std::abs(computed - expected));
    scale = std::max(scale, expected);
  }
  records.push_back(compare_scaled("step_worn_volume_error", worst / scale, 0.0, 1.0, 1e-10));
  records.push_back(report_value("cycles", static_cast<double>(contact.wear.back().cycle)));
  tag(records, 0, "archard-wear", {{"check", "worn volume bookkeeping"}, {"contact_elements", "20"}});
  return records;
}

// (ii) The rigid punch in reciprocating gross slip (coupling off: the shear does not tilt the
// pressure), 10^5 cycles at k = 1e-8: the pressure tends to the uniform P / 2a that wears the
// face alike (within 2 % for |x| < 0.9 a; measured 0.37 %), and the peak pressure falls
// cycle after cycle until it is within 1 % of it (past that the profile settles, the peak
// moving to the centre by 0.2 %). (iii) 1 500 cycles at k = 2e-8 with every cycle computed,
// and with jumps of 10 and 100 cycles: the scars agree within 1 % of their depth at 100
// (forward Euler in the cycle count: first order, the difference grows like ΔN - 1, which
// the observed order checks; measured 0.06 % and 0.83 % on 40 elements, order 1.10).
std::vector<Record> run_punch_wear(const Context& context) {
  std::vector<Record> records;
  {
    const auto file = punch_wear(context, 40, 1e-8, 100000, 0);
    const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
    const auto& contact = result.contacts.front();
    const double a = file.parameters.at("a"), uniform = file.parameters.at("P") / (2.0 * a);
    double worst = 0.0;
    for (const auto& pair : contact.pairs)
      if (std::abs(pair.coordinate) < 0.9 * a) worst = std::max(worst, std::abs(-pair.p_n - uniform) / uniform);
    double rises = 0.0;  // the largest rise of the peak while it is more than 1 % above uniform
    for (std::size_t c = 1; c < contact.wear.size(); ++c)
      if (contact.wear[c - 1].summary.peak_pressure > 1.01 * uniform)
        rises = std::max(rises, contact.wear[c].summary.peak_pressure - contact.wear[c - 1].summary.peak_pressure);
    records.push_back(compare_scaled("pressure_deviation_from_uniform", worst, 0.0, 1.0, 0.02));
    records.push_back(compare_scaled("peak_pressure_rise", rises / uniform, 0.0, 1.0, 0.0));
    records.push_back(report_value("peak_pressure_cycle_1_over_uniform", contact.wear.front().summary.peak_pressure / uniform));
    records.push_back(report_value("computed_cycles", static_cast<double>(contact.wear.back().computed)));
    tag(records, 0, "archard-wear", {{"check", "punch steady state"}, {"cycles", "100000"}});
  }
  std::vector<contact::WearCycle> scars;
  for (const long jump : {1L, 10L, 100L}) {
    const auto file = punch_wear(context, 40, 2e-8, 1500, jump);
    const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
    scars.push_back(result.contacts.front().wear.back());
  }
  const std::size_t first = records.size();
  const double d10 = depth_difference(scars[1], scars[0]), d100 = depth_difference(scars[2], scars[0]);
  records.push_back(compare_scaled("scar_difference_jump_10", d10, 0.0, 1.0, 0.01));
  records.push_back(compare_scaled("scar_difference_jump_100", d100, 0.0, 1.0, 0.01));
  records.push_back(compare_scaled("order_in_jump", std::log(d100 / d10) / std::log(99.0 / 9.0), 1.0, 1.0, 0.2));
  tag(records, first, "archard-wear", {{"check", "cycle jumping"}, {"cycles", "1500"}});
  return records;
}

// (iv) examples/fretting_wear.toml (partial slip, wear on both bodies) over 10^4 cycles: the
// pairs inside the stick zone of every computed cycle never slip, so the cycles after the
// first do not wear them (their
// depth below 1e-9 of the deepest: round-off of the stick condition; measured 2e-13). The
// outermost stick pairs, within a pair spacing of the stick edges, are reported apart: the
// edges lie between pairs and may move by a fraction of a spacing within a cycle, so those
// pairs could slip a little in some steps (measured 1.6e-11 of the deepest). The mean pressure
// over the first cycle's slip annuli falls from one computed cycle to the next.
std::vector<Record> run_partial_slip_wear(const Context& context) {
  auto file = load_contact_example(context, "fretting_wear.toml", {{"N", 10000.0}});
  file.problem.drop_interior_points();
  const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
  const auto& wear = result.contacts.front().wear;
  double stick_start = -1e300, stick_end = 1e300, deepest = 0.0;
  for (const auto& w : wear) {
    stick_start = std::max(stick_start, w.summary.stick_start);
    stick_end = std::min(stick_end, w.summary.stick_end);
    for (const double h : w.depth1) deepest = std::max(deepest, h);
  }
  const auto& last = wear.back();
  double spacing = 1e300;
  for (std::size_t i = 1; i < last.pairs.size(); ++i)
    spacing = std::min(spacing, std::abs(last.pairs[i].coordinate - last.pairs[i - 1].coordinate));
  double in_stick = 0.0, at_stick_edge = 0.0;
  for (std::size_t i = 0; i < last.pairs.size(); ++i) {
    // What the repeated cycles wore (the first loading slips a little at a/R = 0.07: 9e-10 at
    // 0.95 c, where the cylinder's curvature couples the pressure into the tangential jump).
    const double x = last.pairs[i].coordinate;
    const double depth = std::max(last.depth1[i] - wear.front().depth1[i], last.depth2[i] - wear.front().depth2[i]);
    if (x > stick_start + spacing && x < stick_end - spacing) in_stick = std::max(in_stick, depth);
    else if (x > stick_start && x < stick_end) at_stick_edge = std::max(at_stick_edge, depth);
  }
  // The first cycle's annuli: in contact and slipping at its end.
  const auto& first = wear.front();
  std::vector<std::size_t> annuli;
  for (std::size_t i = 0; i < first.pairs.size(); ++i)
    if (first.pairs[i].status == contact::PairStatus::slip) annuli.push_back(i);
  double rises = 0.0, previous = 0.0;
  for (std::size_t c = 0; c < wear.size(); ++c) {
    double mean = 0.0;
    for (const auto i : annuli) mean -= wear[c].pairs[i].p_n / static_cast<double>(annuli.size());
    if (c > 0) rises = std::max(rises, mean - previous);
    previous = mean;
  }
  double first_mean = 0.0;
  for (const auto i : annuli) first_mean -= first.pairs[i].p_n / static_cast<double>(annuli.size());
  std::vector<Record> records;
  records.push_back(compare_scaled("stick_zone_depth_over_deepest", in_stick / deepest, 0.0, 1.0, 1e-9));
  records.push_back(report_value("stick_edge_pair_depth_over_deepest", at_stick_edge / deepest));
  records.push_back(compare_scaled("annuli_pressure_rise", rises / first_mean, 0.0, 1.0, 0.0));
  records.push_back(report_value("annuli_pressure_drop", 1.0 - previous / first_mean));
  records.push_back(report_value("stick_zone_width", stick_end - stick_start));
  records.push_back(report_value("computed_cycles", static_cast<double>(last.computed)));
  tag(records, 0, "archard-wear", {{"check", "partial slip"}, {"cycles", "10000"}});
  return records;
}

std::vector<Record> run_archard_wear(const Context& context) {
  auto records = run_wear_bookkeeping(context);
  for (auto part : {run_punch_wear(context), run_partial_slip_wear(context)})
    records.insert(records.end(), part.begin(), part.end());
  return records;
}

}  // namespace

std::vector<Case> wear_cases() {
  return {{"archard-wear", "Archard 1953", "fretting wear: worn volume, a punch's steady state, cycle jumping, partial slip",
           run_archard_wear}};
}

}  // namespace bemcontact::validation

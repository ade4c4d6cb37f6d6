#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/contact/plastic_coupling.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <cmath>
#include <optional>
#include <limits>
#include <sstream>
#include <utility>

#include "bemcontact/bem/postprocess.hpp"
#include "bemcontact/bem/resultants.hpp"
#include "bemcontact/contact/contact_summary.hpp"
#include "bemcontact/contact/nonlocal_friction.hpp"
#include "bemcontact/contact/step_solvers.hpp"
#include "bemcontact/contact/wear.hpp"
#include "bemcontact/contact/zone_ends.hpp"
#include "bemcontact/contact/zone_refinement.hpp"
#include "bemcontact/core/error.hpp"

namespace bemcontact::contact {

const char* to_string(PairStatus status) {
  switch (status) {
    case PairStatus::open: return "open";
    case PairStatus::stick: return "stick";
    case PairStatus::slip: return "slip";
  }
  return "?";
}
const char* to_string(Algorithm algorithm) { return algorithm == Algorithm::newton ? "newton" : "thesis"; }
const char* to_string(ContactKind kind) {
  switch (kind) {
    case ContactKind::bilateral: return "bilateral";
    case ContactKind::unilateral: return "unilateral";
    case ContactKind::compliant: return "compliant";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The law of every pair: its contact's (`groups`: the pair offsets of the contacts), or,
// when the groups are not the problem's contacts (a model of its own, such as the
// half-space model), the one contact's law for all pairs.
struct PairLaws {
  std::vector<ContactKind> kind;
  Vector friction;
  std::vector<NormalCompliance> compliance;
  MollifierRows mollifier;  // the non-local contacts' pairs (nonlocal_friction.hpp); empty: none
  WearCoefficients wear;    // Archard's k of each side per pair (wear.hpp)
  // The slip threshold g of pair i at its pressure |p_n| = measure: beta |p_n|, or beta c_t
  // pen^m_t for a compliant pair (NormalCompliance::threshold).
  double threshold(Index i, double measure) const {
    const auto k = static_cast<std::size_t>(i);
    return kind[k] == ContactKind::compliant ? friction[i] * compliance[k].threshold(measure) : friction[i] * measure;
  }
};
PairLaws pair_laws(const ContactProblem& problem, const std::vector<Index>& groups) {
  const Index n = groups.back();
  const ContactLaw all = problem.contacts.size() == 1 ? problem.contacts.front().law : ContactLaw{};
  const auto count = static_cast<std::size_t>(n);
  PairLaws laws{std::vector<ContactKind>(count, all.kind), Vector::Constant(n, all.friction),
                std::vector<NormalCompliance>(count, all.compliance), {},
                {Vector::Constant(n, all.wear_coefficient1), Vector::Constant(n, all.wear_coefficient2)}};
  if (groups.size() != problem.contacts.size() + 1) return laws;
  for (std::size_t c = 0; c < problem.contacts.size(); ++c)
    for (Index i = groups[c]; i < groups[c + 1]; ++i) {
      const auto& law = problem.contacts[c].law;
      laws.kind[static_cast<std::size_t>(i)] = law.kind;
      laws.friction[i] = law.friction;
      laws.compliance[static_cast<std::size_t>(i)] = law.compliance;
      laws.wear.side1[i] = law.wear_coefficient1;
      laws.wear.side2[i] = law.wear_coefficient2;
    }
  return laws;
}

// Laws where a pair may open (unilateral, compliant) rather than hold (bilateral).
bool may_open(ContactKind kind) { return kind != ContactKind::bilateral; }

// The part of each pair's interference applied at pseudo-time t (its contact's amplitude):
// the solver carries it in the jump w (ContactModel's loads), the results in the gap.
Vector interference_at(const std::vector<ContactPair>& pairs, const ContactProblem& problem,
                       const std::vector<Index>& groups, double t) {
  Vector out = Vector::Zero(static_cast<Index>(pairs.size()));
  if (groups.size() != problem.contacts.size() + 1) return out;
  for (std::size_t c = 0; c < problem.contacts.size(); ++c)
    for (Index i = groups[c]; i < groups[c + 1]; ++i)
      out[i] = pairs[static_cast<std::size_t>(i)].interference * problem.contacts[c].interference_amplitude.at(t);
  return out;
}

// Results of the pairs [first, first + pairs.size()) of `laws`, `interference` and `wear`
// (the worn depths of both sides; empty: none). The reported gap is the initial gap less
// the interference applied so far plus the wear, and jump_n the relative displacement
// [u]·n itself: closed pairs have jump_n = gap (docs/contact.md).
std::vector<PairResult> pair_results(const std::vector<ContactPair>& pairs, const StepOutput& step,
                                     const PairLaws& laws, const Vector& interference, Index first,
                                     const Vector& wear = {}) {
  // A pressure below 1e-12 of the step's largest, or of the residual's floor (a history
  // unloaded to 0: its pressures are round-off), is an open pair's.
  double scale = step.pressure_floor;
  for (Index i = 0; i < static_cast<Index>(pairs.size()); ++i) scale = std::max(scale, std::abs(step.x[2 * i]));
  const bool side_face = zone_faces_sideways(pairs);
  std::vector<PairResult> out;
  for (Index i = 0; i < static_cast<Index>(pairs.size()); ++i) {
    PairResult r;
    r.position = pairs[i].position1;
    r.coordinate = side_face ? pairs[i].position1.y() : pairs[i].position1.x();
    r.normal = pairs[i].normal;
    r.gap = pairs[i].gap - interference[first + i] + (wear.size() > 0 ? wear[first + i] : 0.0);
    const double lambda = step.x[2 * i];
    r.p_n = 0.0 - lambda;  // +0 for an open pair
    r.p_t = step.x[2 * i + 1];
    r.jump_n = step.w[2 * i] - interference[first + i];
    r.jump_t = step.w[2 * i + 1];
    const double friction = laws.friction[first + i];
    double measure = std::abs(lambda);
    if (!laws.mollifier.empty() && !laws.mollifier[static_cast<std::size_t>(first + i)].empty())
      // the mollified |p_n| (step.x holds this group's pairs from `first` on)
      measure = mollified(laws.mollifier[static_cast<std::size_t>(first + i)],
                          [&](Index j) { return std::abs(step.x[2 * (j - first)]); });
    const double g = laws.threshold(first + i, measure);
    r.slip_ratio = g > 0.0 ? std::abs(r.p_t) / g : 0.0;
    const bool open = may_open(laws.kind[static_cast<std::size_t>(first + i)]) && lambda <= 1e-12 * scale;
    if (open) r.status = PairStatus::open;
    else if (friction == 0.0 || pairs[i].on_axis) r.status = friction == 0.0 ? PairStatus::slip : PairStatus::stick;
    // Slip within 1e-3 of the threshold: the thesis algorithm meets |p_t| = g only to the
    // accuracy of its stopping tests (xi, sqrt(xi) for g).
    else r.status = r.slip_ratio >= 1.0 - 1e-3 ? PairStatus::slip : PairStatus::stick;
    out.push_back(r);
  }
  return out;
}

ContactSummary summarise(const std::vector<ContactPair>& geometry, const std::vector<PairResult>& pairs,
                         const StepOutput& step, double load, bool half_model, const ContactSummary* previous,
                         double edge_power) {
  ContactSummary s = summarise_pairs(geometry, pairs, half_model, previous, edge_power);
  s.time = load;
  s.approach = 0.0;  // set by the caller (the force load's motion)
  s.residual = step.residual;
  s.newton_iterations = step.newton_iterations;
  s.kalker_iterations = step.kalker_iterations;
  s.threshold_iterations = step.threshold_iterations;
  s.gmres_cycles = step.gmres_cycles;
  s.matrix_free_products = step.krylov_iterations;
  return s;
}

// The force loads whose sign pulls their body away from every contact it has along the
// load's direction (a contact in compression cannot carry them), as a hint appended to a
// solver failure; empty when none does.
std::string pulling_loads_hint(const ContactModel& model) {
  const auto& problem = model.problem();
  std::string hint;
  for (const auto& load : problem.forces) {
    if (load.component > 1 || load.force == 0.0) continue;
    bool faces_a_contact = false, pulls_from_all = true;
    std::string contacts;
    for (std::size_t c = 0; c < problem.contacts.size(); ++c) {
      const auto& contact = problem.contacts[c];
      const int side = contact.side1.body == load.body ? 1 : contact.side2.body == load.body ? 2 : 0;
      if (side == 0) continue;
      Vec2 normal = Vec2::Zero();  // body 1 toward body 2
      for (Index g = model.pair_offset(c); g < model.pair_offset(c + 1); ++g) normal += model.pairs()[g].normal;
      if (normal.norm() == 0.0) continue;
      // The direction that presses this body on the other side.
      const double toward = (side == 1 ? 1.0 : -1.0) * normal.normalized()[load.component];
      if (std::abs(toward) < 0.5) continue;  // the load runs along this contact
      faces_a_contact = true;
      pulls_from_all = pulls_from_all && load.force * toward < 0.0;
      contacts += (contacts.empty() ? "'" : ", '") + contact.name + "'";
    }
    if (!faces_a_contact || !pulls_from_all) continue;
    std::ostringstream text;
    text.precision(6);
    text << ". Load '" << load.name << "' (force " << load.force << " along " << (problem.analysis == AnalysisType::axisymmetric ? (load.component == 0 ? "r" : "z")
                                                                                             : (load.component == 0 ? "x" : "y"))
         << ") pulls body '" << problem.bodies[static_cast<std::size_t>(load.body)].name << "' away from contact "
         << contacts << ": a contact in compression cannot carry it; reverse its sign to press the bodies together";
    hint += text.str();
  }
  return hint;
}

// Stops a run whose unilateral contact reaches a smooth end of its zone (zone_ends.hpp).
void check_zones_not_clipped(const ContactModel& model, const std::vector<PairStatus>& state, int step, double time) {
  const auto& problem = model.problem();
  const bool axisymmetric = problem.analysis == AnalysisType::axisymmetric;
  for (std::size_t c = 0; c < problem.contacts.size(); ++c) {
    const auto& contact = model.prepared().contacts[c];
    if (contact.smooth_ends.empty() || !may_open(problem.contacts[c].law.kind)) continue;
    const bool side_face = zone_faces_sideways(contact.pairs);
    std::vector<bool> in_contact;
    std::vector<double> coordinate;
    for (std::size_t i = 0; i < contact.pairs.size(); ++i) {
      in_contact.push_back(state[static_cast<std::size_t>(model.pair_offset(c)) + i] != PairStatus::open);
      coordinate.push_back(side_face ? contact.pairs[i].position1.y() : contact.pairs[i].position1.x());
    }
    const std::string axis = side_face ? (axisymmetric ? "z" : "y") : (axisymmetric ? "r" : "x");
    const std::string message =
        clipped_zone_message(problem.contacts[c].name, contact, in_contact, coordinate, axis, step, time);
    if (!message.empty()) throw SolverError(message, {"contact zone", -1, -1.0, step, time});
  }
}

void check_history_options(const ContactProblem& problem) {
  if (problem.increments < 1) throw Error("contact: the number of load increments must be >= 1");
  if (!(problem.end_time > 0.0)) throw Error("contact: the history's end_time must be > 0");
  if (problem.max_steps < problem.increments) throw Error("contact: max_steps must be >= increments");
  const auto& cycles = problem.cycles;
  if (cycles.repeated() && !(cycles.start >= 0.0 && cycles.start < problem.end_time))
    throw Error("contact: the repeated cycle must start in [0, end_time)");
  if (cycles.repeated() && (cycles.max_jump < 1 || cycles.fixed_jump < 0 || !(cycles.max_pressure_change > 0.0)))
    throw Error("contact: cycle jumps must be >= 1 and max_pressure_change > 0");
  for (const auto& contact : problem.contacts)
    if (!(contact.law.friction >= 0.0)) throw Error("contact '" + contact.name + "': the friction coefficient must be >= 0");
}

std::string format_residual(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

}  // namespace

namespace {

void add_iterations(ContactSummary& totals, const StepOutput& step) {
  totals.newton_iterations += step.newton_iterations;
  totals.kalker_iterations += step.kalker_iterations;
  totals.threshold_iterations += step.threshold_iterations;
  totals.gmres_cycles += step.gmres_cycles;
  totals.matrix_free_products += step.krylov_iterations;
}

// Records one step in a result of pairs [first, last).
void record_step(ContactInterfaceResult& out, const std::vector<ContactPair>& pairs, const StepOutput& step,
                 const ContactProblem& problem, const PairLaws& laws, const Vector& interference,
                 const WearDepths& wear, double load, double approach, Index first, Index last, bool half_model) {
  const std::vector<ContactPair> group(pairs.begin() + first, pairs.begin() + last);
  StepOutput part = step;
  part.x = step.x.segment(2 * first, 2 * (last - first));
  part.w = step.w.segment(2 * first, 2 * (last - first));
  const bool worn = wear.side1.size() > 0;
  out.pairs = pair_results(group, part, laws, interference, first, worn ? wear.total() : Vector());
  const ContactSummary* previous = out.steps.empty() ? nullptr : &out.steps.back();
  const auto law = static_cast<std::size_t>(first);
  const double edge_power = first < last && laws.kind[law] == ContactKind::compliant
                                ? 1.0 / laws.compliance[law].exponent
                                : 2.0;
  const ContactSummary summary = summarise(group, out.pairs, part, load, half_model, previous, edge_power);
  out.steps.push_back(summary);
  out.steps.back().approach = approach;
  if (worn) {
    out.steps.back().worn_volume1 = worn_volume(pairs, wear.side1, first, last);
    out.steps.back().worn_volume2 = worn_volume(pairs, wear.side2, first, last);
  }
  if (problem.record_steps) out.step_pairs.push_back(out.pairs);
}

void finish(ContactInterfaceResult& out, const ContactSummary& totals) {
  out.summary = out.steps.back();
  out.summary.newton_iterations = totals.newton_iterations;
  out.summary.kalker_iterations = totals.kalker_iterations;
  out.summary.threshold_iterations = totals.threshold_iterations;
  out.summary.gmres_cycles = totals.gmres_cycles;
  out.summary.matrix_free_products = totals.matrix_free_products;
}

}  // namespace

namespace {

// The step ends the history must hit: every amplitude's corners in (0, end].
std::vector<double> history_corners(const CondensedProblem& condensed, double end) {
  std::vector<double> corners{end};
  auto add = [&](const Amplitude& amplitude) {
    for (const double t : amplitude.corners())
      if (t > 0.0 && t < end) corners.push_back(t);
  };
  for (const auto& load : condensed.loads) add(load.amplitude);
  for (Index k = 0; k < condensed.motions; ++k)
    if (condensed.force[k] != 0.0) add(condensed.force_amplitude[k]);
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end(), [end](double a, double b) { return b - a <= 1e-12 * end; }),
                corners.end());
  return corners;
}

// Pairs whose state (open / stick / slip) differs between two solutions, per group.
int state_changes(const std::vector<PairStatus>& before, const std::vector<PairStatus>& after, Index first,
                  Index last) {
  int changes = 0;
  for (Index i = first; i < last; ++i) changes += before[i] != after[i];
  return changes;
}

std::vector<PairStatus> statuses(const std::vector<ContactPair>& pairs, const StepOutput& step, const PairLaws& laws) {
  std::vector<PairStatus> out;
  for (const auto& r : pair_results(pairs, step, laws, Vector::Zero(static_cast<Index>(pairs.size())), 0))
    out.push_back(r.status);
  return out;
}

// What every step of a load history reads: the condensed problem, its pairs, their laws
// and groups.
struct HistoryData {
  const CondensedProblem& condensed;
  const std::vector<ContactPair>& pairs;
  const ContactProblem& problem;
  const std::vector<Index>& groups;   // the contacts' pair offsets, as given
  std::vector<Index> all_groups;      // those, or one group of every pair
  PairLaws laws;
  // The last Newton system's factors, reused while the active sets repeat (step_solvers.hpp).
  std::unique_ptr<NewtonSystemCache> newton_cache = std::make_unique<NewtonSystemCache>();
  // An elastoplastic region in contact: it solves each step (plastic_coupling.hpp); null: none.
  PlasticCoupling* coupling = nullptr;
};

HistoryData history_data(const CondensedProblem& condensed, const std::vector<ContactPair>& pairs,
                         const ContactProblem& problem, const std::vector<Index>& groups, PlasticCoupling* coupling) {
  std::vector<Index> all_groups = groups.size() > 1 ? groups : std::vector<Index>{0, condensed.pairs};
  PairLaws laws = pair_laws(problem, all_groups);
  if (all_groups.size() == problem.contacts.size() + 1)
    for (std::size_t c = 0; c < problem.contacts.size(); ++c)
      if (problem.contacts[c].law.nonlocal_radius > 0.0)
        add_mollifier_rows(pairs, all_groups[c], all_groups[c + 1], problem.contacts[c].law.nonlocal_radius,
                           laws.mollifier);
  return {condensed, pairs, problem, groups, std::move(all_groups), std::move(laws), std::make_unique<NewtonSystemCache>(),
          coupling};
}

// What a history carries from step to step; copied to undo a cycle jump.
struct HistoryRun {
  StepInput previous;  // the last accepted step, as the next one's start (its gap worn)
  std::vector<PairStatus> state;
  StepOutput step;
  ContactSummary totals;
  Vector dissipated;   // per group
  WearDepths wear;     // empty without wear; its slip path since the cycle started
  std::vector<double> step_ends;  // the last stretch's accepted steps (a repeated cycle's plan)
  int taken = 0;
  // The last accepted steps since the loads last turned (a corner of their amplitudes, the
  // start of a stretch), at most two: the next step starts on the line through them
  // (predicted_start).
  struct Point {
    double t = 0.0;
    Vector x, delta, product;  // product: M x
  };
  std::vector<Point> line;
  int predicted_in_a_row = 0;  // steps taken as predicted, with no Newton iteration
};

// The state before the first step: no force, no jump, every pair open, nothing worn.
HistoryRun history_start(const HistoryData& data) {
  const Index n = data.condensed.pairs;
  HistoryRun run;
  StepInput& start = run.previous;
  start = step_input(data.condensed, 0.0);
  start.kind = data.laws.kind;
  start.friction = data.laws.friction;
  start.compliance = data.laws.compliance;
  if (!data.laws.mollifier.empty()) start.mollifier = &data.laws.mollifier;
  start.previous_tangential_jump = Vector::Zero(n);
  start.x_start = Vector::Zero(2 * n);
  start.delta_start = Vector::Zero(data.condensed.motions);
  run.state.assign(static_cast<std::size_t>(n), PairStatus::open);
  run.step.x = Vector::Zero(2 * n);
  run.step.delta = Vector::Zero(data.condensed.motions);
  run.dissipated = Vector::Zero(static_cast<Index>(data.all_groups.size()) - 1);
  if (data.laws.wear.any()) {
    run.wear = {Vector::Zero(n), Vector::Zero(n), Vector::Zero(n)};
  }
  return run;
}

// Between two corners of the amplitudes the loads are affine in t, and so is the solution
// while no pair changes state (the Newton system's matrix is the state's, its right-hand side
// affine in t). The next step's Newton iteration therefore starts on the line through the last
// two steps, its first active sets those of that point instead of the last step's: a step in
// which one pair changes state then takes one iteration, not two (the first solving with the
// old sets, the second with the new). The product M x of the start is the same line's through
// theirs. The semi-smooth Newton route alone (the thesis algorithm and the plastic coupling
// start from the last step).
//
// A step in which no pair changes state is then the point of the line itself: its residual
// (no product, no solve) meets the tolerance and it is taken as it stands. Round-off grows
// along such points (as k^2 eps after k of them: each is an extrapolation of the last two),
// so every kMostPredicted-th step is solved again.
constexpr int kMostPredicted = 16;

void predicted_start(const HistoryData& data, const HistoryRun& run, double t_next, StepInput& input) {
  const auto& line = run.line;
  if (line.size() < 2 || data.coupling || data.problem.solver.algorithm != Algorithm::newton) return;
  input.start_may_solve = run.predicted_in_a_row < kMostPredicted;
  const auto &a = line[0], &b = line[1];
  const double rate = (t_next - b.t) / (b.t - a.t);
  input.x_start = b.x + rate * (b.x - a.x);
  input.delta_start = b.delta + rate * (b.delta - a.delta);
  input.product_start = b.product + rate * (b.product - a.product);
  input.state_start.clear();
}

// The accepted step at t as a point of the line (predicted_start), after a corner of the
// amplitudes its first.
void add_to_line(const HistoryData& data, const StepOutput& step, double t, bool at_corner, HistoryRun& run) {
  const auto& condensed = data.condensed;
  if (at_corner) run.line.clear();
  if (run.line.size() == 2) run.line.erase(run.line.begin());
  Vector product = step.w - condensed.jump_at(t);
  if (condensed.motions > 0) product -= condensed.b * step.delta;
  run.line.push_back({t, step.x, step.delta, std::move(product)});
}

// The step to t_next, from the solution at the end of the previous step.
StepOutput solve_step(const HistoryData& data, const StepInput& previous, double t_next,
                      const HistoryRun* run = nullptr) {
  StepInput input = step_input(data.condensed, t_next);
  input.gap = previous.gap;
  input.kind = data.laws.kind;
  input.friction = data.laws.friction;
  input.compliance = data.laws.compliance;
  if (!data.laws.mollifier.empty()) input.mollifier = &data.laws.mollifier;
  input.previous_tangential_jump = previous.previous_tangential_jump;
  input.x_start = previous.x_start;
  input.delta_start = previous.delta_start;
  input.state_start = previous.state_start;
  if (run) predicted_start(data, *run, t_next, input);
  input.newton_cache = data.newton_cache.get();
  const SolverOptions& solver = data.problem.solver;
  StepOutput out = data.coupling                          ? data.coupling->solve_step(input, solver)
                   : solver.algorithm == Algorithm::newton ? solve_step_newton(input, solver)
                                                           : solve_step_thesis(input, solver);
  out.pressure_floor = input.pressure_floor;
  return out;
}

// A force that nothing carries (a tangential force without friction) leaves its body free
// in that direction: the linear system still answers, with a motion of no physical size.
void reject_runaway_motions(const HistoryData& data, StepOutput& trial) {
  const auto& condensed = data.condensed;
  const auto& problem = data.problem;
  for (Index k = 0; k < condensed.motions && trial.converged && condensed.length_scale > 0.0; ++k)
    if (std::abs(trial.delta[k]) > 1e3 * condensed.length_scale) {
      trial.converged = false;
      trial.failure = "the motion of " +
                      (k < static_cast<Index>(problem.forces.size()) ? "load '" + problem.forces[k].name + "'"
                                                                      : std::string("a body held by its contacts")) +
                      " is " + format_residual(trial.delta[k]) + ", over 1000 times the size of the bodies: no contact "
                      "carries the force in that direction";
    }
}

[[noreturn]] void throw_no_solution(const HistoryData& data, const StepOutput& trial, double t, double t_next,
                                    int taken) {
  const auto& problem = data.problem;
  std::ostringstream message;
  message.precision(6);
  message << "contact (" << to_string(problem.solver.algorithm) << " algorithm): no solution at pseudo-time "
          << t_next << " (step " << taken + 1 << ", from " << t << "): " << trial.failure
          << "; complementarity residual " << format_residual(trial.residual) << " (relative)";
  if (!problem.forces.empty()) {
    message << "; the force loads there:";
    const Vector forces = data.condensed.force_at(t_next);
    // Near zero: every force below 1 % of the largest it takes in the history.
    bool near_zero = false;
    for (std::size_t k = 0; k < problem.forces.size(); ++k) {
      const auto& load = problem.forces[k];
      message << (k ? ", " : " ") << load.name << " = " << forces[static_cast<Index>(k)] + 0.0;  // not -0
      const double peak = load.amplitude.peak() * std::abs(load.force);
      const bool small = std::abs(forces[static_cast<Index>(k)]) < 0.01 * peak || peak == 0.0;
      near_zero = (k == 0 || near_zero) && small;
    }
    if (near_zero)
      message << " (every force below 1 % of its largest: the contact may hold a pair or two there, whose stick "
                 "and slip states can cycle from one Newton iteration to the next; end the amplitude at 0, where the "
                 "bodies part, or at a load that keeps several pairs in contact, or mesh the zone finer)";
    else
      message << " (a force that no contact state can carry, such as a tangential force above the friction limit "
                 "or without friction, has no solution)";
  }
  for (const auto& contact : problem.contacts) {
    const auto& law = contact.law.compliance;
    if (contact.law.kind != ContactKind::compliant || contact.law.friction == 0.0 ||
        !(law.friction_exponent < law.exponent))
      continue;
    message << ". Contact '" << contact.name << "' has friction_exponent " << law.friction_exponent
            << " below normal_exponent " << law.exponent
            << ": where pairs close the threshold c_t pen^m_t far exceeds beta times the pressure, which the Newton "
               "iteration may not resolve at small loads (docs/contact.md, Normal compliance); equal load steps "
               "(adaptive = false) that start at a larger load may converge";
    break;
  }
  throw SolverError(message.str(), {"contact step", trial.newton_iterations > 0 ? trial.newton_iterations
                                                                                : trial.kalker_iterations,
                                     trial.residual, taken + 1, t_next});
}

// The most pairs of one group that change state between two states.
int most_state_changes(const HistoryData& data, const std::vector<PairStatus>& state,
                       const std::vector<PairStatus>& trial_state) {
  const auto& all_groups = data.all_groups;
  int most = 0;
  for (std::size_t g = 0; g + 1 < all_groups.size(); ++g)
    most = std::max(most, state_changes(state, trial_state, all_groups[g], all_groups[g + 1]));
  return most;
}

// The factor on a step of adaptive stepping that changed `changes` pairs of one contact:
// the zones' edges move about in proportion to the load, so that step would have changed
// max_state_changes pairs in h max / changes; aiming at 3/4 of it leaves room for the edges'
// uneven pace, so that few steps are redone. Within [1/8, 2]: a step grows at most twice
// (no change) and a redone one shrinks at least by half (as a plain halving would).
double step_factor(int changes, int max_changes) {
  if (changes == 0) return 2.0;
  return std::clamp(0.75 * max_changes / changes, 0.125, 2.0);
}

// Energy dissipated by friction in the step: -sum weight tau (slip increment).
void add_dissipation(const HistoryData& data, const StepOutput& step, const Vector& previous_tangential_jump,
                     Vector& dissipated) {
  const auto& all_groups = data.all_groups;
  for (std::size_t g = 0; g + 1 < all_groups.size(); ++g)
    for (Index i = all_groups[g]; i < all_groups[g + 1]; ++i)
      dissipated[static_cast<Index>(g)] -=
          data.pairs[i].weight * step.x[2 * i + 1] * (step.w[2 * i + 1] - previous_tangential_jump[i]);
}

// The accepted step's wear (wear.hpp), in the gap of the steps after it.
void add_wear(const HistoryData& data, HistoryRun& run) {
  if (run.wear.side1.size() == 0) return;
  add_step_wear(data.laws.wear, run.step.x, run.step.w, run.previous.previous_tangential_jump, run.wear);
  run.previous.gap = data.condensed.gap + run.wear.total();
}

// The accepted step, with the loads at pseudo-time t, recorded at t + offset (a repeated
// cycle's place in the history): all pairs, each contact's, the forces and motions, and the
// unknowns when every step is recorded.
void record_history_step(const HistoryData& data, const HistoryRun& run, double t, double offset,
                         const MotionReport& report, LoadHistory& history) {
  const auto& condensed = data.condensed;
  const auto& groups = data.groups;
  const auto& step = run.step;
  const Index n = condensed.pairs;
  const double approach = condensed.motions > 0 && condensed.force[0] != 0.0 ? step.delta[0] : 0.0;
  const Vector interference = interference_at(data.pairs, data.problem, data.all_groups, t);
  record_step(history, data.pairs, step, data.problem, data.laws, interference, run.wear, t + offset, approach, 0, n,
              condensed.half_model(0, n));
  history.steps.back().dissipated_energy = run.dissipated.sum();
  for (std::size_t c = 0; c < history.contacts.size(); ++c) {
    record_step(history.contacts[c], data.pairs, step, data.problem, data.laws, interference, run.wear, t + offset,
                approach, groups[c], groups[c + 1], condensed.half_model(groups[c], groups[c + 1]));
    history.contacts[c].steps.back().dissipated_energy = run.dissipated[static_cast<Index>(c)];
  }
  StepRecord record;
  record.time = t + offset;
  record.load_time = t;
  record.forces = condensed.force_at(t);
  record.motions = report ? report(step.x, step.delta, t) : step.delta;
  history.records.push_back(record);
  if (data.problem.record_steps) {
    history.step_x.push_back(step.x);
    history.step_delta.push_back(step.delta);
  }
}

// The accepted step as the start of the next: its tangential jump, solution and active sets.
void carry_over(const StepOutput& step, StepInput& previous) {
  for (Index i = 0; i < previous.previous_tangential_jump.size(); ++i)
    previous.previous_tangential_jump[i] = step.w[2 * i + 1];
  previous.x_start = step.x;
  previous.delta_start = step.delta;
  previous.state_start = step.state;
}

// More steps than max_steps (adaptive stepping without end) stop the history; each corner
// of the amplitudes inside the stretch may add one step cut short there.
void check_step_budget(const ContactProblem& problem, int taken, int corner_cuts, double t) {
  if (taken > problem.max_steps + corner_cuts)
    throw SolverError("contact: the history needs more than max_steps = " + std::to_string(problem.max_steps) +
                          " steps (raise max_steps in [solver])",
                      {"load history", -1, -1.0, taken, t});
}

// How a history reports its steps: the zone check, the motions, the progress.
struct HistoryHooks {
  const StepCheck& check_step;
  const MotionReport& report;
  const bem::ProgressCallback& progress;
};

// The steps from pseudo-time `from` to `to`, recorded at their times + offset. A plan (the
// step ends of the same stretch before: a repeated cycle) sets the steps, adaptive stepping
// shortening them where the state now changes faster; without one they start at the base step.
void advance(const HistoryData& data, double from, double to, double offset, const HistoryHooks& hooks,
             HistoryRun& run, LoadHistory& history, const std::vector<double>& plan = {}) {
  const auto& problem = data.problem;
  const double end = problem.end_time;
  auto corners = history_corners(data.condensed, end);
  corners.insert(std::upper_bound(corners.begin(), corners.end(), to), to);
  const int corner_cuts = static_cast<int>(std::count_if(
      corners.begin(), corners.end(), [&](double c) { return c > from + 1e-12 * end && c < to - 1e-12 * end; }));
  const double base_step = end / problem.increments;
  const double min_step = end / problem.max_steps;
  // Adaptive stepping matters for friction and plasticity: frictionless elastic contact does
  // not depend on the path.
  const bool adaptive = problem.adaptive && (problem.has_friction() || data.coupling);
  // An elastoplastic step that fails is redone in halves whether or not the steps adapt
  // (as the elastoplastic route cuts its increments).
  const bool halve_failures = adaptive || data.coupling;
  double t = from, dt = base_step;
  std::size_t corner = 0, planned = 0;
  int taken = 0;  // in this stretch (max_steps bounds each cycle)
  run.step_ends.clear();
  run.line.clear();  // a stretch's steps start from the last one before it (a cycle jump lies between)
  // The last step redone shorter for changing too many pairs: taken after all when its
  // halves do not converge (a normal compliance whose friction exponent is below the
  // pressure's fails at the small loads halving leads to).
  std::optional<std::pair<double, StepOutput>> too_fast;
  int too_fast_changes = 0;     // the pairs it changed
  bool changes_at_once = false;  // seen in the step being redone (below)
  while (t < to - 1e-12 * end) {
    while (corner < corners.size() && corners[corner] <= t + 1e-12 * end) ++corner;
    while (planned < plan.size() && plan[planned] <= t + 1e-12 * end) ++planned;
    double t_next = std::min(t + dt, corners[corner]);
    if (planned < plan.size()) t_next = std::min(t_next, plan[planned]);
    StepOutput trial = solve_step(data, run.previous, t_next, &run);
    add_iterations(run.totals, trial);
    double h = t_next - t;
    reject_runaway_motions(data, trial);
    if (!trial.converged && halve_failures && h > 2.0 * min_step) {
      dt = 0.5 * h;  // a smaller step may converge
      ++history.rejected_steps;
      continue;
    }
    const bool fall_back = !trial.converged && too_fast.has_value();
    if (fall_back) {
      t_next = too_fast->first;
      trial = std::move(too_fast->second);
      // The plastic state is the last solved step's: that step solved again.
      if (data.coupling) trial = solve_step(data, run.previous, t_next);
      h = t_next - t;
      ++history.steps_past_state_limit;
    }
    const bool redone = too_fast.has_value();
    too_fast.reset();
    if (!trial.converged) throw_no_solution(data, trial, t, t_next, run.taken);
    const auto trial_state = statuses(data.pairs, trial, data.laws);
    const int changes = adaptive ? most_state_changes(data, run.state, trial_state) : 0;
    // A step redone at most half as long that still changes more than half as many pairs:
    // they change at once (the slip zone sticking at a reversal, a zone closing at first
    // touch), whatever the step (measured: 146 then 136 pairs at a reversal, 15 then 13 at
    // first touch, the step cut by 8). Still redone down to the shortest step, so that the
    // changes that follow them are resolved, but not reported.
    if (redone && 2 * changes > too_fast_changes) changes_at_once = true;
    // So do the first step of a stretch and a step from a corner of the amplitudes (the loads
    // turn there): a repeated cycle's plan starts them at the shortest step already, with no
    // longer try to compare with.
    const bool from_corner = std::abs(t - from) <= 1e-12 * end ||
                             (corner > 0 && std::abs(t - corners[corner - 1]) <= 1e-12 * end);
    if (from_corner) changes_at_once = true;
    if (!fall_back && adaptive && changes > problem.max_state_changes) {
      if (h > (1.0 + 1e-9) * min_step) {  // redone shorter, down to the shortest step
        too_fast.emplace(t_next, trial);
        too_fast_changes = changes;
        dt = std::max(min_step, std::min(0.5, step_factor(changes, problem.max_state_changes)) * h);
        ++history.rejected_steps;
        continue;
      }
      if (!changes_at_once) {  // reported: a warning names max_steps and the first times
        ++history.steps_at_shortest;
        if (history.shortest_step_times.size() < 3) history.shortest_step_times.push_back(t_next + offset);
      }
    }
    changes_at_once = false;
    if (hooks.check_step) hooks.check_step(run.taken + 1, t_next + offset, trial_state);
    if (trial.at_round_off) {
      ++history.steps_at_round_off;
      history.round_off_residual = std::max(history.round_off_residual, trial.residual);
    }
    run.step = trial;
    add_dissipation(data, run.step, run.previous.previous_tangential_jump, run.dissipated);
    add_wear(data, run);
    ++run.taken;
    ++taken;
    t = t_next;
    if (data.coupling) data.coupling->accept(t + offset);
    run.state = trial_state;
    record_history_step(data, run, t, offset, hooks.report, history);
    run.step_ends.push_back(t);
    carry_over(run.step, run.previous);
    add_to_line(data, run.step, t, corner < corners.size() && std::abs(corners[corner] - t) <= 1e-12 * end, run);
    run.predicted_in_a_row = run.step.newton_iterations == 0 ? run.predicted_in_a_row + 1 : 0;
    // The next step: from this one's state changes (adaptive), or grown again by 2 after a
    // shortened one. A plan's steps are the last cycle's, already sized by their changes:
    // sizing them again would split some in every cycle, so there a step shortened for too
    // many changes only grows back.
    const bool following_plan = planned < plan.size();
    if (adaptive && !following_plan)
      dt = std::min(base_step, changes == 0 ? std::max(dt, 2.0 * h)
                                            : std::max(min_step, step_factor(changes, problem.max_state_changes) * h));
    else if (halve_failures && dt < base_step) dt = std::min(base_step, 2.0 * dt);
    check_step_budget(problem, taken, corner_cuts, t);
    if (hooks.progress) hooks.progress("contact load steps", (t - from) / (to - from));
  }
}

// Where a history's records stand, to cut them back when a cycle jump is undone.
struct HistoryMark {
  std::size_t steps = 0, step_pairs = 0, records = 0, step_x = 0;
  std::vector<std::size_t> contact_steps, contact_step_pairs;
  std::vector<std::vector<PairResult>> contact_pairs;
  std::vector<PairResult> pairs;
};
HistoryMark mark(const LoadHistory& history) {
  HistoryMark m{history.steps.size(), history.step_pairs.size(), history.records.size(), history.step_x.size(),
                {}, {}, {}, history.pairs};
  for (const auto& c : history.contacts) {
    m.contact_steps.push_back(c.steps.size());
    m.contact_step_pairs.push_back(c.step_pairs.size());
    m.contact_pairs.push_back(c.pairs);
  }
  return m;
}
void cut_back(const HistoryMark& m, LoadHistory& history) {
  history.steps.resize(m.steps);
  history.step_pairs.resize(m.step_pairs);
  history.records.resize(m.records);
  history.step_x.resize(m.step_x);
  history.step_delta.resize(m.step_x);
  history.pairs = m.pairs;
  for (std::size_t c = 0; c < history.contacts.size(); ++c) {
    history.contacts[c].steps.resize(m.contact_steps[c]);
    history.contacts[c].step_pairs.resize(m.contact_step_pairs[c]);
    history.contacts[c].pairs = m.contact_pairs[c];
  }
}

// The wear of every wearing contact at the end of a computed cycle. A repeated cycle
// (cycle_steps > 0: its last steps) in which a contact never touched stops the run: the
// wear has taken it out of its load's reach. Open at the end alone is a history that
// unloads, and a history that is not repeated (cycle_steps = 0) may end anyhow.
void record_wear_cycle(const HistoryData& data, const HistoryRun& run, long cycle, int computed, long jump,
                       double change, int cycle_steps, LoadHistory& history) {
  const auto& groups = data.all_groups;
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    const Index first = groups[g], last = groups[g + 1];
    if (first == last || (data.laws.wear.side1.segment(first, last - first).maxCoeff() <= 0.0 &&
                          data.laws.wear.side2.segment(first, last - first).maxCoeff() <= 0.0))
      continue;
    ContactInterfaceResult& out = history.contacts.empty() ? history : history.contacts[g];
    WearCycle record;
    record.cycle = cycle;
    record.computed = computed;
    record.jump = jump;
    record.pressure_change = change;
    for (Index i = first; i < last; ++i) {
      record.depth1.push_back(run.wear.side1[i]);
      record.depth2.push_back(run.wear.side2[i]);
    }
    record.pairs = out.pairs;
    record.summary = out.steps.back();
    out.wear.push_back(std::move(record));
    bool touched = cycle_steps == 0;
    for (int k = 1; k <= cycle_steps && k <= static_cast<int>(out.steps.size()) && !touched; ++k)
      touched = out.steps[out.steps.size() - static_cast<std::size_t>(k)].pairs_in_contact > 0;
    if (touched) continue;
    const std::string name = groups.size() == data.problem.contacts.size() + 1
                                 ? "contact '" + data.problem.contacts[g].name + "'"
                                 : std::string("the contact");
    throw SolverError(name + ": the worn surfaces no longer touch in load cycle " + std::to_string(cycle) +
                          " (computed cycle " + std::to_string(computed) +
                          "): every pair is open at every step. The wear has taken the contact out of its load's "
                          "reach (a prescribed approach rather than a force?); fewer cycles or a smaller wear "
                          "coefficient",
                      {"wear cycle", computed, -1.0, run.taken, data.problem.end_time});
  }
}

// Cycle jumping (wear.hpp): after the history's first cycle, each computed cycle stands for
// ΔN, the wear of ΔN - 1 of them extrapolated from the last computed one.
void repeat_cycles(const HistoryData& data, const HistoryHooks& hooks, WearDepths at_cycle_start, int first_cycle_steps,
                   HistoryRun& run, LoadHistory& history) {
  const LoadCycles& cycles = data.problem.cycles;
  const double period = data.problem.end_time - cycles.start;
  const CycleJumpControl control{cycles.max_jump, cycles.max_pressure_change};
  const bool adaptive = cycles.fixed_jump == 0;
  long represented = 1, jump = adaptive ? 1 : cycles.fixed_jump;
  int computed = 1;
  record_wear_cycle(data, run, represented, computed, 1, 0.0, first_cycle_steps, history);
  while (represented < cycles.cycles) {
    const long dn = std::min(jump, cycles.cycles - represented);
    const HistoryRun saved = run;
    const HistoryMark saved_records = mark(history);
    // The jump (wear.hpp): the last computed cycle's wear extrapolated over dn - 1 cycles
    // through the pressures' response at its end.
    const auto& p = data.condensed;
    add_cycle_jump(data.laws.wear, pressure_response(p.M, p.b, p.f, p.f_delta, run.step.x), at_cycle_start,
                   static_cast<double>(dn - 1), run.wear);
    run.previous.gap = data.condensed.gap + run.wear.total();
    run.wear.slip_path.setZero();
    const WearDepths start_of_cycle = run.wear;
    const std::vector<double> plan = run.step_ends;
    try {
      advance(data, cycles.start, data.problem.end_time, computed * period, hooks, run, history, plan);
    } catch (const SolverError& error) {  // say which cycle (its pseudo-times are shifted)
      throw SolverError(error.what() + std::string(" (in the computed cycle standing for load cycles ") +
                            std::to_string(represented + 1) + " to " + std::to_string(represented + dn) +
                            ", its pseudo-times shifted by " + format_residual(computed * period) + ")",
                        error.failure());
    }
    const double change = relative_pressure_change(saved.step.x, run.step.x);
    if (adaptive && control.reject(dn, change)) {
      run = saved;
      cut_back(saved_records, history);
      jump = control.next(dn, change);
      ++history.rejected_jumps;
      continue;
    }
    at_cycle_start = start_of_cycle;
    represented += dn;
    ++computed;
    record_wear_cycle(data, run, represented, computed, dn, change, run.taken - saved.taken, history);
    if (adaptive) jump = control.next(dn, change);
    if (hooks.progress) hooks.progress("wear cycles", static_cast<double>(represented) / cycles.cycles);
  }
}

// The history's totals and its final solution (that of the last step).
void finish_history(const HistoryRun& run, const ContactSummary& totals, LoadHistory& history) {
  if (history.steps.empty()) throw SolverError("contact: the load history has no step (end_time must be > 0)");
  history.steps_taken = run.taken;
  finish(history, totals);
  for (auto& contact : history.contacts) finish(contact, totals);
  history.x = run.step.x;
  history.delta = run.step.delta;
}

}  // namespace

LoadHistory solve_load_history(const CondensedProblem& condensed, const std::vector<ContactPair>& pairs,
                               const ContactProblem& problem, const bem::ProgressCallback& progress,
                               const std::vector<Index>& groups, const StepCheck& check_step,
                               const MotionReport& report, PlasticCoupling* coupling) {
  check_history_options(problem);
  LoadHistory history;
  if (groups.size() > 1) history.contacts.resize(groups.size() - 1);
  const HistoryData data = history_data(condensed, pairs, problem, groups, coupling);
  const HistoryHooks hooks{check_step, report, progress};
  HistoryRun run = history_start(data);
  const LoadCycles& cycles = problem.cycles;
  if (!cycles.repeated()) {
    advance(data, 0.0, problem.end_time, 0.0, hooks, run, history);
    if (run.wear.side1.size() > 0) record_wear_cycle(data, run, 1, 1, 1, 0.0, 0, history);
  } else {
    if (cycles.start > 0.0) advance(data, 0.0, cycles.start, 0.0, hooks, run, history);
    const WearDepths at_cycle_start = run.wear;
    const int taken_before = run.taken;
    advance(data, cycles.start, problem.end_time, 0.0, hooks, run, history);
    repeat_cycles(data, hooks, at_cycle_start, run.taken - taken_before, run, history);
  }
  finish_history(run, run.totals, history);
  history.newton_systems = {data.newton_cache->factored, data.newton_cache->updated, data.newton_cache->reused};
  return history;
}

namespace {

// Interior points sorted before the contact solve: a listed point outside its region is an
// input error at once (grid points outside are dropped and listed).
std::vector<bem::InteriorSelection> interior_selections(const ContactProblem& problem, const ContactModel& model) {
  std::vector<bem::InteriorSelection> selections;
  for (const auto& region : model.prepared().regions) {
    selections.push_back(
        bem::select_interior_points(region.mesh, problem.bodies[region.body].regions[region.region].interior_points));
    if (selections.back().listed_outside.empty()) continue;
    const auto& p = *selections.back().listed_outside.front();
    throw InputError(p.where.file.empty() ? SourceLocation{problem.source_file, 0, "interior.points"} : p.where,
                     "point " + point_text(p.position) + " is not inside " + region.label);
  }
  return selections;
}

// The free bodies' rigid motions, fitted to their boundary displacement, for the pins'
// values (free_motions.hpp); none without free bodies. It holds on to problem and model.
MotionReport free_motion_report(const ContactProblem& problem, const ContactModel& model) {
  if (model.free_motions().bodies.empty()) return {};
  return [&problem, &model](const Vector& x, const Vector& delta, double t) {
    const Index forces = static_cast<Index>(problem.forces.size());
    Vector motions(delta.size());
    motions.head(forces) = delta.head(forces);
    Index next = forces;
    for (const auto& body : model.free_motions().bodies) {
      std::vector<bem::BoundarySolution> solutions;
      std::vector<const geometry::BoundaryMesh*> meshes;
      std::vector<const std::vector<Vec2>*> displacements;
      for (const int r : body.regions) solutions.push_back(model.region_solution(r, x, delta, t));
      for (std::size_t k = 0; k < body.regions.size(); ++k) {
        meshes.push_back(&model.prepared().regions[body.regions[k]].mesh);
        displacements.push_back(&solutions[k].displacement);
      }
      const Vector v = rigid_motion(body, meshes, displacements, problem.analysis);
      motions.segment(next, v.size()) = v;
      next += v.size();
    }
    return motions;
  };
}

// The load history on the model, its contacts' zones checked at every step; a failure says
// which force loads pull the bodies apart.
LoadHistory contact_history(const ContactProblem& problem, const ContactModel& model,
                            const bem::ProgressCallback& progress, PlasticCoupling* coupling) {
  std::vector<Index> groups;
  for (std::size_t c = 0; c <= problem.contacts.size(); ++c) groups.push_back(model.pair_offset(c));
  const MotionReport report = free_motion_report(problem, model);
  const auto check_zones = [&](int step, double time, const std::vector<PairStatus>& state) {
    check_zones_not_clipped(model, state, step, time);
  };
  try {
    return solve_load_history(model.condensed(), model.pairs(), problem, progress, groups, check_zones, report,
                              coupling);
  } catch (const SolverError& error) {
    throw SolverError(error.what() + pulling_loads_hint(model), error.failure());
  }
}

// The history's contacts and steps in the result; the first contact's also as the result's own.
void take_history(const ContactProblem& problem, LoadHistory& history, ContactResult& result) {
  result.contacts = std::move(history.contacts);
  result.records = std::move(history.records);
  result.steps_taken = history.steps_taken;
  result.rejected_steps = history.rejected_steps;
  result.rejected_jumps = history.rejected_jumps;
  result.steps_past_state_limit = history.steps_past_state_limit;
  result.steps_at_shortest = history.steps_at_shortest;
  result.shortest_step_times = history.shortest_step_times;
  result.steps_at_round_off = history.steps_at_round_off;
  result.round_off_residual = history.round_off_residual;
  result.newton_systems = history.newton_systems;
  for (std::size_t c = 0; c < result.contacts.size(); ++c) result.contacts[c].name = problem.contacts[c].name;
  if (!result.contacts.empty()) static_cast<ContactInterfaceResult&>(result) = result.contacts.front();
}

// Every region's mesh and final boundary solution, with stresses and resultants.
void add_region_boundaries(const ContactProblem& problem, const ContactModel& model, const LoadHistory& history,
                           const PlasticCoupling* coupling, ContactResult& result) {
  const auto& regions = model.prepared().regions;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto& region = regions[r];
    const auto& body = problem.bodies[region.body];
    const auto& material = region.definition.material;
    result.body_names.push_back(body.regions.size() == 1 ? body.name : region.definition.name);
    result.region_labels.push_back(region.label);
    result.meshes.push_back(region.mesh);
    const auto plastic = std::find_if(result.plastic.begin(), result.plastic.end(),
                                      [&](const PlasticRegionResult& p) { return p.region == static_cast<int>(r); });
    // An elastoplastic region's has the cells' part and stresses with its plastic strain; an
    // elastic region bonded to one has its bonds as the cells moved them.
    std::optional<bem::BoundarySolution> bonded = coupling ? coupling->elastic_solution(static_cast<int>(r)) : std::nullopt;
    auto boundary = plastic != result.plastic.end() ? plastic->result.boundary
                    : bonded                         ? std::move(*bonded)
                                 : model.region_solution(static_cast<int>(r), history.x, history.delta, problem.end_time);
    if (boundary.stress.empty())
      boundary.stress = bem::boundary_stresses(region.mesh, problem.analysis, material, boundary);
    // Conditions as the user gave them (the platen's are the solver's own).
    boundary.resultants =
        bem::boundary_resultants(region.mesh, boundary, body.regions[region.region].body, problem.analysis);
    result.boundary.push_back(std::move(boundary));
  }
}

// When every step is recorded: the regions' boundary solutions at each step, with stresses.
void add_step_boundaries(const ContactProblem& problem, const ContactModel& model, const LoadHistory& history,
                         const PlasticCoupling* coupling, ContactResult& result) {
  const auto& regions = model.prepared().regions;
  for (std::size_t k = 0; k < history.step_x.size(); ++k) {
    std::vector<bem::BoundarySolution> regions_at_step;
    for (std::size_t r = 0; r < regions.size(); ++r) {
      // The regions of an elastoplastic region's body: as the coupling kept them at the step.
      auto kept = coupling ? coupling->step_solution(k, static_cast<int>(r)) : std::nullopt;
      auto boundary = kept ? std::move(*kept)
                           : model.region_solution(static_cast<int>(r), history.step_x[k], history.step_delta[k],
                                                   result.records[k].load_time);
      if (boundary.stress.empty())
        boundary.stress =
            bem::boundary_stresses(regions[r].mesh, problem.analysis, regions[r].definition.material, boundary);
      regions_at_step.push_back(std::move(boundary));
    }
    result.step_boundary.push_back(std::move(regions_at_step));
  }
}

// The interior points of every region that lists some; false when none does.
bool add_interior_values(const ContactProblem& problem, const ContactModel& model,
                         std::vector<bem::InteriorSelection>& selections, const bem::ProgressCallback& progress,
                         const PlasticCoupling* coupling, ContactResult& result) {
  const auto& regions = model.prepared().regions;
  bool any_interior = false;
  result.interior.resize(regions.size());
  const auto plastic = coupling ? coupling->regions() : std::vector<int>{};
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto& region = regions[r];
    const auto& points = problem.bodies[region.body].regions[region.region].interior_points;
    if (points.empty()) continue;
    any_interior = true;
    const bem::ElementIntegrator integrator(problem.analysis, region.definition.material);
    bem::DomainTerm cells;
    std::shared_ptr<const bem::PlasticCellFields> fields;
    for (std::size_t k = 0; k < plastic.size(); ++k)
      if (plastic[k] == static_cast<int>(r)) {
        fields = std::make_shared<const bem::PlasticCellFields>(coupling->cell_fields(k));
        cells = [fields](const Vec2& x, Vec2& u, bem::StressTensor& s) { fields->add_at(x, u, s); };
      }
    result.interior[r] = bem::interior_values(result.meshes[r], integrator, result.boundary[r],
                                              std::move(selections[r]), progress, cells);
  }
  return any_interior;
}

}  // namespace

namespace {

// What a pass decides once its load history is solved: true to finish it (boundary
// stresses, interior points), false to stop there (an adaptive pass to be refined).
using PassCheck = std::function<bool(const ContactResult&)>;

// One pass: the problem on its meshes as they stand.
ContactResult solve_on_meshes(const ContactProblem& problem, const bem::ProgressCallback& progress,
                              const PassCheck& finish_pass = {}) {
  check_history_options(problem);  // before the bodies are assembled
  ContactResult result;
  auto start = Clock::now();
  const ContactModel model(problem, progress);
  result.timings.add("assembly, factorisation and condensation", seconds_since(start));
  std::vector<bem::InteriorSelection> selections = interior_selections(problem, model);
  result.unknowns = 2 * model.condensed().pairs + model.condensed().motions;
  result.matrix_free = model.condensed().matrix_free != nullptr;
  if (model.condensed().M_products) result.products_compression = model.condensed().M_products->compression_ratio();

  std::unique_ptr<PlasticCoupling> coupling;
  if (const auto plastic = coupled_plastic_regions(problem, model); !plastic.empty()) {
    start = Clock::now();
    coupling = std::make_unique<PlasticCoupling>(problem, model, plastic, problem.memory_limit_bytes);
    result.timings.add("cells and their operators", seconds_since(start));
  }

  start = Clock::now();
  for (const auto& body : model.free_motions().bodies)
    for (const Index mode : body.reported) result.free_motions.push_back({body.body, mode_direction(mode, problem.analysis)});
  LoadHistory history = contact_history(problem, model, progress, coupling.get());
  result.timings.add(!coupling                ? "contact iterations"
                     : model.pairs().empty() ? "elastoplastic steps"  // bonded regions, no contact
                                             : "elastoplastic contact steps",
                     seconds_since(start));
  take_history(problem, history, result);
  if (const auto& data = model.condensed().matrix_free)
    result.matrix_free_images = data->coarse.formed() + data->start.formed();
  if (finish_pass && !finish_pass(result)) return result;
  if (coupling) {
    const auto regions = coupling->regions();
    for (std::size_t k = 0; k < regions.size(); ++k) result.plastic.push_back({regions[k], coupling->result(k)});
  }

  start = Clock::now();
  result.warnings = model.prepared().warnings;
  if (result.matrix_free && problem.solver.tolerance_given &&
      matrix_free_round_off(model.condensed().pairs) > problem.solver.tolerance) {
    std::ostringstream text;
    text << "tolerance = " << problem.solver.tolerance << " is below the round-off of the matrix-free products over "
         << model.condensed().pairs << " pairs: the steps were converged to " << matrix_free_round_off(model.condensed().pairs)
         << " (docs/contact.md, \"Large contact zones\")";
    result.warnings.push_back(text.str());
  }
  if (result.steps_at_round_off > 0 && !result.matrix_free) {
    std::ostringstream text;
    text << result.steps_at_round_off << " load step" << (result.steps_at_round_off == 1 ? "" : "s")
         << " stopped at the round-off of the Newton solves, residual up to " << result.round_off_residual
         << " against tolerance = " << problem.solver.tolerance
         << " (the contact set repeated and the residual no longer fell; docs/contact.md, \"Tolerance\")";
    result.warnings.push_back(text.str());
  }
  // A few such steps follow first touch and the corners (a zone growing as the square root of
  // the load's change: 1 % of the 480-pair fretting cycle's steps, 1.6 % of the wear example's);
  // past 5 % of the steps the shortest step is too long for the history.
  if (result.steps_at_shortest > 0 && 20 * result.steps_at_shortest > result.steps_taken) {
    std::ostringstream text;
    text << result.steps_at_shortest << " load step" << (result.steps_at_shortest == 1 ? "" : "s")
         << " changed the state of more than max_state_changes = " << problem.max_state_changes
         << " pairs of a contact at the shortest step end_time / max_steps = " << problem.end_time / problem.max_steps
         << " and were taken as they are (at pseudo-time";
    for (std::size_t k = 0; k < result.shortest_step_times.size(); ++k)
      text << (k == 0 ? " " : ", ") << result.shortest_step_times[k];
    text << (result.steps_at_shortest > 3 ? ", ..." : "")
         << "): the stick and contact zones may lag the load there. Just after a contact first touches or a "
            "tangential load reverses, its zones grow as the square root of the load's change, faster than any "
            "step; elsewhere raise max_steps in [solver]";
    result.warnings.push_back(text.str());
  }
  if (coupling) result.warnings.insert(result.warnings.end(), coupling->warnings().begin(), coupling->warnings().end());
  for (const auto& plastic : result.plastic)
    result.warnings.insert(result.warnings.end(), plastic.result.warnings.begin(), plastic.result.warnings.end());
  add_region_boundaries(problem, model, history, coupling.get(), result);
  add_step_boundaries(problem, model, history, coupling.get(), result);
  result.timings.add("boundary stresses", seconds_since(start));
  start = Clock::now();
  if (add_interior_values(problem, model, selections, progress, coupling.get(), result))
    result.timings.add("interior points", seconds_since(start));
  return result;
}

std::string zone_name(const ContactProblem& problem, int c) {
  const auto& contact = problem.contacts[static_cast<std::size_t>(c)];
  return "contact '" + contact.name + "' (" + side_text(problem, contact.side1) + ")";
}

std::string pass_text(const ZonePass& pass) {
  std::ostringstream out;
  out << "pass " << pass.pass << ": " << pass.pairs << " pairs, zone width " << pass.width << ", edge spacing "
      << pass.edge_spacing;
  return out.str();
}

// The refined meshes of an unresolved zone, within the contact's element limit.
void check_zone_limits(const ContactProblem& problem, int c, const ZoneAssessment& next, const AdaptedZone& zone) {
  const auto& adaptivity = problem.contacts[static_cast<std::size_t>(c)].adaptivity;
  if (static_cast<int>(zone.passes.size()) >= adaptivity.max_passes)
    throw SolverError(zone_name(problem, c) + ": the zone in contact is not resolved to contact_resolution = " +
                      format_residual(adaptivity.resolution) + " in " + std::to_string(adaptivity.max_passes) +
                      " adaptive passes (last " + pass_text(zone.passes.back()) +
                      "); raise max_adaptive_passes, or relax contact_resolution");
  const auto count = [](const std::vector<std::vector<double>>& side) {
    std::size_t elements = 0;
    for (const auto& piece : side) elements += piece.size() - 1;
    return static_cast<int>(elements);
  };
  const int elements = std::max(count(next.breakpoints1), count(next.breakpoints2));
  if (elements > adaptivity.max_elements)
    throw SolverError(zone_name(problem, c) + ": resolving the zone in contact to contact_resolution = " +
                      format_residual(adaptivity.resolution) + " takes " + std::to_string(elements) +
                      " elements on a side, over max_zone_elements = " + std::to_string(adaptivity.max_elements) +
                      " (" + pass_text(zone.passes.back()) + "); raise max_zone_elements, or relax contact_resolution");
}

}  // namespace

ContactResult solve_contact(const ContactProblem& problem, const bem::ProgressCallback& progress) {
  const auto adaptive = [&](std::size_t c) { return problem.contacts[c].adaptivity.on(); };
  bool any = false;
  for (std::size_t c = 0; c < problem.contacts.size(); ++c) any = any || adaptive(c);
  if (!any) return solve_on_meshes(problem, progress);
  ContactProblem current = problem;
  std::vector<AdaptedZone> zones(problem.contacts.size());
  double earlier = 0.0;
  for (int pass = 1;; ++pass) {
    const auto start = Clock::now();
    std::vector<ZoneAssessment> next(problem.contacts.size());
    bool resolved = true;
    const auto assess = [&](const ContactResult& pass_result) {
      for (std::size_t c = 0; c < problem.contacts.size(); ++c) {
        if (!adaptive(c)) continue;
        next[c] = assess_zone(problem, current, static_cast<int>(c), pass_result.contacts[c]);
        next[c].pass.pass = pass;
        zones[c].passes.push_back(next[c].pass);
        resolved = resolved && next[c].pass.resolved;
      }
      return resolved;
    };
    ContactResult result = solve_on_meshes(current, progress, assess);
    if (resolved) {
      for (std::size_t c = 0; c < problem.contacts.size(); ++c) {
        if (!adaptive(c)) continue;
        const auto& contact = current.contacts[c];
        zones[c].breakpoints1 = side_breakpoints(current, contact.side1);
        if (next[c].pass.elements2 > 0) zones[c].breakpoints2 = side_breakpoints(current, contact.side2);
        result.contacts[c].zone = zones[c];
      }
      if (!result.contacts.empty()) result.zone = result.contacts.front().zone;
      if (pass > 1) result.timings.add("earlier adaptive passes", earlier);
      return result;
    }
    for (std::size_t c = 0; c < problem.contacts.size(); ++c) {
      if (!adaptive(c) || next[c].pass.resolved) continue;
      check_zone_limits(current, static_cast<int>(c), next[c], zones[c]);
      set_zone_meshes(current, static_cast<int>(c), next[c].breakpoints1, next[c].breakpoints2);
    }
    earlier += seconds_since(start);
  }
}

}  // namespace bemcontact::contact

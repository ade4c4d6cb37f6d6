// Three families, each over the pair count n, for the exponents of time against n:
//  - BM_HertzSphere:
// contact elements per body) and with 4x and 16x more contact elements, frictionless and
// with beta = 0.1 over 16 load steps, for both algorithms.
//   range(0): contact elements per body (30, 120, 480)
//   range(1): 0 = semi-smooth Newton, 1 = thesis (Alg V.1-V.3)
//   range(2): 0 = frictionless one step, 1 = beta 0.1, 16 steps
// Counters: pairs, Newton iterations, Kalker (Alg V.3) and threshold (Alg V.2) iterations,
// GMRES(m) cycles (Alg V.1), and the time of the contact iterations alone (the rest is
// assembly and factorisation of the two bodies).
//  - BM_RigidCylinder/n/dense: a rigid cylinder (R = 1) pressed on a plane-strain block
//    (16 x 8) with n elements on its contact zone |x| <= 0.1 (a = 0.05), frictionless, one
//    step (examples/contact_compliant_cylinder.toml with the unilateral law); the condensed
//    operator as the model chooses it (dense = 0: matrix-free on a compressed block) or
//    formed (dense = 1).
//  - BM_ShearedCylinder/n/dense: the same cylinder with friction (mu = 0.3) on a block of
//    nu = 0.4999, pressed by P = 1.48 (a = 0.0045, zone |x| <= 0.01) then sheared by
//    Q = 0.6 mu P, one step each (validate large-hertz's Cattaneo-Mindlin half).
//  - BM_FrettingCycle: examples/fretting_cylinder.toml (P, then Q = 0.6 mu P forth, back
//    and forth, adaptive steps) with n elements per contact zone.
//  - BM_FrettingWear: examples/fretting_wear.toml (the same cylinder, Archard wear on both
//    bodies, k = 1e-7) over 10^5 cycles with n elements per zone (n = 199: 200 pairs);
//    counters: the computed cycles and the jumps undone.
// Counters: pairs, the phases' seconds, Newton iterations and systems (factored, updated
// through the last factors, reused), the matrix-free route's products of M, and the
// process's peak resident memory (MB).
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"

namespace {

using namespace bemcontact;

contact::ContactProblem ball(int elements, bool thesis, bool friction) {
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_hertz_sphere.toml");
  auto& problem = file.problem;
  const auto& contact = problem.contacts.front();
  for (const auto* side : {&contact.side1, &contact.side2})
    for (const int piece : side->pieces) problem.region(*side).body.pieces[piece].elements = elements;
  problem.solver.algorithm = thesis ? contact::Algorithm::thesis : contact::Algorithm::newton;
  if (friction) {
    problem.set_friction(0.1);
    problem.increments = 16;
  }
  return problem;
}

void BM_HertzSphere(benchmark::State& state) {
  const auto problem = ball(static_cast<int>(state.range(0)), state.range(1) != 0, state.range(2) != 0);
  contact::ContactResult result;
  for (auto _ : state) {
    try {
      result = contact::solve_contact(problem);
    } catch (const bemcontact::Error& error) {  // e.g. the thesis algorithm stalls: report it
      state.SkipWithError(error.what());
      return;
    }
    benchmark::DoNotOptimize(result.summary.contact_radius);
  }
  state.counters["pairs"] = static_cast<double>(result.pairs.size());
  state.counters["newton_iterations"] = result.summary.newton_iterations;
  state.counters["kalker_iterations"] = result.summary.kalker_iterations;
  state.counters["threshold_iterations"] = result.summary.threshold_iterations;
  state.counters["gmres_cycles"] = result.summary.gmres_cycles;
  for (const auto& phase : result.timings.phases) {
    if (phase.first == "contact iterations") state.counters["contact_seconds"] = phase.second;
    if (phase.first == "assembly, factorisation and condensation") state.counters["model_seconds"] = phase.second;
  }
}

double peak_memory_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void add_counters(benchmark::State& state, const contact::ContactResult& result) {
  state.counters["pairs"] = static_cast<double>(result.pairs.size());
  state.counters["newton_iterations"] = result.summary.newton_iterations;
  state.counters["steps"] = result.steps_taken;
  state.counters["factored"] = static_cast<double>(result.newton_systems.factored);
  state.counters["updated"] = static_cast<double>(result.newton_systems.updated);
  state.counters["reused"] = static_cast<double>(result.newton_systems.reused);
  state.counters["matrix_free_products"] = static_cast<double>(result.summary.matrix_free_products);
  for (const auto& phase : result.timings.phases) {
    if (phase.first == "contact iterations") state.counters["contact_seconds"] = phase.second;
    if (phase.first == "assembly, factorisation and condensation") state.counters["model_seconds"] = phase.second;
  }
  state.counters["peak_MB"] = peak_memory_mb();
}

// The result of the last run (empty after an error, which the state reports).
contact::ContactResult run_case(benchmark::State& state, const contact::ContactProblem& problem) {
  contact::ContactResult result;
  for (auto _ : state) {
    try {
      result = contact::solve_contact(problem);
    } catch (const bemcontact::Error& error) {
      state.SkipWithError(error.what());
      return {};
    }
    benchmark::DoNotOptimize(result.summary.contact_radius);
  }
  add_counters(state, result);
  return result;
}



// examples/contact_compliant_cylinder.toml with the unilateral law, on an aluminium-like block.
void BM_RigidCylinder(benchmark::State& state) {
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_compliant_cylinder.toml",
                                    {{"n", static_cast<double>(state.range(0))}, {"rc", 0.1}, {"E_block", 70000.0},
                                     {"P", 148.0}});
  file.problem.contacts.front().law = contact::ContactLaw{};
  // The second argument: 0 the route the model chooses (matrix-free from 2 000 pairs on a
  // compressed block), 1 the formed operator.
  if (state.range(1) != 0) file.problem.solver.contact_operator = contact::CondensedOperatorKind::dense;
  run_case(state, file.problem);
}

void BM_ShearedCylinder(benchmark::State& state) {
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_compliant_cylinder.toml",
                                    {{"n", static_cast<double>(state.range(0))}, {"rc", 0.01}, {"E_block", 70000.0},
                                     {"P", 1.48}});
  auto& problem = file.problem;
  problem.contacts.front().law = contact::ContactLaw{};
  problem.elastic(0).material.poisson_ratio = 0.4999;
  problem.set_friction(0.3);
  auto& P = problem.forces.front();
  P.amplitude.points = {{0.0, 0.0}, {1.0, 1.0}};
  contact::ForceLoad Q = P;
  Q.name = "Q";
  Q.component = 0;
  Q.force = 0.6 * 0.3 * 1.48;
  Q.amplitude.points = {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}};
  problem.forces.push_back(Q);
  problem.end_time = 2.0;
  problem.increments = 2;
  problem.adaptive = false;
  if (state.range(1) != 0) problem.solver.contact_operator = contact::CondensedOperatorKind::dense;
  run_case(state, problem);
}

// An example with n elements per contact zone, without its stress points.
contact::ContactProblem example_with_zones(const std::string& name, benchmark::State& state) {
  std::ifstream in(std::string(BEMCONTACT_EXAMPLES_DIR) + "/" + name);
  std::ostringstream text;
  text << in.rdbuf();
  auto file = io::parse_contact_problem(text.str(), name, {{"n", static_cast<double>(state.range(0))}});
  file.problem.drop_interior_points();
  return file.problem;
}

void BM_FrettingCycle(benchmark::State& state) { run_case(state, example_with_zones("fretting_cylinder.toml", state)); }

void BM_FrettingWear(benchmark::State& state) {
  const auto result = run_case(state, example_with_zones("fretting_wear.toml", state));
  if (result.wear.empty()) return;
  state.counters["cycles"] = static_cast<double>(result.wear.back().cycle);
  state.counters["computed_cycles"] = result.wear.back().computed;
  state.counters["undone_jumps"] = result.rejected_jumps;
}

}  // namespace

BENCHMARK(BM_FrettingWear)->Arg(59)->Arg(99)->Arg(199)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RigidCylinder)
    ->Args({500, 0})
    ->Args({1000, 0})
    ->Args({2000, 0})
    ->Args({4000, 1})
    ->Args({4000, 0})
    ->Args({8000, 0})
    ->Args({16000, 0})
    ->Args({32000, 0})  // about 4 minutes and 5.9 GB (2.5 minutes and 3 GB before the blocks by component)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_ShearedCylinder)
    ->Args({1250, 0})
    ->Args({2500, 0})
    ->Args({5000, 1})
    ->Args({5000, 0})
    ->Args({10000, 0})
    ->Args({20000, 0})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_FrettingCycle)->Arg(60)->Arg(120)->Arg(240)->Arg(480)->Arg(960)->Arg(1920)->Arg(3999)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK(BM_HertzSphere)
    ->ArgsProduct({{30, 120, 480}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK_MAIN();

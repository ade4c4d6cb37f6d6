// Ball on a support (hertz-sphere, V.5.2.3, P = 31.5) at the example's resolution (30
// contact elements per body) and with 4x and 16x more contact elements, frictionless and
// with beta = 0.1 over 16 load steps, for both algorithms.
//   range(0): contact elements per body (30, 120, 480)
//   range(1): 0 = semi-smooth Newton, 1 = thesis (Alg V.1-V.3)
//   range(2): 0 = frictionless one step, 1 = beta 0.1, 16 steps
// Counters: pairs, Newton iterations, Kalker (Alg V.3) and threshold (Alg V.2) iterations,
// GMRES(m) cycles (Alg V.1), and the time of the contact iterations alone (the rest is
// assembly and factorisation of the two bodies).
#include <benchmark/benchmark.h>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/core/error.hpp"
#include "bemcontact/io/input/contact_file.hpp"

namespace {

using namespace bemcontact;

contact::ContactProblem ball(int elements, bool thesis, bool friction) {
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/contact_hertz_sphere.toml");
  auto& problem = file.problem;
  const auto& contact = problem.contacts.front();
  for (const auto* side : {&contact.side1, &contact.side2}) problem.region(*side).body.pieces[side->piece].elements = elements;
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

}  // namespace

BENCHMARK(BM_HertzSphere)
    ->ArgsProduct({{30, 120, 480}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK_MAIN();

// The unified model's paths: three bodies with two contacts and a free roller
// (examples/contact_roller_plates.toml), a body of two bonded regions under a rigid ball
// (contact_coated_indentation.toml), and a fretting cycle with adaptive steps
// (fretting_cylinder.toml), each at the example's mesh times the first argument.
// Counters: pairs, steps taken, steps redone, and the time of the contact iterations.
#include <benchmark/benchmark.h>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/contact_file.hpp"

namespace {

using namespace bemcontact;

void solve_example(benchmark::State& state, const std::string& name, const io::ParameterOverrides& overrides) {
  auto problem = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/" + name, overrides).problem;
  problem.drop_interior_points();
  contact::ContactResult result;
  for (auto _ : state) {
    result = contact::solve_contact(problem);
    benchmark::DoNotOptimize(result.summary.contact_radius);
  }
  std::size_t pairs = 0;
  for (const auto& contact : result.contacts) pairs += contact.pairs.size();
  state.counters["pairs"] = static_cast<double>(pairs);
  state.counters["steps"] = result.steps_taken;
  state.counters["steps_redone"] = result.rejected_steps;
  for (const auto& phase : result.timings.phases)
    if (phase.first == "contact iterations") state.counters["contact_seconds"] = phase.second;
}

void BM_RollerBetweenPlates(benchmark::State& state) {
  solve_example(state, "contact_roller_plates.toml", {{"n", 25.0 * static_cast<double>(state.range(0))}});
}

void BM_CoatedIndentation(benchmark::State& state) {
  const double k = static_cast<double>(state.range(0));
  solve_example(state, "contact_coated_indentation.toml", {{"n", 30.0 * k}, {"n_bond", 40.0 * k}});
}

void BM_FrettingCycle(benchmark::State& state) {
  solve_example(state, "fretting_cylinder.toml", {{"n", 60.0 * static_cast<double>(state.range(0))}});
}

}  // namespace

BENCHMARK(BM_RollerBetweenPlates)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CoatedIndentation)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FrettingCycle)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();

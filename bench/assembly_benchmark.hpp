#pragma once
// Shared by the assembly benchmarks: time assemble_influence_matrices on one problem and
// report the cost per (source node, element) pair.
#include <benchmark/benchmark.h>

#include "bemcontact/bem/analysis.hpp"

namespace bemcontact::bench {

inline void measure_assembly(benchmark::State& state, const bem::ProblemDefinition& problem) {
  const auto mesh = bem::mesh_body(problem);
  const bem::ElementIntegrator integrator(problem.analysis, problem.body.material);
  for (auto _ : state) {
    auto m = bem::assemble_influence_matrices(mesh, integrator);
    benchmark::DoNotOptimize(m.H.data());
  }
  const double pairs = static_cast<double>(mesh.node_count()) * mesh.element_count();
  state.counters["elements"] = static_cast<double>(mesh.element_count());
  state.counters["ns_per_pair"] =
      benchmark::Counter(pairs * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace bemcontact::bench

#pragma once
// Shared by the BEM benchmarks: time assemble_influence_matrices on one problem and report
// the cost per (source node, element) pair; time the whole solve, dense or compressed.
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

// The whole one-body solve with `compressed` operators or dense ones; with `progress`, a
// listener hears the phases (as on a terminal), to show what the reports cost. Counters:
// unknowns, the compressed share of stored values, the reports heard.
inline void measure_whole_solve(benchmark::State& state, bem::ProblemDefinition problem, bool compressed,
                                bool progress = false) {
  problem.operator_choice.kind = compressed ? bem::OperatorKind::compressed : bem::OperatorKind::dense;
  bem::BodyResult result;
  double reports = 0.0;
  bem::ProgressCallback listener;
  if (progress) listener = [&reports](const std::string&, double) { reports += 1.0; };
  for (auto _ : state) {
    reports = 0.0;
    result = bem::solve_body(problem, listener);
    benchmark::DoNotOptimize(result.boundary.displacement.data());
  }
  state.counters["unknowns"] = static_cast<double>(result.report.unknowns);
  state.counters["stored_fraction"] = compressed ? result.report.compression_ratio : 1.0;
  state.counters["reports"] = reports;
}

}  // namespace bemcontact::bench

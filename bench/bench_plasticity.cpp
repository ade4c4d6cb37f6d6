// The elastoplastic region (bem/elastoplastic_region.hpp) over its cell count. The thick
// tube of examples/thick_ring_plane_strain.toml (32 elements on each arc, 64 on each
// straight side), perfectly plastic, quadrilateral cells over 1 <= r <= 1.6 on the arc's 32
// angles in range(0) rings (32 range(0) cells), loaded to 0.5, 0.9, 1.1, 1.3 and 1.5 times
// the first-yield pressure and unloaded.
// Counters: cells, the set-up's seconds (boundary system, the cells' domain terms, the cell
// operator), the increments' seconds, Newton iterations, and the peak resident memory (MB).
#include <benchmark/benchmark.h>

#include <chrono>
#include <numbers>

#include <sys/resource.h>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/elastoplastic_region.hpp"
#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/io/input/contact_file.hpp"
#include "bemcontact/io/input/problem_file.hpp"
#include "bemcontact/plasticity/cell_meshes.hpp"
#include "bemcontact/reference/plastic_cylinder.hpp"

namespace {

using namespace bemcontact;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void BM_ElastoplasticTube(benchmark::State& state) {
  auto problem = io::read_problem_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/thick_ring_plane_strain.toml",
                                       {{"p", 1.0}}).problem;
  for (auto& piece : problem.body.pieces)
    if (piece.name == "AB" || piece.name == "CD") piece.elements = 64;
  const auto mesh = bem::mesh_body(problem);
  const plasticity::J2Hardening perfect{250.0, 0.0, 0.0};
  const double py = reference::first_yield_pressure(1.0, 2.0, problem.body.material, perfect.yield_stress);
  const auto rings = static_cast<int>(state.range(0));
  double setup = 0.0, increments = 0.0;
  int iterations = 0;
  std::size_t cells = 0;
  for (auto _ : state) {
    auto start = Clock::now();
    bem::ElastoplasticRegion region(
        mesh, problem.body, problem.analysis, perfect,
        plasticity::annular_sector_cells(Vec2::Zero(), 1.0, 1.6, 0.0, 0.5 * std::numbers::pi, rings, 32));
    setup = seconds_since(start);
    start = Clock::now();
    iterations = 0;
    for (const double factor : {0.5, 0.9, 1.1, 1.3, 1.5, 0.0}) iterations += region.advance(factor * py).newton_iterations;
    increments = seconds_since(start);
    cells = region.cells().size();
    benchmark::DoNotOptimize(region.cell_stress());
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["setup_seconds"] = setup;
  state.counters["increment_seconds"] = increments;
  state.counters["newton_iterations"] = iterations;
  state.counters["peak_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// The Brinell cycle of examples/brinell.toml (axisymmetric, rigid ball 0.06 in and out, 22
// steps) at cell size range(0) / 1000 (the example: 160), on rectangles (range(1) = 0) or
// crossed triangles (1), with range(2) elements on the contact zone (the example: 36), the
// cells' operator dense (range(3) = 0) or compressed (1):
// the contact history with the elastoplastic region (contact/plastic_coupling.hpp). The
// issue's case: 2 182 crossed cells and 200 pairs (113, 1, 200).
// Counters: cells, the cells' set-up and the steps' seconds (the run's phases), Newton
// iterations, peak resident memory (of the process so far).
void BM_BrinellCycle(benchmark::State& state) {
  const double cell = static_cast<double>(state.range(0)) / 1000.0;
  auto file = io::read_contact_file(std::string(BEMCONTACT_EXAMPLES_DIR) + "/brinell.toml",
                                    {{"cell", cell}, {"n", static_cast<double>(state.range(2))}});
  auto& plasticity = *file.problem.bodies.front().regions.front().body.plasticity;
  plasticity.cells.crossed = state.range(1) != 0;
  plasticity.cell_operator = state.range(3) != 0 ? bem::OperatorKind::compressed : bem::OperatorKind::dense;
  double setup = 0.0, steps = 0.0;
  int iterations = 0;
  std::size_t cells = 0;
  for (auto _ : state) {
    const auto result = contact::solve_contact(file.problem);
    for (const auto& [phase, seconds] : result.timings.phases) {
      if (phase == "cells and their operators") setup = seconds;
      if (phase == "elastoplastic contact steps") steps = seconds;
    }
    iterations = 0;
    for (const auto& step : result.plastic.at(0).result.steps) iterations += step.report.newton_iterations;
    cells = result.plastic.at(0).result.cells.size();
    benchmark::DoNotOptimize(result.summary);
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["setup_seconds"] = setup;
  state.counters["step_seconds"] = steps;
  state.counters["newton_iterations"] = iterations;
  state.counters["peak_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace

BENCHMARK(BM_BrinellCycle)
    ->ArgNames({"cell_per_mille", "crossed", "n", "compressed"})
    ->Args({320, 0, 36, 0})
    ->Args({160, 0, 36, 0})
    ->Args({80, 0, 36, 0})
    ->Args({320, 1, 36, 0})
    ->Args({160, 1, 36, 0})
    ->Args({160, 1, 36, 1})
    ->Args({113, 1, 200, 0})
    ->Args({113, 1, 200, 1})
    ->Args({80, 1, 200, 0})
    ->Args({80, 1, 200, 1})
    ->Args({57, 1, 200, 0})  // 8 166 cells: 14 min, 5.4 GB (run it alone)
    ->Args({57, 1, 200, 1})  // 19 min, 4.9 GB
    ->Args({36, 1, 200, 1})  // 20 400 cells: not finished in 2 h 09 min, peak 22.8 GB (dense: ~25 GB)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_ElastoplasticTube)->Arg(4)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();

// Domain decomposition against the monolithic multi-region solve (then iterations against
// the number of subdomains, with and without the balancing preconditioner, on 2 to 64
// strips and on a fibre composite of 1 to 64 fibres): 2, 4 and 8 strips of
// 500 linear elements each (200 across, 50 up; h = 0.01, strips 2 x 0.5, stacked), plate
// in tension, mixed method, GMRES(20), tolerance 1e-8.
//   BM_Decomposed:  assemble + factor each strip (n^3 per strip), GMRES on the interface
//                   (one triangular solve per strip per iteration), recovery.
//                   With explicit = 1 each strip's interface map is formed once (one
//                   multi-right-hand-side solve) and GMRES costs small dense products.
//   BM_Monolithic:  every strip's rows and the interface equations in one dense LU
//                   ((sum n)^3): the cost the decomposition avoids.
// Counters: unknowns, iterations, and memory of the dense matrices (bytes, from their sizes:
// the LU factors per strip and the right-hand-side columns of the interface data for the
// decomposition; the one dense system plus the per-strip H and G for the monolithic solve).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

#include "bemcontact/dd/fibre_composite.hpp"
#include "bemcontact/dd/monolithic.hpp"
#include "bemcontact/dd/plate_strips.hpp"
#include "bemcontact/dd/solver.hpp"

namespace {

using namespace bemcontact;

dd::DecompositionProblem strips(int count, bool explicit_operators = false) {
  dd::PlateStripsSpec spec;
  spec.strips = count;
  spec.elements_per_unit = 100;  // h = 0.01: 200 elements across
  spec.height = 0.5 * count;     // T = 0.5: 50 elements up; 500 per strip
  spec.method = dd::InterfaceMethod::mixed;
  auto problem = dd::plate_strips(spec);
  problem.options.explicit_operators = explicit_operators;
  return problem;
}

void BM_Decomposed(benchmark::State& state) {
  const auto problem = strips(static_cast<int>(state.range(0)), state.range(1) != 0);
  dd::DecompositionResult result;
  for (auto _ : state) {
    result = dd::solve_decomposition(problem);
    benchmark::DoNotOptimize(result.gmres.x.data());
  }
  if (!result.converged()) state.SkipWithError(result.gmres.message.c_str());
  state.counters["interface_unknowns"] = static_cast<double>(result.interface_unknowns);
  state.counters["iterations"] = result.gmres.iterations;
  state.counters["memory_MB"] = result.factor_memory_bytes / 1e6;
  state.counters["elements"] = static_cast<double>(500 * state.range(0));
}

void BM_Monolithic(benchmark::State& state) {
  const auto problem = strips(static_cast<int>(state.range(0)));
  const auto meshes = dd::mesh_subdomains(problem);
  const auto connectivity = dd::build_connectivity(problem, meshes);
  dd::MonolithicResult result;
  for (auto _ : state) {
    result = dd::solve_monolithic(problem, meshes, connectivity);
    benchmark::DoNotOptimize(result.boundary.data());
  }
  double per_strip = 0.0;
  for (const auto& mesh : meshes) per_strip += 2.0 * std::pow(2.0 * mesh.node_count(), 2);  // H and G
  state.counters["unknowns"] = static_cast<double>(result.unknowns);
  state.counters["memory_MB"] = (8.0 * std::pow(static_cast<double>(result.unknowns), 2) + 8.0 * per_strip) / 1e6;
  state.counters["elements"] = static_cast<double>(500 * state.range(0));
}

// Second argument: 0 matrix-free K (Alg IV.1), 1 explicit interface maps.
BENCHMARK(BM_Decomposed)
    ->ArgsProduct({{2, 4, 8}, {0, 1}})
    ->ArgNames({"strips", "explicit"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_Monolithic)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);

// The preconditioner variants compared below: 0 the thesis' mixed method unpreconditioned,
// 1 conforming unpreconditioned, 2 conforming with balancing (the default).
void set_variant(dd::DecompositionProblem& problem, std::int64_t variant) {
  problem.options.set_method(variant == 0 ? dd::InterfaceMethod::mixed : dd::InterfaceMethod::conforming);
  if (variant == 1) problem.options.preconditioner = dd::InterfacePreconditioner::none;
  problem.options.max_iterations = 2000;
}

// Solves `problem` in the given variant and reports its counters.
void solve_variant(benchmark::State& state, dd::DecompositionProblem problem, std::int64_t variant) {
  set_variant(problem, variant);
  dd::DecompositionResult result;
  for (auto _ : state) {
    result = dd::solve_decomposition(problem);
    benchmark::DoNotOptimize(result.gmres.x.data());
  }
  if (!result.converged()) state.SkipWithError(result.gmres.message.c_str());
  state.counters["subdomains"] = static_cast<double>(problem.subdomains.size());
  state.counters["interface_unknowns"] = static_cast<double>(result.interface_unknowns);
  state.counters["iterations"] = result.gmres.iterations;
  state.counters["coarse_dimension"] = static_cast<double>(result.coarse_dimension);
}

// The thesis' strips (h = 1/6, unit thickness, stacked): iterations against strips.
void BM_StripsIterations(benchmark::State& state) {
  dd::PlateStripsSpec spec;
  spec.strips = static_cast<int>(state.range(0));
  spec.height = spec.strips;
  solve_variant(state, dd::plate_strips(spec), state.range(1));
}
BENCHMARK(BM_StripsIterations)
    ->ArgsProduct({{2, 4, 8, 16, 32, 64}, {0, 1, 2}})
    ->ArgNames({"strips", "variant"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// A fibre composite of n x n glass fibres in epoxy (dd/fibre_composite.hpp, pitch 4 R,
// 8 elements per quarter arc, matrix half-width 30 R), full GMRES: iterations and time
// against the number of subdomains (n^2 + 1), per variant.
void BM_FibreComposite(benchmark::State& state) {
  dd::FibreCompositeSpec spec;
  spec.fibres_per_side = static_cast<int>(state.range(0));
  solve_variant(state, dd::fibre_composite(spec), state.range(1));
}
BENCHMARK(BM_FibreComposite)
    ->ArgsProduct({{1, 2, 4, 6, 8}, {0, 2}})
    ->ArgNames({"per_side", "variant"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();

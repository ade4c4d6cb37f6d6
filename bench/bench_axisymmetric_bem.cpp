// Axisymmetric BEM: assembly time per element pair next to the plane (analytic) assembly
// at equal size, 250 ... 2000 elements, the cost of the kernels' elliptic integrals, and the
// whole solve dense against compressed.
#include <benchmark/benchmark.h>

#include <cmath>

#include "assembly_benchmark.hpp"
#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/kernels/axisymmetric.hpp"
#include "bemcontact/kernels/elliptic.hpp"

namespace {

using namespace bemcontact;

// A hollow cylinder section (r in [1, 2], z in [0, 1]) with `elements` linear elements,
// clamped at the bottom, loaded at the top; plane or axisymmetric.
bem::ProblemDefinition hollow_section(int elements, AnalysisType type) {
  bem::ProblemDefinition problem;
  problem.analysis = type;
  problem.body.material = {1000.0, 0.3};
  const Vec2 corners[4] = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  for (int k = 0; k < 4; ++k) {
    geometry::BoundaryPiece piece;
    piece.name = "side" + std::to_string(k);
    piece.start = corners[k];
    piece.end = corners[(k + 1) % 4];
    piece.elements = elements / 4;
    bem::BoundaryCondition bc;
    if (k == 0) bc.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
    if (k == 2) bc.value[1] = [](const Vec2&) { return 1.0; };
    bc.signature = piece.name;
    piece.condition_signature = bc.signature;
    problem.body.pieces.push_back(piece);
    problem.body.conditions.push_back(bc);
  }
  return problem;
}

void assembly(benchmark::State& state, AnalysisType type) {
  bench::measure_assembly(state, hollow_section(static_cast<int>(state.range(0)), type));
}

void BM_AssemblyPlane(benchmark::State& state) { assembly(state, AnalysisType::plane_strain); }
void BM_AssemblyAxisymmetric(benchmark::State& state) { assembly(state, AnalysisType::axisymmetric); }
// Quadratic elements: half as many for the same number of nodes.
void BM_AssemblyAxisymmetricQuadratic(benchmark::State& state) {
  auto problem = hollow_section(static_cast<int>(state.range(0)), AnalysisType::axisymmetric);
  problem.mesh.interpolation = Interpolation::quadratic;
  bench::measure_assembly(state, problem);
}
BENCHMARK(BM_AssemblyAxisymmetricQuadratic)->Arg(124)->Arg(248)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AssemblyPlane)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_AssemblyAxisymmetric)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole axisymmetric solve dense against compressed (accuracy 1e-10, the default) on
// the hollow section: where the compressed operator starts to pay (the ring kernels cost
// 6x the plane ones per pair, so earlier than in plane). Counters: unknowns, stored share.
void BM_WholeSolveAxisymmetric(benchmark::State& state) {
  bench::measure_whole_solve(state, hollow_section(static_cast<int>(state.range(0)), AnalysisType::axisymmetric),
                             state.range(1) != 0);
}
BENCHMARK(BM_WholeSolveAxisymmetric)
    ->Args({1000, 0})->Args({1000, 1})->Args({2000, 0})->Args({2000, 1})->Args({4000, 0})->Args({4000, 1})
    ->Args({8000, 1})
    ->ArgNames({"elements", "compressed"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// One evaluation of K and E (arithmetic-geometric mean), the unit the kernels pay per
// quadrature point; compare with ns_per_pair above to see the elliptic share.
void BM_CompleteElliptic(benchmark::State& state) {
  double m = 0.1, sum = 0.0;
  for (auto _ : state) {
    const auto ke = kernels::complete_elliptic(m, 1.0 - m);
    sum += ke.K + ke.E;
    m = m < 0.99 ? m + 1e-3 : 0.1;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_CompleteElliptic);

// One ring-kernel evaluation (U* and T* at a field point), elliptic integrals included.
void BM_RingKernels(benchmark::State& state) {
  const kernels::KelvinAxisymmetric kelvin{384.6, 0.3};
  double z = 0.1, sum = 0.0;
  for (auto _ : state) {
    const auto k = kernels::ring_kernels(kelvin, Vec2(1.0, 0.0), Vec2(1.5, z), Vec2(1.0, 0.0));
    sum += k.U(0, 0) + k.T(1, 1);
    z = z < 2.0 ? z + 1e-3 : 0.1;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_RingKernels);

}  // namespace

BENCHMARK_MAIN();

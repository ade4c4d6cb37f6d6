// Interior points: Somigliana displacement and stress at a grid of points, per (point,
// element) pair, plane and axisymmetric, and one evaluation of the axisymmetric stress
// kernel (the unit that dominates the Hertz example's run).
#include <benchmark/benchmark.h>

#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/postprocess.hpp"
#include "bemcontact/kernels/axisymmetric.hpp"

namespace {

using namespace bemcontact;

// A section r in [1, 2], z in [0, 1] (plane or axisymmetric), `elements` linear elements,
// clamped at the bottom and pulled at the top; a grid of points x points inside.
struct Setup {
  bem::ProblemDefinition problem;
  bem::BodyResult result;
  std::vector<Vec2> points;
};

Setup setup(int elements, int grid, AnalysisType type) {
  Setup s;
  s.problem.analysis = type;
  s.problem.body.material = {1000.0, 0.3};
  const Vec2 corners[4] = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  for (int k = 0; k < 4; ++k) {
    geometry::BoundaryPiece piece = geometry::line_piece("side" + std::to_string(k), corners[k], corners[(k + 1) % 4], elements / 4);
    bem::BoundaryCondition bc;
    if (k == 0) bc.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
    if (k == 2) bc.value[1] = [](const Vec2&) { return 1.0; };
    bc.signature = piece.name;
    piece.condition_signature = bc.signature;
    s.problem.body.pieces.push_back(piece);
    s.problem.body.conditions.push_back(bc);
  }
  s.result = bem::solve_body(s.problem);
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) s.points.emplace_back(1.05 + 0.9 * i / (grid - 1), 0.05 + 0.9 * j / (grid - 1));
  return s;
}

void interior(benchmark::State& state, AnalysisType type) {
  const Setup s = setup(static_cast<int>(state.range(0)), 28, type);
  const bem::ElementIntegrator integrator(s.problem.analysis, s.problem.body.material);
  for (auto _ : state) {
    auto values = bem::interior_values(s.result.mesh, integrator, s.result.boundary, s.points);
    benchmark::DoNotOptimize(values.stress.data());
  }
  const double pairs = static_cast<double>(s.points.size()) * s.result.mesh.element_count();
  state.counters["points"] = static_cast<double>(s.points.size());
  state.counters["ns_per_pair"] =
      benchmark::Counter(pairs * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_InteriorPlane(benchmark::State& state) { interior(state, AnalysisType::plane_strain); }
void BM_InteriorAxisymmetric(benchmark::State& state) { interior(state, AnalysisType::axisymmetric); }
BENCHMARK(BM_InteriorPlane)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_InteriorAxisymmetric)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond)->UseRealTime();

// One axisymmetric stress-kernel evaluation (D* and S*, elliptic integrals included).
void BM_RingStressKernels(benchmark::State& state) {
  const kernels::KelvinAxisymmetric kelvin{384.6, 0.3};
  double z = 0.1, sum = 0.0;
  for (auto _ : state) {
    const auto k = kernels::ring_stress_kernels(kelvin, Vec2(1.0, 0.0), Vec2(1.5, z), Vec2(0.6, 0.8));
    sum += k.D[0][0] + k.S[1][2];
    z = z < 2.0 ? z + 1e-3 : 0.1;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_RingStressKernels);

}  // namespace

BENCHMARK_MAIN();

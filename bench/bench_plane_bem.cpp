// Plane BEM: assembly of H and G (linear elements in closed form, quadratic by quadrature)
// and the dense LU, for 250 ... 4000 linear elements,
// with the LU's GFLOP/s next to the machine's dgemm GFLOP/s measured in the same run; and
// the whole solve, dense against compressed.
#include <benchmark/benchmark.h>
#include <cblas.h>

#include <algorithm>
#include <omp.h>

#include "assembly_benchmark.hpp"
#include "bemcontact/bem/analysis.hpp"
#include "bemcontact/bem/boundary_system.hpp"
#include "bemcontact/operators/dense_lu.hpp"

namespace {

using namespace bemcontact;

// A square plate clamped at the bottom and pulled at the top, `elements` linear elements.
bem::ProblemDefinition square_plate(int elements) {
  bem::ProblemDefinition problem;
  problem.analysis = AnalysisType::plane_strain;
  problem.body.material = {1000.0, 0.3};
  const Vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const char* names[4] = {"bottom", "right", "top", "left"};
  for (int k = 0; k < 4; ++k) {
    geometry::BoundaryPiece piece;
    piece.name = names[k];
    piece.start = corners[k];
    piece.end = corners[(k + 1) % 4];
    piece.elements = elements / 4;
    bem::BoundaryCondition bc;
    if (k == 0) {
      bc.kind = {bem::ConditionKind::displacement, bem::ConditionKind::displacement};
      bc.signature = "clamped";
    } else if (k == 2) {
      bc.value[1] = [](const Vec2&) { return 1.0; };
      bc.signature = "pulled";
    }
    piece.condition_signature = bc.signature;
    problem.body.pieces.push_back(piece);
    problem.body.conditions.push_back(bc);
  }
  return problem;
}

void BM_PlaneAssembly(benchmark::State& state) {
  bench::measure_assembly(state, square_plate(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_PlaneAssembly)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Quadratic elements (Gauss quadrature, plane_element_quadrature.cpp): half as many
// elements as the linear runs above for the same number of nodes.
void BM_PlaneAssemblyQuadratic(benchmark::State& state) {
  auto problem = square_plate(static_cast<int>(state.range(0)));
  problem.mesh.interpolation = Interpolation::quadratic;
  bench::measure_assembly(state, problem);
}
BENCHMARK(BM_PlaneAssemblyQuadratic)->Arg(124)->Arg(248)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_DenseLU(benchmark::State& state) {
  const auto problem = square_plate(static_cast<int>(state.range(0)));
  const auto mesh = bem::mesh_body(problem);
  const bem::ElementIntegrator integrator(problem.analysis, problem.body.material);
  auto m = bem::assemble_influence_matrices(mesh, integrator);
  const auto conditions = bem::resolve_node_conditions(mesh, problem.body, problem.analysis);
  auto system = bem::build_boundary_system(m, conditions, {});
  const double n = static_cast<double>(system.A.rows());
  for (auto _ : state) {
    operators::DenseLU lu(system.A);
    benchmark::DoNotOptimize(lu.reciprocal_condition());
  }
  state.counters["unknowns"] = n;
  state.counters["GFLOPs"] = benchmark::Counter(2.0 / 3.0 * n * n * n * 1e-9,
                                                benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_DenseLU)->Arg(250)->Arg(500)->Arg(1000)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The machine's dgemm on all threads, the peak the tiled LU is measured against: OpenMP
// over blocks of columns, each a single-threaded dgemm (the library keeps OpenBLAS on one
// thread and threads its own tiles, operators/dense_lu.cpp).
void BM_Dgemm(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Matrix a = Matrix::Random(n, n), b = Matrix::Random(n, n), c = Matrix::Zero(n, n);
  constexpr int block = 256;
  const int blocks = (n + block - 1) / block;
  for (auto _ : state) {
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < blocks; ++k) {
      const int first = k * block, columns = std::min(block, n - first);
      cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, n, columns, n, 1.0, a.data(), n,
                  b.data() + static_cast<Index>(first) * n, n, 0.0, c.data() + static_cast<Index>(first) * n, n);
    }
    benchmark::DoNotOptimize(c.data());
  }
  state.counters["GFLOPs"] =
      benchmark::Counter(2.0 * n * n * n * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Dgemm)->Arg(1000)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

// The whole one-body solve (assembly, factorisation, solve, boundary stresses) dense
// against compressed (hierarchical matrices, accuracy 1e-10, the default) on the square
// plate: 2 000 to 8 000 unknowns both ways, 16 000 compressed. Counters: unknowns, the compressed share of stored
// values. bench/scaling_compressed.sh goes to 128k unknowns with peak memory. With
// progress = 1 a listener hears every phase (as the command on a terminal): the cost of the
// reports, against the same size without.
void BM_WholeSolve(benchmark::State& state) {
  bench::measure_whole_solve(state, square_plate(static_cast<int>(state.range(0))), state.range(1) != 0,
                             state.range(2) != 0);
}
BENCHMARK(BM_WholeSolve)  // (dense at 16 000 unknowns would take 2 GB and a minute)
    ->Args({1000, 0, 0})->Args({1000, 1, 0})->Args({2000, 0, 0})->Args({2000, 1, 0})->Args({4000, 0, 0})
    ->Args({4000, 0, 1})->Args({4000, 1, 0})->Args({4000, 1, 1})->Args({8000, 1, 0})->Args({8000, 1, 1})
    ->ArgNames({"elements", "compressed", "progress"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK_MAIN();

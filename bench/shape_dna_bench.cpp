// Shape-DNA (mesh/shape_dna.h): the time per mesh of the retrieval baseline,
// the figure of docs/benchmarks.md.
//
//   build/bench/shape_dna_bench [--benchmark_filter=...]
//
// The 50 eigenvalues of the default options on generated tori of about 10k
// and 50k vertices (major x minor = 180 x 56 and 400 x 125, triangles close
// to equilateral-right), and the assembly of the two matrices on its own.
// Single-threaded code.
#include "reebkit/mesh/shape_dna.h"
#include "reebkit/mesh/shapes.h"

#include <benchmark/benchmark.h>

namespace {

using namespace reebkit;

Mesh torus(int vertices) { return vertices < 20000 ? make_torus(180, 56, 1.0, 0.35) : make_torus(400, 125, 1.0, 0.35); }

void BM_ShapeDna(benchmark::State& state) {
  const Mesh mesh = torus(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(shape_dna(mesh));
  state.counters["vertices"] = static_cast<double>(mesh.num_vertices());
}
BENCHMARK(BM_ShapeDna)->Arg(10000)->Arg(50000)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_LaplaceBeltramiMatrices(benchmark::State& state) {
  const Mesh mesh = torus(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(laplace_beltrami(mesh));
  state.counters["vertices"] = static_cast<double>(mesh.num_vertices());
}
BENCHMARK(BM_LaplaceBeltramiMatrices)->Arg(10000)->Arg(50000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

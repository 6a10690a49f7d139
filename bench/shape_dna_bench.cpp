// Shape-DNA (mesh/shape_dna.h): the time per mesh of the retrieval baseline,
// and the spectra that the graph attributes compute (attributes/
// region_spectra.h): the figures of docs/benchmarks.md.
//
//   build/bench/shape_dna_bench [--benchmark_filter=...]
//
// The 50 eigenvalues of the default options on generated tori of about 10k
// and 50k vertices (major x minor = 180 x 56 and 400 x 125, triangles close
// to equilateral-right), and the assembly of the two matrices on its own.
// Single-threaded code.
#include "reebkit/attributes/region_spectra.h"
#include "reebkit/mesh/decimation.h"
#include "reebkit/mesh/shape_dna.h"
#include "reebkit/mesh/shapes.h"

#include <cmath>

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

/// 12 regions: bands of the torus by angle around its axis.
std::vector<Index> bands(const Mesh& mesh) {
  std::vector<Index> label(static_cast<std::size_t>(mesh.num_vertices()));
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const double angle = std::atan2(mesh.vertices(v, 1), mesh.vertices(v, 0)) + M_PI;  // [0, 2 pi]
    label[static_cast<std::size_t>(v)] = std::min<Index>(11, static_cast<Index>(angle / (2 * M_PI) * 12));
  }
  return label;
}

void BM_SurfaceSpectra(benchmark::State& state) {
  const Mesh mesh = torus(static_cast<int>(state.range(0)));
  const std::vector<Index> label = bands(mesh);
  for (auto _ : state) benchmark::DoNotOptimize(surface_spectra(mesh, label, 12));
  state.counters["vertices"] = static_cast<double>(mesh.num_vertices());
}
BENCHMARK(BM_SurfaceSpectra)->Arg(10000)->Arg(50000)->Unit(benchmark::kMillisecond);

void BM_DecimateToSpectraSize(benchmark::State& state) {
  const Mesh mesh = torus(static_cast<int>(state.range(0)));
  const double ratio = static_cast<double>(SpectraOptions{}.coarse_vertices) / static_cast<double>(mesh.num_vertices());
  for (auto _ : state) benchmark::DoNotOptimize(decimate_mesh(mesh, {ratio, 0.05}));
  state.counters["vertices"] = static_cast<double>(mesh.num_vertices());
}
BENCHMARK(BM_DecimateToSpectraSize)->Arg(10000)->Arg(50000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

// Geodesics and feature points: the speed figures of docs/benchmarks.md.
//
//   build/bench/features_bench [--benchmark_filter=...]
//
// Dijkstra and fast marching: one full single-source pass on generated tori
// of 10k, 100k and 1M vertices (items/s = vertices settled per second; target
// >= 4 M/s on one core); fast marching's one-time precomputation (third sides
// of the triangles, splits of obtuse corners) on its own. Features: feature
// points + f_q from a built mesh graph (target <= 60 ms for a 100k-face
// mesh), with Dijkstra and (the _FMM cases) fast marching, on generated
// meshes (default options: extrema filtered by persistence; the _AllExtrema
// cases with every local extremum, the paper's rule; the persistence of one
// field on its own) and, when ../shared is beside the checkout, on the largest SHREC07
// mesh. Single-threaded code.
#include "reebkit/features/feature_points.h"
#include "reebkit/features/persistence.h"
#include "reebkit/features/quotient_function.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/geodesic/fast_marching.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace {

using namespace reebkit;

// Meshes are built once per process and shared by the benchmarks.
struct Case {
  Mesh mesh;
  MeshGraph graph;
};

const Case& torus_case(int major, int minor) {
  static std::map<std::pair<int, int>, std::unique_ptr<Case>> cache;
  auto& slot = cache[{major, minor}];
  if (!slot) {
    slot = std::make_unique<Case>();
    slot->mesh = make_torus(major, minor, 1.0, 0.35);
    slot->graph = build_mesh_graph(slot->mesh);
  }
  return *slot;
}

const Case& star_case(int levels) {
  static std::map<int, std::unique_ptr<Case>> cache;
  auto& slot = cache[levels];
  if (!slot) {
    StarOptions options;
    options.arms = 6;
    options.levels = levels;
    slot = std::make_unique<Case>();
    slot->mesh = make_star(options);
    slot->graph = build_mesh_graph(slot->mesh);
  }
  return *slot;
}

void report_size(benchmark::State& state, const Case& c) {
  state.counters["vertices"] = c.mesh.num_vertices();
  state.counters["faces"] = c.mesh.num_triangles();
}

// One full single-source pass per iteration, from a different source each time.
template <class Solver>
void run_full_passes(benchmark::State& state, const Case& c) {
  Solver solver(c.graph);
  Index source = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solver.run({source}).max_distance);
    source = (source + 7919) % c.mesh.num_vertices();
  }
  state.SetItemsProcessed(state.iterations() * c.mesh.num_vertices());
  report_size(state, c);
}

// Tori with major x minor = 10k, 100k, 1M vertices.
const Case& torus_arg(const benchmark::State& state) {
  return torus_case(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
}
void BM_DijkstraFullPass(benchmark::State& state) { run_full_passes<DijkstraSolver>(state, torus_arg(state)); }
BENCHMARK(BM_DijkstraFullPass)->Args({200, 50})->Args({500, 200})->Args({2000, 500})->Unit(benchmark::kMillisecond);
void BM_FastMarchingFullPass(benchmark::State& state) { run_full_passes<FastMarchingSolver>(state, torus_arg(state)); }
BENCHMARK(BM_FastMarchingFullPass)->Args({200, 50})->Args({500, 200})->Args({2000, 500})->Unit(benchmark::kMillisecond);

// The solver's construction: paid once per extract_feature_points and once
// per quotient_function.
void BM_FastMarchingSetup(benchmark::State& state) {
  const Case& c = torus_arg(state);
  for (auto _ : state) benchmark::DoNotOptimize(FastMarchingSolver(c.graph).split_corners());
  state.SetItemsProcessed(state.iterations() * c.mesh.num_vertices());
  report_size(state, c);
}
BENCHMARK(BM_FastMarchingSetup)->Args({500, 200})->Unit(benchmark::kMillisecond);

// The geodesic passes of the feature step and f_q. Full: single-source
// passes over the whole mesh, the diameter ends' sweeps (Dijkstra's search,
// then f1, f2 and the extra sweeps and seeds), the average rule's samples,
// and f_q's pass where it covers every vertex (no diameter end among the
// feature points). Equivalents: those passes plus the share of the vertices
// f_q's pass settled (the other feature points' Voronoi cells,
// quotient_function.h). The epsilon balls, restricted to epsilon x diameter,
// count in neither.
struct Passes {
  int full = 0;
  double equivalents = 0.0;
};
Passes passes_of(const FeaturePoints& fp, const QuotientFunction& fq) {
  const int full = fp.sweeps + fp.sample_passes;
  return {full + (fq.pass_share >= 1.0 ? 1 : 0), full + fq.pass_share};
}

void run_features(benchmark::State& state, const Case& c, Geodesic method = Geodesic::Dijkstra,
                  double min_persistence = FeatureOptions{}.min_persistence,
                  FeatureRule rule = FeatureRule::Intersection) {
  FeatureOptions options;
  options.geodesic = method;
  options.min_persistence = min_persistence;
  options.rule = rule;
  std::size_t count = 0;
  Passes passes;
  for (auto _ : state) {
    const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(c.graph, method);
    const FeaturePoints fp = extract_feature_points(c.mesh, c.graph, options, *solver);
    const QuotientFunction fq = quotient_function(*solver, fp);
    benchmark::DoNotOptimize(fq.value.data());
    count = fp.vertices.size();
    passes = passes_of(fp, fq);
  }
  state.counters["feature_points"] = static_cast<double>(count);
  state.counters["full_passes"] = passes.full;
  state.counters["pass_equivalents"] = passes.equivalents;
  report_size(state, c);
}

// A torus of 50k vertices and exactly 100k faces.
void BM_FeaturesAndQuotient_Torus100kFaces(benchmark::State& state) { run_features(state, torus_case(250, 200)); }
BENCHMARK(BM_FeaturesAndQuotient_Torus100kFaces)->Unit(benchmark::kMillisecond);
void BM_FeaturesAndQuotient_Torus100kFaces_FMM(benchmark::State& state) {
  run_features(state, torus_case(250, 200), Geodesic::FastMarching);
}
BENCHMARK(BM_FeaturesAndQuotient_Torus100kFaces_FMM)->Unit(benchmark::kMillisecond);
// The paper's rule: every local extremum of f1 and f2 (min_persistence 0),
// without the persistence of each.
void BM_FeaturesAndQuotient_Torus100kFaces_AllExtrema(benchmark::State& state) {
  run_features(state, torus_case(250, 200), Geodesic::Dijkstra, 0.0);
}
BENCHMARK(BM_FeaturesAndQuotient_Torus100kFaces_AllExtrema)->Unit(benchmark::kMillisecond);
void BM_FeaturesAndQuotient_Torus100kFaces_FMM_AllExtrema(benchmark::State& state) {
  run_features(state, torus_case(250, 200), Geodesic::FastMarching, 0.0);
}
BENCHMARK(BM_FeaturesAndQuotient_Torus100kFaces_FMM_AllExtrema)->Unit(benchmark::kMillisecond);

// The persistence of every extremum of one distance field (a sort of the
// vertices, then a union-find sweep each way); extract_feature_points with
// min_persistence > 0 pays it for f1 and f2.
void BM_ExtremaPersistence_Torus100kFaces(benchmark::State& state) {
  const Case& c = torus_case(250, 200);
  const std::vector<double> f = dijkstra(c.graph, 0).distance;
  for (auto _ : state) benchmark::DoNotOptimize(extrema_persistence(c.graph, f).maxima.data());
  state.SetItemsProcessed(state.iterations() * c.mesh.num_vertices());
  report_size(state, c);
}
BENCHMARK(BM_ExtremaPersistence_Torus100kFaces)->Unit(benchmark::kMillisecond);

// Six-armed stars: levels 6 = 82k faces, 7 = 328k faces.
void BM_FeaturesAndQuotient_Star(benchmark::State& state) {
  run_features(state, star_case(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_FeaturesAndQuotient_Star)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);
void BM_FeaturesAndQuotient_Star_FMM(benchmark::State& state) {
  run_features(state, star_case(static_cast<int>(state.range(0))), Geodesic::FastMarching);
}
BENCHMARK(BM_FeaturesAndQuotient_Star_FMM)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);
// The tips of the mean geodesic distance (FeatureRule::Average).
void BM_FeaturesAndQuotient_Star_FMM_Average(benchmark::State& state) {
  run_features(state, star_case(static_cast<int>(state.range(0))), Geodesic::FastMarching,
               FeatureOptions{}.min_persistence, FeatureRule::Average);
}
BENCHMARK(BM_FeaturesAndQuotient_Star_FMM_Average)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);

// A torus of 1M vertices (2M faces).
void BM_FeaturesAndQuotient_Torus1M(benchmark::State& state) { run_features(state, torus_case(2000, 500)); }
BENCHMARK(BM_FeaturesAndQuotient_Torus1M)->Unit(benchmark::kMillisecond);
void BM_FeaturesAndQuotient_Torus1M_FMM(benchmark::State& state) {
  run_features(state, torus_case(2000, 500), Geodesic::FastMarching);
}
BENCHMARK(BM_FeaturesAndQuotient_Torus1M_FMM)->Unit(benchmark::kMillisecond);

void BM_MeshGraph_Torus100kFaces(benchmark::State& state) {
  const Case& c = torus_case(250, 200);
  for (auto _ : state) benchmark::DoNotOptimize(build_mesh_graph(c.mesh).neighbor.data());
  report_size(state, c);
}
BENCHMARK(BM_MeshGraph_Torus100kFaces)->Unit(benchmark::kMillisecond);

// The full passes of the feature step under `options` + f_q over every mesh
// of a folder (issue 23 aims at 5 per mesh): mean, max and the share at 5
// or fewer. Run once: the time is the whole folder's.
void count_full_passes(benchmark::State& state, const std::filesystem::path& folder, const FeatureOptions& options) {
  std::vector<Passes> passes;
  for (auto _ : state) {
    passes.clear();
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() != ".off") continue;
      const Mesh mesh = load_mesh(entry.path()).components.front();
      const MeshGraph graph = build_mesh_graph(mesh);
      const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(graph, options.geodesic);
      const FeaturePoints fp = extract_feature_points(mesh, graph, options, *solver);
      passes.push_back(passes_of(fp, quotient_function(*solver, fp)));
    }
  }
  const double n = static_cast<double>(passes.size());
  double full = 0.0, equivalents = 0.0;
  int most = 0, at_most_5 = 0;
  for (const Passes& p : passes) {
    full += p.full;
    equivalents += p.equivalents;
    most = std::max(most, p.full);
    at_most_5 += p.full <= 5;
  }
  state.counters["meshes"] = n;
  state.counters["mean_passes"] = full / n;
  state.counters["max_passes"] = most;
  state.counters["share_at_most_5"] = at_most_5 / n;
  state.counters["mean_pass_equivalents"] = equivalents / n;
}

// The largest SHREC07 Watertight mesh (27,824 vertices), when present.
void register_shrec() {
  const std::filesystem::path unpacked = std::filesystem::path(REEBKIT_UNPACKED_DATASETS) / "shrec07_watertight";
  if (!std::filesystem::is_directory(unpacked)) return;
  std::filesystem::path largest;
  std::uintmax_t size = 0;
  for (const auto& entry : std::filesystem::directory_iterator(unpacked))
    if (entry.path().extension() == ".off" && entry.file_size() > size) {
      size = entry.file_size();
      largest = entry.path();
    }
  if (largest.empty()) return;
  static Case shrec;
  shrec.mesh = load_mesh(largest).components.front();
  shrec.graph = build_mesh_graph(shrec.mesh);
  const std::string name = largest.filename().string();
  benchmark::RegisterBenchmark(("BM_FeaturesAndQuotient_SHREC07/" + name).c_str(), [](benchmark::State& state) {
    run_features(state, shrec);
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("BM_FeaturesAndQuotient_SHREC07_FMM/" + name).c_str(), [](benchmark::State& state) {
    run_features(state, shrec, Geodesic::FastMarching);
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("BM_FeaturesAndQuotient_SHREC07_FMM_Average/" + name).c_str(), [](benchmark::State&
                                                                                                      state) {
    run_features(state, shrec, Geodesic::FastMarching, FeatureOptions{}.min_persistence, FeatureRule::Average);
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("BM_DijkstraFullPass_SHREC07/" + name).c_str(), [](benchmark::State& state) {
    run_full_passes<DijkstraSolver>(state, shrec);
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("BM_FastMarchingFullPass_SHREC07/" + name).c_str(), [](benchmark::State& state) {
    run_full_passes<FastMarchingSolver>(state, shrec);
  })->Unit(benchmark::kMillisecond);
  // Default options (the search held to four passes), the search without
  // that bound (FeatureOptions::max_search_passes 0, layout 15) and the
  // average rule.
  FeatureOptions unbounded, average;
  unbounded.max_search_passes = 0;
  average.rule = FeatureRule::Average;
  const std::pair<std::string, FeatureOptions> variants[] = {{"", FeatureOptions{}},
                                                             {"/max_search_passes:0", unbounded},
                                                             {"/feature_rule:average", average}};
  for (const auto& [suffix, options] : variants)
    benchmark::RegisterBenchmark(("BM_FullPasses_SHREC07All" + suffix).c_str(),
                                 [unpacked, options = options](benchmark::State& state) {
                                   count_full_passes(state, unpacked, options);
                                 })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
}

}  // namespace

int main(int argc, char** argv) {
  register_shrec();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

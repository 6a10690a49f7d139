// Reading speed of read_polygon_soup on a generated torus of 1,000,000
// triangles (500,000 vertices), written once per format with write_mesh:
// ASCII OFF (coordinates in their shortest exact form, ~17 digits) and binary PLY;
// and load_mesh, the read followed by the cleaning every command does
// (mesh/mesh_cleanup.h), to compare the two (issue 23: read + clean <= 1.5x
// the read alone).
//   build/bench/io_bench
#include "reebkit/io/mesh_io.h"
#include "reebkit/mesh/load_mesh.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

namespace {

using reebkit::Index;

/// A torus of `rings` x `segments` quads, each split into two triangles.
reebkit::Mesh torus(Index rings, Index segments) {
  constexpr double kMajor = 3.0;
  constexpr double kMinor = 1.0;
  const double pi = std::acos(-1.0);
  reebkit::Mesh mesh;
  mesh.vertices.resize(rings * segments, 3);
  mesh.triangles.resize(2 * rings * segments, 3);
  for (Index i = 0; i < rings; ++i) {
    const double u = 2 * pi * i / rings;
    for (Index j = 0; j < segments; ++j) {
      const double v = 2 * pi * j / segments;
      const Index a = i * segments + j;
      mesh.vertices.row(a) << (kMajor + kMinor * std::cos(v)) * std::cos(u),
          (kMajor + kMinor * std::cos(v)) * std::sin(u), kMinor * std::sin(v);
      const Index b = i * segments + (j + 1) % segments;
      const Index c = ((i + 1) % rings) * segments + j;
      const Index d = ((i + 1) % rings) * segments + (j + 1) % segments;
      mesh.triangles.row(2 * a) << a, c, b;
      mesh.triangles.row(2 * a + 1) << b, c, d;
    }
  }
  return mesh;
}

/// The benchmark files, written on first use and removed at exit.
class TorusFiles {
 public:
  ~TorusFiles() {
    for (const auto& entry : paths_) std::filesystem::remove(entry.second);
  }

  const std::filesystem::path& get(const std::string& extension) {
    auto [it, inserted] = paths_.try_emplace(extension);
    if (inserted) {
      it->second =
          std::filesystem::temp_directory_path() / ("reebkit_io_bench_" + std::to_string(::getpid()) + extension);
      reebkit::write_mesh(it->second, torus(1000, 500));
    }
    return it->second;
  }

 private:
  std::map<std::string, std::filesystem::path> paths_;
};

TorusFiles files;

void read_polygon_soup(benchmark::State& state, const std::string& extension) {
  const std::filesystem::path& path = files.get(extension);
  Index faces = 0;
  for (auto _ : state) {
    const reebkit::PolygonSoup soup = reebkit::read_polygon_soup(path);
    faces = soup.num_polygons();
    benchmark::DoNotOptimize(soup.face_vertex.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * std::filesystem::file_size(path)));
  state.counters["faces"] = faces;
  state.counters["faces/s"] = benchmark::Counter(static_cast<double>(faces) * static_cast<double>(state.iterations()),
                                                 benchmark::Counter::kIsRate);
}

void load_mesh(benchmark::State& state, const std::string& extension) {
  const std::filesystem::path& path = files.get(extension);
  for (auto _ : state) {
    const reebkit::CleanedMesh cleaned = reebkit::load_mesh(path);
    benchmark::DoNotOptimize(cleaned.components.front().triangles.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * std::filesystem::file_size(path)));
}

BENCHMARK_CAPTURE(read_polygon_soup, off_ascii_1M_faces, std::string(".off"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_polygon_soup, ply_binary_1M_faces, std::string(".ply"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load_mesh, off_ascii_1M_faces, std::string(".off"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load_mesh, ply_binary_1M_faces, std::string(".ply"))->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

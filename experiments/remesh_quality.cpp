// Degenerate triangles in remeshed variants (issue: remeshing without
// degenerate triangles): N remeshes of meshes drawn from the given folders,
// each with a random seed and a random target of 0.25x to 4x the mesh's
// vertex count (log-uniform), capped at MAX_VERTICES so that a run takes
// minutes. Counts the triangles of zero area (at most 1e-12 x the largest
// triangle of the variant, the test of the issue) and those at or below
// MIN_AREA (RemeshOptions::min_triangle_area) x the mean, and the remeshes that failed
// (their error names the seed). Prints one line per failure and the totals;
// exits 1 when a variant holds a degenerate triangle or a remesh failed.
//
//   D=build/data
//   build/experiments/remesh_quality 1000 26 20000 default $D/shrec07_watertight $D/tosca_dev
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/mesh/degenerate_triangles.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/remeshing.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 6) {
    std::cerr << "usage: remesh_quality N SEED MAX_VERTICES MIN_AREA MESH_DIR...   (MIN_AREA: "
                 "RemeshOptions::min_triangle_area, 'default' for its default; threads: OMP_NUM_THREADS)\n";
    return 2;
  }
  using namespace reebkit;
  try {
    const int n = std::stoi(argv[1]);
    const auto max_vertices = static_cast<double>(std::stoll(argv[3]));
    std::vector<std::filesystem::path> files;
    const std::vector<std::string> folders(argv + 5, argv + argc);
    for (const MeshInput& input : list_mesh_inputs(folders)) files.push_back(input.path);
    if (files.empty()) throw Error("remesh_quality: no mesh in the folders given");
    // The draws first, from one generator: the same list whatever the threads.
    struct Draw {
      std::size_t file;
      std::uint64_t seed;
      double factor;
    };
    std::mt19937_64 random(std::stoull(argv[2]));
    std::vector<Draw> draws;
    for (int i = 0; i < n; ++i) {
      const std::size_t file = std::uniform_int_distribution<std::size_t>(0, files.size() - 1)(random);
      const std::uint64_t seed = random();
      const double factor = std::exp(std::uniform_real_distribution<double>(std::log(0.25), std::log(4.0))(random));
      draws.push_back({file, seed, factor});
    }
    RemeshOptions defaults;
    if (std::string(argv[4]) != "default") defaults.min_triangle_area = std::stod(argv[4]);
    long zero_area = 0, degenerate = 0, triangles = 0, failed = 0, variants_with_defect = 0;
    Timer timer;
#pragma omp parallel for schedule(dynamic) reduction(+ : zero_area, degenerate, triangles, failed, variants_with_defect)
    for (int i = 0; i < n; ++i) {
      const Draw& d = draws[static_cast<std::size_t>(i)];
      try {
        const Mesh mesh = std::move(load_mesh(files[d.file]).components.front());
        RemeshOptions options = defaults;
        options.seed = d.seed;
        options.target_vertices =
            static_cast<Index>(std::max(4.0, std::round(std::min(max_vertices, d.factor * mesh.num_vertices()))));
        const Mesh out = remesh(mesh, options).mesh;
        double largest = 0;
        for (Index t = 0; t < out.num_triangles(); ++t) largest = std::max(largest, triangle_area(out, t));
        long zero = 0;
        for (Index t = 0; t < out.num_triangles(); ++t) zero += triangle_area(out, t) <= 1e-12 * largest;
        const auto small = static_cast<long>(degenerate_triangles(out, defaults.min_triangle_area).size());
        zero_area += zero;
        degenerate += small;
        triangles += out.num_triangles();
        variants_with_defect += zero + small > 0;
        if (zero + small > 0) {
#pragma omp critical
          std::cout << files[d.file].filename().string() << " seed " << d.seed << " target " << options.target_vertices
                    << ": " << zero << " zero-area, " << small << " degenerate\n";
        }
      } catch (const std::exception& e) {
        ++failed;
#pragma omp critical
        std::cout << "failed: " << e.what() << "\n";
      }
    }
    std::cout << n << " remeshes of " << files.size() << " meshes (targets 0.25x-4x, at most " << argv[3]
              << " vertices, draw seed " << argv[2] << ") in " << timer.lap() / 1000 << " s: " << triangles
              << " triangles, " << zero_area << " of zero area (<= 1e-12 x the largest), " << degenerate
              << " at or below " << defaults.min_triangle_area << " x the mean, " << variants_with_defect
              << " variants with either, " << failed << " remeshes failed\n";
    return zero_area + degenerate + failed > 0 ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "remesh_quality: " << e.what() << "\n";
    return 2;
  }
}

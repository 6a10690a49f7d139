// Three baseline shape descriptors for retrieval, to stand next to reebkit's
// graph matching in the same evaluation (reeb eval):
//  - D2, the shape distribution of Osada, Funkhouser, Chazelle and Dobkin
//    ("Shape distributions", ACM TOG 2002): the histogram of Euclidean
//    distances between random pairs of surface points (area-weighted
//    sampling), distances divided by their mean (scale invariance);
//  - a geodesic distance histogram, invariant to isometric bending: the
//    area-weighted histogram of the geodesic distances (Dijkstra on the mesh
//    graph) from farthest-point-sampled sources to every vertex, divided by
//    the largest of them (the geodesic diameter, approximately);
//  - Shape-DNA (Reuter, Wolter and Peinecke, CAD 2006): the first 50
//    eigenvalues of the Laplace-Beltrami operator normalized by the area
//    (mesh/shape_dna.h), an isometry invariant.
// Histograms are compared with the L1 distance, Shape-DNAs with
// shape_dna_distance. Writes one PSB binary
// .matrix per method, rows in .cla order, and prints each method's nearest
// neighbour rate (query left out, ties to the lower index, classes of fewer
// than 3 models not queried, as reeb eval).
// A model a method cannot describe (no mesh file, a mesh that does not load,
// a descriptor error) is reported and gets the largest distance to every
// other model in that method's matrix, as a failed entry gets in `reeb
// distances` (kFailedEntryDistance, 0 on the diagonal); the run goes on and
// lists the failures at the end (batch_failures.h). Exit status 1 only when
// a method described no model at all.
//
//   D=build/data/shrec07_watertight
//   build/experiments/baselines $D $D/shrec07_watertight.cla /tmp/out/shrec07
//   -> /tmp/out/shrec07-d2.matrix, /tmp/out/shrec07-geodesic.matrix,
//      /tmp/out/shrec07-shape-dna.matrix
#include "batch_failures.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/core/error.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/mesh_graph.h"
#include "reebkit/mesh/shape_dna.h"
#include "reebkit/mesh/surface_sampling.h"
#include "reebkit/retrieval/all_pairs.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

using reebkit::Index;
using reebkit::Mesh;
using reebkit::Vec3;
using Histogram = std::vector<double>;

constexpr int kBins = 64;
constexpr int kD2Samples = 1024;  // 1024 points: 523,776 pairs
constexpr double kD2Range = 4.0;  // D2 bins cover [0, 4 x mean distance); beyond goes to the last bin
constexpr int kGeodesicSources = 64;

void add(Histogram& h, double x, double weight) {
  const int bin = std::clamp(static_cast<int>(x * kBins), 0, kBins - 1);
  h[static_cast<std::size_t>(bin)] += weight;
}

Histogram normalized(Histogram h) {
  double sum = 0;
  for (const double x : h) sum += x;
  if (sum > 0)
    for (double& x : h) x /= sum;
  return h;
}

/// D2 with a fixed seed: every mesh gets the same random sequence.
Histogram d2(const Mesh& m) {
  const std::vector<Vec3> points = reebkit::sample_surface(m, reebkit::triangle_areas(m).view(), kD2Samples, 2002);
  std::vector<double> distances;
  distances.reserve(points.size() * (points.size() - 1) / 2);
  double sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) sum += distances.emplace_back((points[i] - points[j]).norm());
  const double mean = sum / static_cast<double>(distances.size());
  Histogram h(kBins, 0.0);
  for (const double d : distances) add(h, d / (mean * kD2Range), 1.0);
  return normalized(h);
}

/// Geodesic distance histogram from farthest-point-sampled sources: the first
/// source is the vertex farthest from vertex 0, each next one the vertex
/// farthest from those chosen.
Histogram geodesic(const Mesh& m) {
  const reebkit::MeshGraph graph = reebkit::build_mesh_graph(m);
  std::vector<double> vertex_area(static_cast<std::size_t>(m.num_vertices()), 0.0);
  for (Index f = 0; f < m.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) vertex_area[static_cast<std::size_t>(m.triangles(f, k))] += triangle_area(m, f) / 3;
  reebkit::DijkstraSolver solver(graph);
  Index source = solver.run({0}).farthest;
  std::vector<double> nearest(vertex_area.size(), INFINITY);
  std::vector<std::vector<double>> fields;
  double diameter = 0;
  for (int s = 0; s < kGeodesicSources && source != reebkit::kInvalidIndex; ++s) {
    const reebkit::DistanceField& field = solver.run({source});
    diameter = std::max(diameter, field.max_distance);
    fields.push_back(field.distance);
    for (std::size_t v = 0; v < nearest.size(); ++v) nearest[v] = std::min(nearest[v], field.distance[v]);
    const auto far = std::max_element(nearest.begin(), nearest.end());
    source = *far > 0 ? static_cast<Index>(far - nearest.begin()) : reebkit::kInvalidIndex;
  }
  Histogram h(kBins, 0.0);
  for (const auto& field : fields)
    for (std::size_t v = 0; v < field.size(); ++v) add(h, field[v] / diameter, vertex_area[v]);
  return normalized(h);
}

double l1_distance(const Histogram& a, const Histogram& b) {
  double sum = 0;
  for (std::size_t k = 0; k < a.size(); ++k) sum += std::abs(a[k] - b[k]);
  return sum;
}

/// The n x n matrix of distance(i, j).
reebkit::DistanceMatrix all_pairs(Index n, const std::function<double(std::size_t, std::size_t)>& distance) {
  reebkit::DistanceMatrix d(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j)
      d(i, j) = static_cast<float>(distance(static_cast<std::size_t>(i), static_cast<std::size_t>(j)));
  return d;
}

/// Fraction of the queries (models of classes with >= 3 models) whose nearest
/// other model, ties to the lower index, is in their class.
double nearest_neighbor_rate(const reebkit::DistanceMatrix& d, const std::vector<int>& label,
                             const std::vector<int>& class_size) {
  int queries = 0, hits = 0;
  for (Index i = 0; i < d.rows(); ++i) {
    if (class_size[static_cast<std::size_t>(label[static_cast<std::size_t>(i)])] < 3) continue;
    Index best = i == 0 ? 1 : 0;
    for (Index j = 0; j < d.cols(); ++j)
      if (j != i && d(i, j) < d(i, best)) best = j;
    ++queries;
    hits += label[static_cast<std::size_t>(best)] == label[static_cast<std::size_t>(i)];
  }
  return queries ? static_cast<double>(hits) / queries : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: baselines MESH_DIR CLASSES.cla OUT_PREFIX   (writes OUT_PREFIX-d2.matrix, "
                 "OUT_PREFIX-geodesic.matrix, OUT_PREFIX-shape-dna.matrix; threads: OMP_NUM_THREADS)\n";
    return 2;
  }
  try {
    const std::vector<reebkit::PsbClass> classes = reebkit::read_psb_classes(argv[2]);
    std::map<std::string, std::filesystem::path> file_of;  // model id (name without extension) -> file
    for (const reebkit::MeshInput& input : reebkit::list_mesh_inputs({argv[1]}))
      file_of[std::filesystem::path(input.name).replace_extension().generic_string()] = input.path;
    std::vector<std::filesystem::path> files;  // empty: the model has no mesh file
    std::vector<std::string> models;
    std::vector<int> label, class_size;
    for (const reebkit::PsbClass& c : classes) {
      class_size.push_back(static_cast<int>(c.models.size()));
      for (const std::string& model : c.models) {
        const auto it = file_of.find(model);
        files.push_back(it == file_of.end() ? std::filesystem::path() : it->second);
        models.push_back(model);
        label.push_back(static_cast<int>(class_size.size()) - 1);
      }
    }
    const Index n = static_cast<Index>(files.size());
    std::vector<Histogram> d2_histograms(files.size()), geodesic_histograms(files.size());
    std::vector<reebkit::ShapeDna> spectra(files.size());
    // Per method, the time per model, whether it failed, and the failures.
    struct Outcome {
      std::vector<double> ms;
      std::vector<char> failed;
      BatchFailures failures;
    };
    std::array<Outcome, 3> outcome = {Outcome{{}, {}, BatchFailures("baselines d2")},
                                      Outcome{{}, {}, BatchFailures("baselines geodesic")},
                                      Outcome{{}, {}, BatchFailures("baselines shape-dna")}};
    for (Outcome& o : outcome) o.ms.resize(files.size()), o.failed.resize(files.size());
    const auto fail = [&](std::size_t method, std::size_t k, const std::string& why) {
      outcome[method].failed[k] = 1;
      outcome[method].failures.add(why);
    };
    const std::array<std::function<void(const Mesh&, std::size_t)>, 3> describe =
        {[&](const Mesh& mesh, std::size_t k) { d2_histograms[k] = d2(mesh); },
         [&](const Mesh& mesh, std::size_t k) { geodesic_histograms[k] = geodesic(mesh); },
         [&](const Mesh& mesh, std::size_t k) { spectra[k] = reebkit::shape_dna(mesh); }};
#pragma omp parallel for schedule(dynamic)
    for (Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      Mesh mesh;
      try {  // an exception may not leave the parallel loop
        if (files[k].empty())
          throw reebkit::Error(std::string(argv[2]) + ": model " + models[k] + " has no mesh file in " + argv[1]);
        mesh = std::move(reebkit::load_mesh(files[k]).components.front());
      } catch (const std::exception& e) {
        for (std::size_t method = 0; method < outcome.size(); ++method) fail(method, k, e.what());
        continue;
      }
      for (std::size_t method = 0; method < describe.size(); ++method) try {
          const double t = omp_get_wtime();
          describe[method](mesh, k);
          outcome[method].ms[k] = 1e3 * (omp_get_wtime() - t);
        } catch (const std::exception& e) {
          fail(method, k, e.what());
        }
    }
    const std::string prefix = argv[3];
    const auto l1_of = [](const std::vector<Histogram>& h) {
      return [&h](std::size_t i, std::size_t j) { return l1_distance(h[i], h[j]); };
    };
    const auto shape_dna_of = [&spectra](std::size_t i, std::size_t j) {
      return reebkit::shape_dna_distance(spectra[i], spectra[j]);
    };
    using Distance = std::function<double(std::size_t, std::size_t)>;
    const std::array<std::pair<const char*, Distance>, 3> methods = {std::pair{"d2", Distance(l1_of(d2_histograms))},
                                                                     std::pair{"geodesic",
                                                                               Distance(l1_of(geodesic_histograms))},
                                                                     std::pair{"shape-dna", Distance(shape_dna_of)}};
    int status = 0;
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const auto& [method, distance] = methods[m];
      const std::vector<char>& failed = outcome[m].failed;
      const reebkit::DistanceMatrix d = all_pairs(n, [&](std::size_t i, std::size_t j) {
        if (i == j) return 0.0;
        return failed[i] || failed[j] ? reebkit::kFailedEntryDistance : distance(i, j);
      });
      reebkit::write_psb_matrix(prefix + "-" + method + ".matrix", d);
      double total_ms = 0;
      for (const double x : outcome[m].ms) total_ms += x;
      const auto described = static_cast<double>(files.size() - outcome[m].failures.size());
      std::cout << method << ": nearest neighbour " << nearest_neighbor_rate(d, label, class_size) << " over " << n
                << " models (" << outcome[m].failures.size()
                << " failed: the largest float to every other), descriptor "
                << (described > 0 ? total_ms / described : 0.0) << " ms per mesh, wrote " << prefix << "-" << method
                << ".matrix\n";
    }
    for (const Outcome& o : outcome) status = std::max(status, o.failures.finish(files.size()));
    return status;
  } catch (const std::exception& e) {
    std::cerr << "baselines: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

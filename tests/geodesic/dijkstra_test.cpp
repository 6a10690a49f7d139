#include "reebkit/geodesic/dijkstra.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace reebkit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// All-pairs shortest paths by Floyd-Warshall: the oracle for small meshes.
std::vector<std::vector<double>> floyd_warshall(const MeshGraph& g) {
  const auto n = static_cast<std::size_t>(g.num_vertices());
  std::vector<std::vector<double>> d(n, std::vector<double>(n, kInf));
  for (std::size_t v = 0; v < n; ++v) {
    d[v][v] = 0;
    for (Index i = g.offset[v]; i < g.offset[v + 1]; ++i) d[v][static_cast<std::size_t>(g.neighbor[i])] = g.length[i];
  }
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) d[i][j] = std::min(d[i][j], d[i][k] + d[k][j]);
  return d;
}

TEST(Dijkstra, GridDistancesAreAnalytic) {
  const int nx = 12, ny = 9;
  const double h = 0.5;
  const MeshGraph g = build_mesh_graph(make_grid(nx, ny, h));
  const DistanceField f = dijkstra(g, 0);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      EXPECT_NEAR(f.distance[j * (nx + 1) + i], h * (std::min(i, j) * std::sqrt(2.0) + std::abs(i - j)), 1e-12)
          << "(" << i << "," << j << ")";
  EXPECT_EQ(f.farthest, (nx + 1) * (ny + 1) - 1);
  EXPECT_NEAR(f.max_distance, h * (9 * std::sqrt(2.0) + 3), 1e-12);
  EXPECT_EQ(f.reached, (nx + 1) * (ny + 1));
}

TEST(Dijkstra, CubeCornerToOppositeCorner) {
  // make_cube splits every face along a diagonal through vertex 0 or 7, so
  // the shortest path 0 -> 7 is one face diagonal plus one edge.
  const MeshGraph g = build_mesh_graph(make_cube());
  EXPECT_NEAR(dijkstra(g, 0).distance[7], 1 + std::sqrt(2.0), 1e-12);
}

TEST(Dijkstra, MatchesFloydWarshallOnIrregularMeshes) {
  for (const Mesh& mesh : {make_icosphere(2), make_torus(14, 7), make_star(StarOptions{3, 2, 1.5, 0.4, 0.0})}) {
    const MeshGraph g = build_mesh_graph(mesh);
    const auto oracle = floyd_warshall(g);
    for (Index s = 0; s < g.num_vertices(); s += 7) {
      const DistanceField f = dijkstra(g, s);
      for (Index v = 0; v < g.num_vertices(); ++v) EXPECT_NEAR(f.distance[v], oracle[s][v], 1e-12);
    }
  }
}

TEST(Dijkstra, IsSymmetric) {
  const MeshGraph g = build_mesh_graph(make_star(StarOptions{5, 3, 2.0, 0.3, 0.0}));
  std::mt19937 rng(7);
  std::uniform_int_distribution<Index> pick(0, g.num_vertices() - 1);
  for (int k = 0; k < 20; ++k) {
    const Index a = pick(rng), b = pick(rng);
    EXPECT_DOUBLE_EQ(dijkstra(g, a).distance[b], dijkstra(g, b).distance[a]);
  }
}

TEST(Dijkstra, MultiSourceIsTheMinimumOverSingleSources) {
  const MeshGraph g = build_mesh_graph(make_torus(30, 12));
  const std::vector<Index> sources = {3, 100, 257, 301};
  const DistanceField multi = dijkstra(g, sources);
  std::vector<DistanceField> single;
  for (const Index s : sources) single.push_back(dijkstra(g, s));
  for (Index v = 0; v < g.num_vertices(); ++v) {
    double best = kInf;
    for (const auto& f : single) best = std::min(best, f.distance[v]);
    EXPECT_DOUBLE_EQ(multi.distance[v], best);
    // The reported nearest source attains the minimum.
    ASSERT_GE(multi.nearest_source[v], 0);
    EXPECT_DOUBLE_EQ(single[multi.nearest_source[v]].distance[v], best);
  }
}

// A search restricted to one label equals the search on the graph whose
// edges into other labels are cut (infinite length): labels here cut a torus
// into bands so that paths inside one band must go the long way round.
TEST(Dijkstra, LabelsRestrictTheSearchToOneRegion) {
  const MeshGraph g = build_mesh_graph(make_torus(16, 6));
  std::vector<Index> labels(static_cast<std::size_t>(g.num_vertices()));
  for (Index v = 0; v < g.num_vertices(); ++v) labels[v] = (v / 6) % 5 == 0 ? 1 : (v % 6 < 3 ? 2 : 3);
  MeshGraph cut = g;
  for (Index v = 0; v < g.num_vertices(); ++v)
    for (Index i = g.offset[v]; i < g.offset[v + 1]; ++i)
      if (labels[g.neighbor[i]] != labels[v]) cut.length[i] = kInf;
  const auto oracle = floyd_warshall(cut);
  DijkstraSolver solver(g);
  DijkstraOptions options;
  options.labels = &labels;
  for (Index s = 0; s < g.num_vertices(); s += 5) {
    options.label = labels[s];
    const DistanceField& f = solver.run({s}, options);
    Index inside = 0;
    for (Index v = 0; v < g.num_vertices(); ++v) {
      if (oracle[s][v] == kInf || labels[v] != labels[s])
        EXPECT_EQ(f.distance[v], kInf) << s << " -> " << v;
      else
        EXPECT_NEAR(f.distance[v], oracle[s][v], 1e-12) << s << " -> " << v;
      inside += f.distance[v] < kInf ? 1 : 0;
    }
    EXPECT_EQ(f.reached, inside);
  }
}

}  // namespace
}  // namespace reebkit

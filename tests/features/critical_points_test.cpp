#include "reebkit/features/critical_points.h"

#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

namespace reebkit {
namespace {

std::vector<double> random_function(Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> f(static_cast<std::size_t>(n));
  for (double& x : f) x = u(rng);
  return f;
}

std::vector<double> height(const Mesh& mesh, const Vec3& direction) {
  std::vector<double> f(static_cast<std::size_t>(mesh.num_vertices()));
  for (Index v = 0; v < mesh.num_vertices(); ++v) f[v] = mesh.vertices.row(v).dot(direction);
  return f;
}

// Banchoff's index of a vertex of a closed surface: 1 for extrema, 1 - L+
// for the others (a saddle whose link alternates k times has index 1 - k).
int index_of(const MeshGraph& g, const std::vector<double>& f, Index v) {
  const LinkCount c = count_link_components(g, f, v);
  if (c.upper == 0 || c.lower == 0) return 1;
  EXPECT_EQ(c.upper, c.lower) << "on a closed ring upper and lower sets alternate";
  return 1 - c.upper;
}

// L+ and L- by brute force: union-find over the link edges of v's triangles.
LinkCount brute_force_link(const Mesh& mesh, const std::vector<double>& f, Index v) {
  std::vector<Index> parent(static_cast<std::size_t>(mesh.num_vertices()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<Index> link;
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      if (mesh.triangles(t, k) != v) continue;
      const Index a = mesh.triangles(t, (k + 1) % 3), b = mesh.triangles(t, (k + 2) % 3);
      link.push_back(a);
      link.push_back(b);
      if (sos_less(f, v, a) == sos_less(f, v, b)) parent[find(a)] = find(b);
    }
  LinkCount c;
  std::sort(link.begin(), link.end());
  link.erase(std::unique(link.begin(), link.end()), link.end());
  for (const Index a : link)
    if (find(a) == a) (sos_less(f, v, a) ? c.upper : c.lower) += 1;
  return c;
}

struct TypeCounts {
  int minima = 0, maxima = 0, saddles = 0;
};

TypeCounts count_types(const MeshGraph& g, const std::vector<double>& f) {
  TypeCounts c;
  for (Index v = 0; v < g.num_vertices(); ++v) {
    const CriticalType t = classify_vertex(g, f, v);
    c.minima += t == CriticalType::Minimum;
    c.maxima += t == CriticalType::Maximum;
    c.saddles += t == CriticalType::Saddle;
  }
  return c;
}

TEST(CriticalPoints, IndicesSumToTheEulerCharacteristic) {
  // Morse-theory oracle: for any function on a closed surface, the indices of
  // its vertices sum to chi (2 for a sphere, 0 for a torus).
  const std::vector<std::pair<Mesh, int>> cases = {{make_icosphere(3), 2},
                                                   {make_torus(30, 12), 0},
                                                   {make_star(StarOptions{7, 3, 2.0, 0.3, 0.0}), 2}};
  for (const auto& [mesh, chi] : cases) {
    const MeshGraph g = build_mesh_graph(mesh);
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const std::vector<double> f = random_function(mesh.num_vertices(), seed);
      int sum = 0;
      for (Index v = 0; v < g.num_vertices(); ++v) sum += index_of(g, f, v);
      EXPECT_EQ(sum, chi) << "seed " << seed;
    }
  }
}

TEST(CriticalPoints, RingCountMatchesBruteForceIncludingBoundaries) {
  for (const Mesh& mesh : {make_grid(9, 7), make_torus(16, 9), make_icosphere(2)}) {
    const MeshGraph g = build_mesh_graph(mesh);
    const std::vector<double> f = random_function(mesh.num_vertices(), 11);
    for (Index v = 0; v < g.num_vertices(); ++v) {
      const LinkCount fast = count_link_components(g, f, v), slow = brute_force_link(mesh, f, v);
      EXPECT_EQ(fast.upper, slow.upper) << "vertex " << v;
      EXPECT_EQ(fast.lower, slow.lower) << "vertex " << v;
      EXPECT_EQ(is_local_maximum(g, f, v), slow.upper == 0) << "vertex " << v;
    }
  }
}

TEST(CriticalPoints, HeightOnSphereHasOneMinimumAndOneMaximum) {
  const Mesh sphere = make_icosphere(3);
  const MeshGraph g = build_mesh_graph(sphere);
  const std::vector<double> f = height(sphere, Vec3(0.3, 0.2, 0.9).normalized());
  const TypeCounts c = count_types(g, f);
  EXPECT_EQ(c.minima, 1);
  EXPECT_EQ(c.maxima, 1);
  EXPECT_EQ(c.saddles, 0);
  EXPECT_EQ(local_extrema(g, f).size(), 2u);
}

TEST(CriticalPoints, HeightAcrossAStandingTorusHasTwoSaddles) {
  // Torus in the xy-plane, height along x: min, max and two saddles where the
  // level sets pinch at the hole.
  const Mesh torus = make_torus(40, 16);
  const MeshGraph g = build_mesh_graph(torus);
  const std::vector<double> f = height(torus, Vec3(1.0, 0.013, 0.021).normalized());
  const TypeCounts c = count_types(g, f);
  EXPECT_EQ(c.minima, 1);
  EXPECT_EQ(c.maxima, 1);
  EXPECT_EQ(c.saddles, 2);
}

TEST(CriticalPoints, TiesAreBrokenByVertexId) {
  // A constant function: by (value, id) the lowest id is the only minimum and
  // the highest the only maximum.
  const Mesh sphere = make_icosphere(1);
  const MeshGraph g = build_mesh_graph(sphere);
  const std::vector<double> f(static_cast<std::size_t>(sphere.num_vertices()), 0.5);
  EXPECT_EQ(classify_vertex(g, f, 0), CriticalType::Minimum);
  EXPECT_EQ(classify_vertex(g, f, sphere.num_vertices() - 1), CriticalType::Maximum);
}

}  // namespace
}  // namespace reebkit

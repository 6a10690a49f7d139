#include "reebkit/mesh/mesh_graph.h"

#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace reebkit {
namespace {

std::set<std::set<Index>> triangle_set(const Mesh& mesh) {
  std::set<std::set<Index>> out;
  for (Index f = 0; f < mesh.num_triangles(); ++f)
    out.insert({mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)});
  return out;
}

// Every linked pair of ring slots must be a triangle of the mesh, and every
// triangle must appear once in each of its vertices' rings.
void expect_rings_match_triangles(const Mesh& mesh, const MeshGraph& g) {
  const auto tris = triangle_set(mesh);
  std::size_t linked = 0;
  for (Index v = 0; v < g.num_vertices(); ++v) {
    const Index b = g.offset[v], e = g.offset[v + 1];
    for (Index i = b; i < e; ++i) {
      if (!g.link_next[i]) continue;
      const Index next = i + 1 < e ? g.neighbor[i + 1] : g.neighbor[b];
      EXPECT_TRUE(tris.count({v, g.neighbor[i], next})) << "vertex " << v << " slot " << i - b;
      ++linked;
    }
  }
  EXPECT_EQ(linked, 3 * tris.size());
}

TEST(MeshGraph, IcosphereRingsAreClosedCounterClockwiseCycles) {
  const Mesh mesh = make_icosphere(2);
  const MeshGraph g = build_mesh_graph(mesh);
  ASSERT_EQ(g.num_vertices(), mesh.num_vertices());
  EXPECT_EQ(g.num_half_edges(), 3 * mesh.num_triangles());  // 2E, E = 3F/2
  expect_rings_match_triangles(mesh, g);
  for (Index v = 0; v < g.num_vertices(); ++v) {
    EXPECT_EQ(g.ring[v], RingKind::Closed);
    EXPECT_TRUE(g.degree(v) == 5 || g.degree(v) == 6);
    // Outward normal of (v, n_i, n_i+1) agrees with the position (unit sphere).
    const Vec3 p = mesh.vertices.row(v);
    for (Index i = g.offset[v]; i + 1 < g.offset[v + 1]; ++i) {
      const Vec3 a = mesh.vertices.row(g.neighbor[i]), b = mesh.vertices.row(g.neighbor[i + 1]);
      EXPECT_GT((a - p).cross(b - p).dot(p), 0.0) << "vertex " << v;
    }
  }
}

TEST(MeshGraph, EdgeLengthsAreEuclidean) {
  const Mesh mesh = make_torus(12, 8);
  const MeshGraph g = build_mesh_graph(mesh);
  for (Index v = 0; v < g.num_vertices(); ++v)
    for (Index i = g.offset[v]; i < g.offset[v + 1]; ++i)
      EXPECT_DOUBLE_EQ(g.length[i], (mesh.vertices.row(v) - mesh.vertices.row(g.neighbor[i])).norm());
}

TEST(MeshGraph, GridBoundaryRingsAreOpenPaths) {
  const Mesh mesh = make_grid(4, 3);
  const MeshGraph g = build_mesh_graph(mesh);
  expect_rings_match_triangles(mesh, g);
  for (Index v = 0; v < g.num_vertices(); ++v) {
    const int i = v % 5, j = v / 5;
    const bool boundary = i == 0 || i == 4 || j == 0 || j == 3;
    EXPECT_EQ(g.ring[v], boundary ? RingKind::Open : RingKind::Closed) << "vertex " << v;
    if (boundary) {
      EXPECT_EQ(g.link_next[g.offset[v + 1] - 1], 0) << "an open ring does not wrap around";
    }
  }
  EXPECT_EQ(g.degree(0), 3);  // corner (0,0): (1,0), (1,1), (0,1)
  EXPECT_EQ(g.degree(4), 2);  // corner (4,0): (3,0), (4,1)
}

TEST(MeshGraph, InconsistentOrientationStillGivesClosedRings) {
  Mesh mesh = make_icosphere(1);
  for (Index f = 0; f < mesh.num_triangles(); f += 3) std::swap(mesh.triangles(f, 1), mesh.triangles(f, 2));
  const MeshGraph g = build_mesh_graph(mesh);
  expect_rings_match_triangles(mesh, g);
  for (Index v = 0; v < g.num_vertices(); ++v) EXPECT_EQ(g.ring[v], RingKind::Closed);
}

TEST(MeshGraph, BowtieVertexIsIrregular) {
  // Two triangles sharing only vertex 0.
  Mesh mesh;
  mesh.vertices.resize(5, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0;
  mesh.triangles.resize(2, 3);
  mesh.triangles << 0, 1, 2, 0, 3, 4;
  const MeshGraph g = build_mesh_graph(mesh);
  EXPECT_EQ(g.ring[0], RingKind::Irregular);
  EXPECT_EQ(g.degree(0), 4);
  EXPECT_EQ(g.ring[1], RingKind::Open);
  expect_rings_match_triangles(mesh, g);
}

TEST(MeshGraph, NonManifoldEdgeEndpointsAreIrregular) {
  // Three triangles on edge 0-1.
  Mesh mesh;
  mesh.vertices.resize(5, 3);
  mesh.vertices << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1;
  mesh.triangles.resize(3, 3);
  mesh.triangles << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  const MeshGraph g = build_mesh_graph(mesh);
  EXPECT_EQ(g.ring[0], RingKind::Irregular);
  EXPECT_EQ(g.ring[1], RingKind::Irregular);
  EXPECT_EQ(g.degree(0), 4);
  EXPECT_EQ(g.ring[2], RingKind::Open);
}

}  // namespace
}  // namespace reebkit

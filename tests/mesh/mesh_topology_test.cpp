#include "reebkit/mesh/mesh_topology.h"

#include "reebkit/core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace reebkit {
namespace {

Mesh make_mesh(Points vertices, const std::vector<std::vector<Index>>& triangles) {
  Mesh mesh;
  mesh.vertices = std::move(vertices);
  mesh.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    mesh.triangles.row(static_cast<Eigen::Index>(t)) << triangles[t][0], triangles[t][1], triangles[t][2];
  return mesh;
}

/// Topology only looks at the triangles; any positions do.
Mesh make_mesh(Index num_vertices, const std::vector<std::vector<Index>>& triangles) {
  return make_mesh(Points::Zero(num_vertices, 3), triangles);
}

Mesh tetrahedron() { return make_mesh(4, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}); }

Mesh cube() {
  return make_mesh(8, {{0, 3, 2},
                       {0, 2, 1},
                       {4, 5, 6},
                       {4, 6, 7},
                       {0, 1, 5},
                       {0, 5, 4},
                       {1, 2, 6},
                       {1, 6, 5},
                       {2, 3, 7},
                       {2, 7, 6},
                       {3, 0, 4},
                       {3, 4, 7}});
}

/// An n x m grid of squares, each split in two; with `wrap` its opposite
/// sides are identified, giving a torus.
Mesh grid(Index n, Index m, bool wrap) {
  const Index columns = wrap ? n : n + 1;
  const Index rows = wrap ? m : m + 1;
  Points points(columns * rows, 3);
  const double pi = std::acos(-1.0);
  for (Index j = 0; j < rows; ++j) {
    for (Index i = 0; i < columns; ++i) {
      const double u = 2 * pi * i / n;
      const double v = 2 * pi * j / m;
      if (wrap) {
        points.row(j * columns + i) << (2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v);
      } else {
        points.row(j * columns + i) << i, j, 0;
      }
    }
  }
  std::vector<std::vector<Index>> triangles;
  for (Index j = 0; j < m; ++j) {
    for (Index i = 0; i < n; ++i) {
      const Index a = j * columns + i;
      const Index b = j * columns + (i + 1) % columns;
      const Index c = ((j + 1) % rows) * columns + (i + 1) % columns;
      const Index d = ((j + 1) % rows) * columns + i;
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
  }
  return make_mesh(points, triangles);
}

Mesh torus(Index n = 12, Index m = 8) { return grid(n, m, true); }

/// Both meshes side by side in one vertex numbering.
Mesh disjoint_union(const Mesh& a, const Mesh& b) {
  Mesh both;
  both.vertices.resize(a.num_vertices() + b.num_vertices(), 3);
  both.vertices << a.vertices, b.vertices;
  both.triangles.resize(a.num_triangles() + b.num_triangles(), 3);
  both.triangles << a.triangles, (b.triangles.array() + a.num_vertices()).matrix();
  return both;
}

/// `mesh` without the listed triangles.
Mesh without(const Mesh& mesh, const std::vector<Index>& removed) {
  Mesh result = mesh;
  Index kept = 0;
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    if (std::find(removed.begin(), removed.end(), t) == removed.end())
      result.triangles.row(kept++) = mesh.triangles.row(t);
  result.triangles.conservativeResize(kept, 3);
  return result;
}

void expect_counts(const MeshTopology& topology, Index vertices, Index edges, Index faces, Index components) {
  EXPECT_EQ(topology.vertices, vertices);
  EXPECT_EQ(topology.edges, edges);
  EXPECT_EQ(topology.faces, faces);
  EXPECT_EQ(topology.components, components);
  EXPECT_EQ(topology.euler_characteristic, vertices - edges + faces);
}

void expect_closed_surface(const MeshTopology& topology, int genus) {
  EXPECT_TRUE(topology.closed);
  EXPECT_TRUE(topology.manifold);
  EXPECT_TRUE(topology.orientable);
  EXPECT_EQ(topology.boundary_edges, 0);
  EXPECT_EQ(topology.boundary_loops, 0);
  EXPECT_EQ(topology.non_manifold_edges, 0);
  EXPECT_EQ(topology.non_manifold_vertices, 0);
  EXPECT_EQ(topology.genus, genus);
}

TEST(AnalyzeTopology, Tetrahedron) {
  const MeshTopology topology = analyze_topology(tetrahedron());
  expect_counts(topology, 4, 6, 4, 1);
  expect_closed_surface(topology, 0);
}

TEST(AnalyzeTopology, Cube) {
  const MeshTopology topology = analyze_topology(cube());
  expect_counts(topology, 8, 18, 12, 1);
  expect_closed_surface(topology, 0);
}

TEST(AnalyzeTopology, InconsistentOrientationDoesNotChangeTheGenus) {
  Mesh mesh = cube();
  mesh.triangles.row(3) = mesh.triangles.row(3).reverse().eval();
  mesh.triangles.row(8) = mesh.triangles.row(8).reverse().eval();
  expect_closed_surface(analyze_topology(mesh), 0);
}

TEST(AnalyzeTopology, TorusHasGenusOne) {
  const MeshTopology topology = analyze_topology(torus(12, 8));
  expect_counts(topology, 96, 288, 192, 1);
  EXPECT_EQ(topology.euler_characteristic, 0);
  expect_closed_surface(topology, 1);
}

TEST(AnalyzeTopology, TwoToriHaveGenusTwo) {
  const MeshTopology topology = analyze_topology(disjoint_union(torus(12, 8), torus(5, 3)));
  EXPECT_EQ(topology.components, 2);
  EXPECT_EQ(topology.euler_characteristic, 0);
  expect_closed_surface(topology, 2);
}

TEST(AnalyzeTopology, TorusAndSpheresAddUp) {
  const MeshTopology topology = analyze_topology(disjoint_union(disjoint_union(tetrahedron(), torus()), cube()));
  EXPECT_EQ(topology.components, 3);
  EXPECT_EQ(topology.euler_characteristic, 4);
  expect_closed_surface(topology, 1);
}

TEST(AnalyzeTopology, DiskHasOneBoundaryLoop) {
  const MeshTopology topology = analyze_topology(grid(4, 3, false));
  EXPECT_EQ(topology.euler_characteristic, 1);
  EXPECT_FALSE(topology.closed);
  EXPECT_TRUE(topology.manifold);
  EXPECT_EQ(topology.boundary_edges, 14);
  EXPECT_EQ(topology.boundary_loops, 1);
  EXPECT_EQ(topology.genus, 0);
}

TEST(AnalyzeTopology, PuncturedSurfacesKeepTheirGenus) {
  // Two separate holes in a torus: chi = -2, b = 2, genus still 1.
  const MeshTopology torus_with_holes = analyze_topology(without(torus(12, 8), {0, 100}));
  EXPECT_EQ(torus_with_holes.boundary_loops, 2);
  EXPECT_EQ(torus_with_holes.boundary_edges, 6);
  EXPECT_EQ(torus_with_holes.euler_characteristic, -2);
  EXPECT_TRUE(torus_with_holes.manifold);
  EXPECT_EQ(torus_with_holes.genus, 1);
  // A cube without its top (an open box).
  const MeshTopology open_box = analyze_topology(without(cube(), {2, 3}));
  EXPECT_EQ(open_box.boundary_loops, 1);
  EXPECT_EQ(open_box.boundary_edges, 4);
  EXPECT_EQ(open_box.genus, 0);
}

TEST(AnalyzeTopology, HolesTouchingAtAVertexFormOneLoop) {
  // In a 4 x 4 grid, remove the inner squares (1,1) and (2,2): they share only
  // the vertex (2,2), which then has two fans. Each fan's two boundary edges
  // lie on different holes, so walking the boundary fan by fan (as if the
  // vertex were split into its fans) passes from one hole into the other.
  const MeshTopology topology = analyze_topology(without(grid(4, 4, false), {10, 11, 20, 21}));
  EXPECT_EQ(topology.non_manifold_vertices, 1);
  EXPECT_EQ(topology.non_manifold_edges, 0);
  EXPECT_EQ(topology.boundary_edges, 16 + 4 + 4);
  EXPECT_EQ(topology.boundary_loops, 2);  // the border, and the two holes as one figure-eight
  EXPECT_FALSE(topology.manifold);
  EXPECT_EQ(topology.genus, -1);
}

TEST(AnalyzeTopology, BowtieIsNonManifold) {
  const MeshTopology topology = analyze_topology(make_mesh(5, {{0, 1, 2}, {0, 3, 4}}));
  EXPECT_EQ(topology.non_manifold_vertices, 1);
  EXPECT_EQ(topology.components, 1);
  EXPECT_EQ(topology.boundary_loops, 2);
  EXPECT_FALSE(topology.manifold);
  EXPECT_EQ(topology.genus, -1);
}

TEST(AnalyzeTopology, ThreeTrianglesOnOneEdge) {
  const MeshTopology topology = analyze_topology(make_mesh(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}));
  EXPECT_EQ(topology.non_manifold_edges, 1);
  EXPECT_EQ(topology.non_manifold_vertices, 2);
  EXPECT_EQ(topology.boundary_edges, 6);
  EXPECT_EQ(topology.edges, 7);
  EXPECT_EQ(topology.genus, -1);
}

TEST(AnalyzeTopology, IsolatedVertexIsANonManifoldComponent) {
  const MeshTopology topology = analyze_topology(make_mesh(5, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}));
  EXPECT_EQ(topology.components, 2);
  EXPECT_EQ(topology.non_manifold_vertices, 1);
  EXPECT_EQ(topology.euler_characteristic, 3);
  EXPECT_EQ(topology.genus, -1);
}

TEST(AnalyzeTopology, MoebiusStripIsNotOrientable) {
  // A strip of 4 squares whose ends are glued with a half twist.
  const Mesh strip =
      make_mesh(8, {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 4, 0}, {3, 0, 7}});
  const MeshTopology topology = analyze_topology(strip);
  EXPECT_TRUE(topology.manifold);
  EXPECT_FALSE(topology.orientable);
  EXPECT_EQ(topology.euler_characteristic, 0);
  EXPECT_EQ(topology.boundary_loops, 1);
  EXPECT_EQ(topology.genus, -1);
}

TEST(AnalyzeTopology, KleinBottleIsClosedButNotOrientable) {
  // A 6 x 5 grid whose columns wrap around and whose last row is glued to the
  // first one mirrored: every edge has two triangles, chi = 0, yet going once
  // around the rows flips the orientation, a contradiction that only shows
  // after a long chain of triangles.
  const Index n = 6;
  const Index m = 5;
  const auto vertex = [&](Index i, Index j) { return j == m ? (n - i % n) % n : j * n + i % n; };
  std::vector<std::vector<Index>> triangles;
  for (Index j = 0; j < m; ++j) {
    for (Index i = 0; i < n; ++i) {
      triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  }
  const MeshTopology topology = analyze_topology(make_mesh(n * m, triangles));
  expect_counts(topology, n * m, 3 * n * m, 2 * n * m, 1);
  EXPECT_EQ(topology.euler_characteristic, 0);
  EXPECT_TRUE(topology.closed);
  EXPECT_TRUE(topology.manifold);
  EXPECT_FALSE(topology.orientable);
  EXPECT_EQ(topology.genus, -1);
}

TEST(AnalyzeTopology, RejectsBrokenTriangles) {
  EXPECT_THROW(analyze_topology(make_mesh(3, {{0, 1, 3}})), InvalidArgument);
  EXPECT_THROW(analyze_topology(make_mesh(3, {{0, 1, 1}})), InvalidArgument);
}

TEST(ConnectedComponents, LabelsFollowTheSmallestVertex) {
  const Mesh mesh = make_mesh(7, {{4, 5, 6}, {0, 3, 1}});
  const ComponentLabels labels = connected_components(mesh.triangles, mesh.num_vertices());
  EXPECT_EQ(labels.count, 3);  // {0,1,3}, {2} alone, {4,5,6}
  EXPECT_EQ(labels.vertex_component, (std::vector<Index>{0, 0, 1, 0, 2, 2, 2}));
}

TEST(CornersByVertex, EveryCornerOnceUnderItsVertexInOrder) {
  const Mesh mesh = torus(12, 8);
  const VertexCorners corners = corners_by_vertex(mesh.triangles, mesh.num_vertices());
  ASSERT_EQ(corners.start.size(), 96u + 1);
  ASSERT_EQ(corners.corner.size(), 3u * 192);
  EXPECT_EQ(corners.start.front(), 0);
  std::vector<int> seen(corners.corner.size(), 0);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    EXPECT_EQ(corners.degree(v), 6);  // every vertex of the split-square torus lies on 6 triangles
    for (Index i = corners.start[v]; i < corners.start[v + 1]; ++i) {
      const Index c = corners.corner[i];
      EXPECT_EQ(mesh.triangles(c / 3, c % 3), v);
      if (i > corners.start[v]) {
        EXPECT_LT(corners.corner[i - 1], c);
      }
      ++seen[c];
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(seen.size()));
}

TEST(CornersByVertex, IsolatedVertexHasNoCorner) {
  const Mesh mesh = make_mesh(5, {{4, 0, 1}, {1, 0, 3}});
  const VertexCorners corners = corners_by_vertex(mesh.triangles, mesh.num_vertices());
  EXPECT_EQ(corners.start, (std::vector<Index>{0, 2, 4, 4, 5, 6}));
  EXPECT_EQ(corners.corner, (std::vector<Index>{1, 4, 2, 3, 5, 0}));
  EXPECT_TRUE(corners.link.empty());  // only when asked for
}

// The links are the corner's triangle read on from the corner: (next, previous).
TEST(CornersByVertex, LinksAreTheOtherTwoVerticesInTheTrianglesOrder) {
  const Mesh mesh = make_mesh(5, {{4, 0, 1}, {1, 0, 3}});
  const VertexCorners corners = corners_by_vertex(mesh.triangles, mesh.num_vertices(), CornerParts::Both);
  EXPECT_EQ(corners.corner, (std::vector<Index>{1, 4, 2, 3, 5, 0}));
  const std::vector<std::array<Index, 2>> expected = {{1, 4}, {3, 1}, {4, 0}, {0, 3}, {1, 0}, {0, 1}};
  EXPECT_EQ(corners.link, expected);
  const Mesh big = torus(12, 8);
  const VertexCorners all = corners_by_vertex(big.triangles, big.num_vertices(), CornerParts::Both);
  ASSERT_EQ(all.link.size(), all.corner.size());
  for (std::size_t i = 0; i < all.corner.size(); ++i) {
    const Index t = all.corner[i] / 3, k = all.corner[i] % 3;
    EXPECT_EQ(all.link[i][0], big.triangles(t, (k + 1) % 3)) << i;
    EXPECT_EQ(all.link[i][1], big.triangles(t, (k + 2) % 3)) << i;
  }
  // Links alone: the same links, no corners.
  const VertexCorners links = corners_by_vertex(big.triangles, big.num_vertices(), CornerParts::Links);
  EXPECT_TRUE(links.corner.empty());
  EXPECT_EQ(links.start, all.start);
  EXPECT_EQ(links.link, all.link);
}

}  // namespace
}  // namespace reebkit

#include "reebkit/mesh/degenerate_triangles.h"

#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

namespace reebkit {
namespace {

/// The triangles of `mesh` as sorted vertex triples, in the numbering of
/// `vertex` (new -> old; empty: the identity).
std::set<std::array<Index, 3>> triangle_set(const Mesh& mesh, const std::vector<Index>& vertex = {}) {
  std::set<std::array<Index, 3>> out;
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    std::array<Index, 3> c{};
    for (int k = 0; k < 3; ++k) {
      const Index v = mesh.triangles(t, k);
      c[static_cast<std::size_t>(k)] = vertex.empty() ? v : vertex[static_cast<std::size_t>(v)];
    }
    std::sort(c.begin(), c.end());
    out.insert(c);
  }
  return out;
}

// A sliver whose corner c lies almost on its longest edge (a, b): the flip
// of (a, b) makes two fat triangles, no vertex moves.
TEST(DegenerateTriangles, SliverIsFlipped) {
  Mesh m;  // a = 0, b = 1, c = 2 just above (a, b), d = 3 below, e = 4 above c
  m.vertices.resize(5, 3);
  m.vertices << 0, 0, 0, 2, 0, 0, 1, 1e-9, 0, 1, -1, 0, 1, 2, 0;
  m.triangles.resize(4, 3);
  m.triangles << 0, 1, 2, 1, 0, 3, 0, 2, 4, 2, 1, 4;
  EXPECT_EQ(degenerate_triangles(m, 1e-6), (std::vector<Index>{0}));
  EXPECT_TRUE(degenerate_triangles(m, 0.0).empty());  // its area is not zero
  const TriangleRepair r = repair_degenerate_triangles(m, 1e-6);
  EXPECT_EQ(r.flips, 1);
  EXPECT_EQ(r.collapses, 0);
  EXPECT_EQ(r.remaining, 0);
  EXPECT_EQ(r.mesh.vertices, m.vertices);
  EXPECT_EQ(triangle_set(r.mesh), (std::set<std::array<Index, 3>>{{0, 2, 3}, {1, 2, 3}, {0, 2, 4}, {1, 2, 4}}));
  EXPECT_TRUE(degenerate_triangles(r.mesh, 1e-6).empty());
  for (Index t = 0; t < r.mesh.num_triangles(); ++t) {  // oriented as the plane: normals along +z
    const Vec3 a = r.mesh.vertices.row(r.mesh.triangles(t, 0)), b = r.mesh.vertices.row(r.mesh.triangles(t, 1)),
               c = r.mesh.vertices.row(r.mesh.triangles(t, 2));
    EXPECT_GT((b - a).cross(c - a).z(), 0) << t;
  }
}

// An edge of a sphere split very near one end: the two needles go by the
// collapse of the short edge, which gives back the sphere's triangles.
TEST(DegenerateTriangles, NeedlesAreCollapsed) {
  const Mesh sphere = make_icosphere(2);
  const Index a = sphere.triangles(0, 0), b = sphere.triangles(0, 1), n = sphere.num_vertices();
  Mesh m = sphere;
  m.vertices.conservativeResize(n + 1, 3);
  m.vertices.row(n) = sphere.vertices.row(a) + 1e-7 * (sphere.vertices.row(b) - sphere.vertices.row(a));
  // Every triangle on (a, b) becomes two, through the new vertex n.
  std::vector<std::array<Index, 3>> triangles;
  for (Index t = 0; t < sphere.num_triangles(); ++t) {
    std::array<Index, 3> c{sphere.triangles(t, 0), sphere.triangles(t, 1), sphere.triangles(t, 2)};
    int k = 0;
    for (; k < 3; ++k) {
      const Index u = c[static_cast<std::size_t>(k)], v = c[static_cast<std::size_t>((k + 1) % 3)];
      if ((u == a && v == b) || (u == b && v == a)) break;
    }
    if (k == 3) {
      triangles.push_back(c);
      continue;
    }
    const Index u = c[static_cast<std::size_t>(k)], v = c[static_cast<std::size_t>((k + 1) % 3)],
                w = c[static_cast<std::size_t>((k + 2) % 3)];
    triangles.push_back({u, n, w});
    triangles.push_back({n, v, w});
  }
  m.triangles.resize(static_cast<Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) m.triangles(static_cast<Index>(t), k) = triangles[t][static_cast<std::size_t>(k)];
  ASSERT_EQ(degenerate_triangles(m, 1e-4).size(), 2u);

  const TriangleRepair r = repair_degenerate_triangles(m, 1e-4);
  EXPECT_EQ(r.remaining, 0);
  EXPECT_EQ(r.flips, 0);
  EXPECT_EQ(r.collapses, 1);
  ASSERT_EQ(r.mesh.num_vertices(), n);
  // a or n is gone; with n read as a, the sphere's triangles.
  std::vector<Index> as_sphere = r.input_vertex;
  std::replace(as_sphere.begin(), as_sphere.end(), n, a);
  EXPECT_EQ(triangle_set(r.mesh, as_sphere), triangle_set(sphere));
  for (Index v = 0; v < r.mesh.num_vertices(); ++v)
    EXPECT_EQ(r.mesh.vertices.row(v), m.vertices.row(r.input_vertex[static_cast<std::size_t>(v)]));
  EXPECT_EQ(analyze_topology(r.mesh).genus, 0);
}

// A closed tetrahedron of zero volume hanging on an edge of a sphere (a
// pocket a collapse folded, its vertices on the line of that edge) goes
// whole, with its two vertices.
TEST(DegenerateTriangles, FoldedPocketIsRemoved) {
  const Mesh sphere = make_icosphere(2);
  const Index a = sphere.triangles(0, 0), x = sphere.triangles(0, 1), n = sphere.num_vertices();
  Mesh m = sphere;
  m.vertices.conservativeResize(n + 2, 3);
  m.vertices.row(n) = 0.6 * sphere.vertices.row(a) + 0.4 * sphere.vertices.row(x);      // b
  m.vertices.row(n + 1) = 0.3 * sphere.vertices.row(a) + 0.7 * sphere.vertices.row(x);  // c
  const Index b = n, c = n + 1;
  m.triangles.conservativeResize(sphere.num_triangles() + 4, 3);
  m.triangles.bottomRows(4) << a, b, c, b, x, c, b, a, x, c, x, a;
  const TriangleRepair r = repair_degenerate_triangles(m, 1e-6);
  EXPECT_EQ(r.pockets, 1);
  EXPECT_EQ(r.remaining, 0);
  EXPECT_EQ(r.mesh.vertices, sphere.vertices);
  EXPECT_EQ(r.mesh.triangles, sphere.triangles);
}

// What no flip or collapse can mend stays, and is counted: a lone triangle
// of zero area beside a good one (a border edge cannot flip; a collapse
// would leave a vertex with fewer than 3 neighbours).
TEST(DegenerateTriangles, WhatCannotBeMendedIsCounted) {
  Mesh m;
  m.vertices.resize(5, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 3, 0, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 1, 3, 4;
  const TriangleRepair r = repair_degenerate_triangles(m, 1e-6);
  EXPECT_EQ(r.remaining, 1);
  EXPECT_EQ(r.mesh.triangles, m.triangles);
}

// A mesh without degenerate triangles comes back as it was.
TEST(DegenerateTriangles, GoodMeshIsUnchanged) {
  for (const Mesh& mesh : {make_torus(32, 12), make_star(StarOptions{5, 3})}) {
    EXPECT_TRUE(degenerate_triangles(mesh, 1e-4).empty());
    const TriangleRepair r = repair_degenerate_triangles(mesh, 1e-4);
    EXPECT_EQ(r.mesh.vertices, mesh.vertices);
    EXPECT_EQ(r.mesh.triangles, mesh.triangles);
    EXPECT_EQ(r.flips + r.collapses + r.pockets + r.remaining, 0);
  }
}

}  // namespace
}  // namespace reebkit

#include "reebkit/mesh/remeshing.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reebkit {
namespace {

TEST(Remeshing, ANewTriangulationOfTheSameSurface) {
  for (const Mesh& mesh : {make_torus(48, 16), make_star(StarOptions{5, 4})})
    for (const double factor : {0.5, 1.0, 2.0}) {
      RemeshOptions options;
      options.target_vertices = static_cast<Index>(std::lround(factor * mesh.num_vertices()));
      const MeshVariant out = remesh(mesh, options);
      const double target = options.target_vertices;
      EXPECT_NEAR(out.mesh.num_vertices(), target, 0.02 * target + 1) << "x" << factor;
      EXPECT_EQ(analyze_topology(out.mesh).genus, analyze_topology(mesh).genus) << "x" << factor;
      const SurfaceLocator original(mesh);
      const double d = bounding_box_diagonal(mesh);
      // Shares no vertex: every vertex is away from every original vertex.
      for (Index v = 0; v < out.mesh.num_vertices(); ++v) {
        const Vec3 p = out.mesh.vertices.row(v);
        // Stays on the surface (projected onto it; to rounding).
        EXPECT_LT(original.closest(p).distance, 1e-9 * d);
        const Index nearest = out.original_vertex[static_cast<std::size_t>(v)];
        EXPECT_GT((p - mesh.vertices.row(nearest).transpose()).norm(), 1e-9 * d);
      }
      for (Index v = 0; v < mesh.num_vertices(); ++v)
        for (Index w = 0; w < out.mesh.num_vertices(); ++w)
          ASSERT_FALSE(mesh.vertices.row(v) == out.mesh.vertices.row(w)) << "shared vertex " << v;
      // And covers it: every point of the original is near the new surface.
      EXPECT_LT(sampled_distance_to_surface(mesh, SurfaceLocator(out.mesh), 2000, 3), 0.02 * d) << "x" << factor;
    }
}

// The correspondence maps each new vertex to an original vertex near it:
// within the longest original edge (the vertex lies in a triangle of it).
TEST(Remeshing, CorrespondenceMapsBackWithinAnEdge) {
  const Mesh mesh = make_torus(48, 16);
  double longest = 0.0;
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (mesh.vertices.row(mesh.triangles(t, k)) - mesh.vertices.row(mesh.triangles(t, (k + 1) % 3))).norm());
  RemeshOptions options;
  options.target_vertices = mesh.num_vertices();
  const MeshVariant out = remesh(mesh, options);
  for (Index v = 0; v < out.mesh.num_vertices(); ++v)
    EXPECT_LT((out.mesh.vertices.row(v) - mesh.vertices.row(out.original_vertex[static_cast<std::size_t>(v)])).norm(),
              longest);
}

TEST(Remeshing, EdgeLengthGivesTheVertexCountOfAnEquilateralMesh) {
  const Mesh sphere = make_icosphere(4);
  RemeshOptions options;
  options.target_edge_length = 0.1;
  const double expected = 2.0 * surface_area(sphere) / (std::sqrt(3.0) * 0.01);
  EXPECT_NEAR(remesh(sphere, options).mesh.num_vertices(), expected, 0.03 * expected);
}

TEST(Remeshing, SameSeedSameMeshAndBadTargetsThrow) {
  const Mesh sphere = make_icosphere(3);
  RemeshOptions options;
  options.target_vertices = 300;
  EXPECT_EQ(remesh(sphere, options).mesh.vertices, remesh(sphere, options).mesh.vertices);
  EXPECT_THROW(remesh(sphere, RemeshOptions{}), InvalidArgument);
  options.target_vertices = 3;
  EXPECT_THROW(remesh(sphere, options), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

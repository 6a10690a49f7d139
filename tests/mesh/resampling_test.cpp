#include "reebkit/mesh/resampling.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

namespace reebkit {
namespace {

TEST(Resampling, KeepsTheSurfaceItsGenusAndItsArea) {
  for (const Mesh& mesh : {make_torus(24, 12), make_star(StarOptions{4, 3}), make_grid(6, 5), make_cube()}) {
    const MeshTopology before = analyze_topology(mesh);
    const Mesh out = resample_mesh(mesh);
    const MeshTopology after = analyze_topology(out);
    EXPECT_EQ(after.vertices, before.vertices + before.edges);
    EXPECT_EQ(after.faces, 4 * before.faces);
    EXPECT_EQ(after.genus, before.genus);
    EXPECT_EQ(after.boundary_loops, before.boundary_loops);
    EXPECT_TRUE(after.manifold);
    EXPECT_TRUE(after.orientable);
    // Edge vertices slide along their edges, so the four triangles tile the old one.
    EXPECT_NEAR(surface_area(out), surface_area(mesh), 1e-12 * surface_area(mesh));
    EXPECT_TRUE(out.vertices.topRows(mesh.num_vertices()) == mesh.vertices);
  }
}

TEST(Resampling, EdgeVerticesLieOnTheirEdgeWithinTheJitter) {
  const Mesh cube = make_cube();
  ResamplingOptions options;
  options.jitter = 0.1;
  const Mesh out = resample_mesh(cube, options);
  for (Index f = 0; f < cube.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k) {
      // Triangle 4f + 3 is the middle one: its corner k is on edge (k, k + 1) of f.
      const Vec3 a = cube.vertices.row(cube.triangles(f, k)), b = cube.vertices.row(cube.triangles(f, (k + 1) % 3));
      const Vec3 m = out.vertices.row(out.triangles(4 * f + 3, k));
      const double t = (m - a).dot(b - a) / (b - a).squaredNorm();
      EXPECT_NEAR((a + t * (b - a) - m).norm(), 0.0, 1e-12);
      EXPECT_GE(t, 0.4 - 1e-12);
      EXPECT_LE(t, 0.6 + 1e-12);
    }
  options.jitter = 0.0;
  const Mesh midpoints = resample_mesh(cube, options);
  const Vec3 m = midpoints.vertices.row(midpoints.triangles(3, 0));
  EXPECT_TRUE(m.isApprox(
      0.5 * (cube.vertices.row(cube.triangles(0, 0)) + cube.vertices.row(cube.triangles(0, 1))).transpose()));
}

TEST(Resampling, SameSeedSameMeshOtherSeedOtherSampling) {
  const Mesh torus = make_torus(16, 8);
  ResamplingOptions options;
  EXPECT_TRUE(resample_mesh(torus, options).vertices == resample_mesh(torus, options).vertices);
  const Mesh first = resample_mesh(torus, options);
  options.seed = 2;
  EXPECT_FALSE(resample_mesh(torus, options).vertices == first.vertices);
}

TEST(Resampling, RejectsAJitterOutsideItsRange) {
  ResamplingOptions options;
  options.jitter = 0.5;
  EXPECT_THROW(resample_mesh(make_cube(), options), InvalidArgument);
  options.jitter = -0.1;
  EXPECT_THROW(resample_mesh(make_cube(), options), InvalidArgument);
}

TEST(NormalNoise, MovesEveryVertexAlongItsNormalWithinTheAmplitude) {
  const Mesh sphere = make_icosphere(0);  // an icosahedron: every one-ring is symmetric about the radius
  const double diagonal = (sphere.vertices.colwise().maxCoeff() - sphere.vertices.colwise().minCoeff()).norm();
  NoiseOptions options;
  options.amplitude = 0.01;
  const Mesh noisy = add_normal_noise(sphere, options);
  EXPECT_TRUE(noisy.triangles == sphere.triangles);
  double largest = 0.0;
  for (Index v = 0; v < sphere.num_vertices(); ++v) {
    const Vec3 p = sphere.vertices.row(v), q = noisy.vertices.row(v);
    EXPECT_LE((q - p).norm(), 0.01 * diagonal * (1 + 1e-12));
    EXPECT_NEAR((q - p).cross(p).norm(), 0.0, 1e-12);  // radial
    largest = std::max(largest, (q - p).norm());
  }
  EXPECT_GT(largest, 0.005 * diagonal);  // uniform in [-a, a]: one of 12 draws reaches beyond a/2
  options.amplitude = 0.0;
  EXPECT_TRUE(add_normal_noise(sphere, options).vertices == sphere.vertices);
  options.amplitude = -1.0;
  EXPECT_THROW(add_normal_noise(sphere, options), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

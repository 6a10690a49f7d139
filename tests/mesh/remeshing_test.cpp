#include "reebkit/mesh/remeshing.h"

#include "reebkit/core/error.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/mesh/degenerate_triangles.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shapes.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

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
      longest = std::max(longest,
                         (mesh.vertices.row(mesh.triangles(t, k)) - mesh.vertices.row(mesh.triangles(t, (k + 1) % 3)))
                             .norm());
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

/// Checks a remesh of `mesh`: no triangle at or below the options' share of
/// the mean area, none of zero area (at most 1e-12 of the largest), every
/// vertex on the original surface and off the original vertices.
void expect_remesh_without_degenerate_triangles(const Mesh& mesh, const RemeshOptions& options) {
  SCOPED_TRACE(mesh.source + " seed " + std::to_string(options.seed) + " target " +
               std::to_string(options.target_vertices));
  MeshVariant out;
  try {
    out = remesh(mesh, options);
  } catch (const InvalidMeshError& e) {
    ADD_FAILURE() << e.what();
    return;
  }
  EXPECT_TRUE(degenerate_triangles(out.mesh, options.min_triangle_area).empty());
  double largest = 0;
  for (Index t = 0; t < out.mesh.num_triangles(); ++t) largest = std::max(largest, triangle_area(out.mesh, t));
  for (Index t = 0; t < out.mesh.num_triangles(); ++t) ASSERT_GT(triangle_area(out.mesh, t), 1e-12 * largest) << t;
  const SurfaceLocator original(mesh);
  const double d = bounding_box_diagonal(mesh);
  for (Index v = 0; v < out.mesh.num_vertices(); ++v) {
    const Vec3 p = out.mesh.vertices.row(v);
    ASSERT_LT(original.closest(p).distance, 1e-9 * d) << v;
    ASSERT_GT((p - mesh.vertices.row(out.original_vertex[static_cast<std::size_t>(v)]).transpose()).norm(), 1e-9 * d)
        << v;
  }
}

/// A target of 0.25x to 4x (log-uniform) the vertices of `mesh`, at least 16
/// and at most `cap`.
Index random_target(const Mesh& mesh, std::mt19937_64& random, double cap) {
  const double factor = std::exp(std::uniform_real_distribution<double>(std::log(0.25), std::log(4.0))(random));
  return static_cast<Index>(std::clamp(std::round(factor * mesh.num_vertices()), 16.0, cap));
}

// The closed CGAL meshes of one piece (the manifest's "closed", "comps" 1,
// "manifold"), each remeshed with two random seeds and targets: no
// degenerate triangle in any.
TEST(Remeshing, NoDegenerateTriangleOnTheClosedCgalMeshes) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  std::ifstream manifest(dir / "manifest.jsonl");
  std::mt19937_64 random(26);
  int meshes = 0;
  for (std::string line; std::getline(manifest, line);) {
    if (line.find("\"closed\": true") == std::string::npos || line.find("\"comps\": 1,") == std::string::npos ||
        line.find("\"manifold\": true") == std::string::npos)
      continue;
    const std::size_t name = line.find("\"file\": \"") + 9;
    const Mesh mesh = std::move(load_mesh(dir / line.substr(name, line.find('"', name) - name)).components.front());
    if (mesh.num_vertices() > 3000) continue;  // the larger ones: experiments/remesh_quality
    ++meshes;
    for (int k = 0; k < 2; ++k) {
      RemeshOptions options;
      options.seed = random();
      options.target_vertices = random_target(mesh, random, 4000);
      expect_remesh_without_degenerate_triangles(mesh, options);
    }
  }
  EXPECT_GE(meshes, 50);
}

// The first model of every SHREC07 class, remeshed with a random seed and
// target (at most 3000 vertices), and decimated: no degenerate triangle.
TEST(Remeshing, NoDegenerateTriangleOnEveryShrec07Class) {
  REEBKIT_REQUIRE_DATASET(dir, "shrec07_watertight");
  std::mt19937_64 random(7);
  const std::vector<PsbClass> classes = read_psb_classes(dir / "shrec07_watertight.cla");
  ASSERT_EQ(classes.size(), 20u);
  for (const PsbClass& c : classes) {
    const Mesh mesh = std::move(load_mesh(dir / (c.models.front() + ".off")).components.front());
    RemeshOptions options;
    options.seed = random();
    options.target_vertices = random_target(mesh, random, 3000);
    expect_remesh_without_degenerate_triangles(mesh, options);
  }
}

// A remesh of the 1,000 of experiments/remesh_quality that failed before
// collapses could leave a triangle degenerate when it already was: the
// dense sampling's decimation held a vertex of three neighbours whose
// triangles all lay on one line of the original (a flat fan), which only a
// collapse onto its neighbour on the line, then a flip, removes.
TEST(Remeshing, FlatFanOnALineOfTheOriginalIsRepaired) {
  REEBKIT_REQUIRE_DATASET(dir, "shrec07_watertight");
  const Mesh mesh = std::move(load_mesh(dir / "340.off").components.front());
  RemeshOptions options;
  options.seed = 15938181821389288267u;
  options.target_vertices = 5485;
  expect_remesh_without_degenerate_triangles(mesh, options);
}

// A dense sampling whose decimation leaves a sliver that no flip or collapse
// removes (found by remeshing every SHREC07 model with three seeds; this one
// was an error before): the remeshing is made again from another sampling
// drawn from the seed, and succeeds.
TEST(Remeshing, ASliverNoRepairRemovesIsRemeshedFromAnotherSampling) {
  REEBKIT_REQUIRE_DATASET(dir, "shrec07_watertight");
  const Mesh mesh = std::move(load_mesh(dir / "152.off").components.front());
  RemeshOptions options;
  options.seed = 1203690;
  options.target_vertices = 7649;
  expect_remesh_without_degenerate_triangles(mesh, options);
  const MeshVariant again = remesh(mesh, options);  // the same seed, the same mesh
  EXPECT_EQ(again.mesh.vertices, remesh(mesh, options).mesh.vertices);
}

// A remesh that cannot meet the bound is an error naming the mesh, the seed
// and each of the four tries, not an output: here a bound no triangulation
// meets (every triangle within 1 % of the mean area).
TEST(Remeshing, AVariantThatCannotMeetTheBoundIsAnErrorNamingTheSeed) {
  Mesh sphere = make_icosphere(3);
  sphere.source = "sphere.off";
  RemeshOptions options;
  options.target_vertices = 300;
  options.seed = 77;
  options.min_triangle_area = 0.99;
  const std::string message = test::thrown_message<InvalidMeshError>([&] { remesh(sphere, options); });
  EXPECT_NE(message.find("sphere.off"), std::string::npos) << message;
  EXPECT_NE(message.find("seed 77 failed 4 times"), std::string::npos) << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), ';'), 3) << message;  // four problems
  options.min_triangle_area = 1.0;
  EXPECT_THROW(remesh(sphere, options), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

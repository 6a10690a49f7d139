#include "reebkit/mesh/decimation.h"

#include "reebkit/core/error.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/mesh/degenerate_triangles.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shapes.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reebkit {
namespace {

/// Largest distance from 2000 points sampled on `from` to the surface of `to`.
double one_sided_distance(const Mesh& from, const Mesh& to) {
  return sampled_distance_to_surface(from, SurfaceLocator(to), 2000, 7);
}

TEST(Decimation, HitsTheTargetCountAndKeepsTheSurface) {
  for (const Mesh& mesh : {make_torus(64, 24), make_icosphere(5), make_star(StarOptions{5, 5})})
    for (const double ratio : {0.75, 0.5, 0.25}) {
      const MeshVariant out = decimate_mesh(mesh, DecimationOptions{ratio, 0.02});
      const double target = ratio * mesh.num_vertices();
      EXPECT_NEAR(out.mesh.num_vertices(), target, 0.02 * target + 1) << "ratio " << ratio;
      EXPECT_EQ(analyze_topology(out.mesh).genus, analyze_topology(mesh).genus);
      // Hausdorff-like, both ways, sampled: within 1 % of the diagonal.
      EXPECT_LT(one_sided_distance(out.mesh, mesh), 0.01 * bounding_box_diagonal(mesh)) << "ratio " << ratio;
      EXPECT_LT(one_sided_distance(mesh, out.mesh), 0.01 * bounding_box_diagonal(mesh)) << "ratio " << ratio;
      // Kept vertices keep their positions: the correspondence is exact.
      ASSERT_EQ(out.original_vertex.size(), static_cast<std::size_t>(out.mesh.num_vertices()));
      for (Index v = 0; v < out.mesh.num_vertices(); ++v)
        EXPECT_EQ(out.mesh.vertices.row(v), mesh.vertices.row(out.original_vertex[static_cast<std::size_t>(v)]));
    }
}

// A patch with a border, as the regions whose spectra are computed: the
// first try keeps too many vertices (the collapses spare the border), and
// with refine_last_try the next tries decimate that copy further. The target
// is met, and the kept vertices are the mesh's own, as from the whole mesh.
TEST(Decimation, RefiningTheLastTryHitsTheTargetOnAPatchWithABorder) {
  Mesh patch = make_grid(60, 60, 1.0 / 60);
  for (Index v = 0; v < patch.num_vertices(); ++v)
    patch.vertices(v, 2) = 0.2 * std::sin(6.0 * patch.vertices(v, 0)) * std::cos(5.0 * patch.vertices(v, 1));
  for (const double ratio : {0.3, 0.1, 0.03}) {
    DecimationOptions options{ratio, 0.05};
    options.refine_last_try = true;
    const MeshVariant out = decimate_mesh(patch, options);
    const double target = ratio * patch.num_vertices();
    EXPECT_NEAR(out.mesh.num_vertices(), target, 0.05 * target + 1) << "ratio " << ratio;
    EXPECT_EQ(connected_components(out.mesh.triangles, out.mesh.num_vertices()).count, 1);
    EXPECT_LT(one_sided_distance(out.mesh, patch), 0.01 * bounding_box_diagonal(patch)) << "ratio " << ratio;
    EXPECT_LT(one_sided_distance(patch, out.mesh), 0.02 * bounding_box_diagonal(patch)) << "ratio " << ratio;
    ASSERT_EQ(out.original_vertex.size(), static_cast<std::size_t>(out.mesh.num_vertices()));
    for (Index v = 0; v < out.mesh.num_vertices(); ++v)
      EXPECT_EQ(out.mesh.vertices.row(v), patch.vertices.row(out.original_vertex[static_cast<std::size_t>(v)]));
  }
}

TEST(Decimation, RatioOneKeepsTheMeshAndBadRatiosThrow) {
  const Mesh mesh = make_icosphere(2);
  const MeshVariant same = decimate_mesh(mesh, DecimationOptions{1.0, 0.02});
  EXPECT_EQ(same.mesh.vertices, mesh.vertices);
  EXPECT_EQ(same.mesh.triangles, mesh.triangles);
  for (const double bad : {0.0, -0.5, 1.5})
    EXPECT_THROW(decimate_mesh(mesh, DecimationOptions{bad, 0.02}), InvalidArgument);
}

// Every SHREC07 model of the first class, the first model of every class
// and 351 (which holds triangles of zero area), decimated to a tenth and to
// a half: no triangle at or below the bound, the kept vertices exactly where
// they were.
TEST(Decimation, NoDegenerateTriangleOnShrec07) {
  REEBKIT_REQUIRE_DATASET(dir, "shrec07_watertight");
  const std::vector<PsbClass> classes = read_psb_classes(dir / "shrec07_watertight.cla");
  std::vector<std::string> models = classes.front().models;
  for (const PsbClass& c : classes) models.push_back(c.models.front());
  models.push_back("351");
  for (const std::string& model : models) {
    const Mesh mesh = std::move(load_mesh(dir / (model + ".off")).components.front());
    for (const double ratio : {0.1, 0.5}) {
      SCOPED_TRACE(model + " ratio " + std::to_string(ratio));
      const DecimationOptions options{ratio, 0.02};
      const MeshVariant out = decimate_mesh(mesh, options);
      EXPECT_TRUE(degenerate_triangles(out.mesh, options.min_triangle_area).empty());
      for (Index v = 0; v < out.mesh.num_vertices(); ++v)
        ASSERT_EQ(out.mesh.vertices.row(v), mesh.vertices.row(out.original_vertex[static_cast<std::size_t>(v)]));
    }
  }
}

}  // namespace
}  // namespace reebkit

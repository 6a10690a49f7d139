#include "reebkit/mesh/transform.h"

#include "reebkit/mesh/shapes.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace reebkit {
namespace {

TEST(Transform, RandomSimilarityIsARotationAScaleAndATranslationInRange) {
  const Mesh mesh = make_torus(24, 12);
  const double diagonal = bounding_box_diagonal(mesh);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Similarity s = random_similarity(mesh, seed);
    EXPECT_TRUE((s.rotation * s.rotation.transpose()).isIdentity(1e-12));
    EXPECT_NEAR(s.rotation.determinant(), 1.0, 1e-12);
    EXPECT_GE(s.scale, 0.5);
    EXPECT_LE(s.scale, 2.0);
    EXPECT_LE(s.translation.cwiseAbs().maxCoeff(), diagonal);
    const Similarity again = random_similarity(mesh, seed);
    EXPECT_EQ(s.rotation, again.rotation);
    EXPECT_EQ(s.scale, again.scale);
    EXPECT_EQ(s.translation, again.translation);
  }
}

// Distances scale by exactly the scale factor (to rounding): a similarity.
TEST(Transform, TransformedScalesEveryDistance) {
  const Mesh mesh = make_icosphere(3);
  const Similarity s = random_similarity(mesh, 9);
  const Mesh out = transformed(mesh, s);
  EXPECT_EQ(out.triangles, mesh.triangles);
  for (Index v = 1; v < mesh.num_vertices(); ++v)
    EXPECT_NEAR((out.vertices.row(v) - out.vertices.row(0)).norm(),
                s.scale * (mesh.vertices.row(v) - mesh.vertices.row(0)).norm(), 1e-12);
  EXPECT_TRUE(out.vertices.row(0).transpose().isApprox(s.scale * s.rotation * mesh.vertices.row(0).transpose() +
                                                       s.translation));
}

// Similar copies of a shape with well-separated second moments, their
// vertices renumbered, have the same canonical copy to the last bit, and the
// copy is the shape at unit area about its centroid.
TEST(Transform, CanonicalCopyIsTheSameForEverySimilarCopy) {
  StarOptions options;
  options.levels = 4;
  const Mesh star = make_star(options);
  const CanonicalCopy canonical = canonical_copy(star);
  EXPECT_GT(canonical.axis_gap, 1e-2);
  EXPECT_NEAR(surface_area(canonical.mesh), 1.0, 1e-4);
  EXPECT_LT(canonical.mesh.vertices.colwise().mean().norm(), 0.1);
  const double scale = std::sqrt(surface_area(star));
  for (Index v = 1; v < star.num_vertices(); v += 97)
    EXPECT_NEAR((canonical.mesh.vertices.row(v) - canonical.mesh.vertices.row(0)).norm() * scale,
                (star.vertices.row(canonical.original_vertex[static_cast<std::size_t>(v)]) -
                 star.vertices.row(canonical.original_vertex[0]))
                    .norm(),
                1e-5 * scale);
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 4; ++trial) {
    SCOPED_TRACE(trial);
    std::vector<Index> order(static_cast<std::size_t>(star.num_vertices()));
    std::iota(order.begin(), order.end(), Index{0});
    std::shuffle(order.begin(), order.end(), rng);
    const Mesh moved = renumbered(transformed(star, random_similarity(star, rng)), order);
    const CanonicalCopy again = canonical_copy(moved);
    EXPECT_EQ(again.mesh.vertices, canonical.mesh.vertices);
    EXPECT_EQ(again.mesh.triangles, canonical.mesh.triangles);
    for (std::size_t v = 0; v < again.original_vertex.size(); ++v)
      ASSERT_EQ(again.original_vertex[v], order[static_cast<std::size_t>(canonical.original_vertex[v])]) << v;
  }
}

// The axes of a shape with a symmetry are ill-defined: a small axis_gap,
// the same from the frame alone as from the copy made in it.
TEST(Transform, CanonicalCopyReportsIllDefinedAxes) {
  EXPECT_LT(surface_frame(make_icosphere(3)).axis_gap, 1e-9);   // icosahedral symmetry: a multiple of the identity
  EXPECT_LT(surface_frame(make_torus(48, 16)).axis_gap, 1e-9);  // rotation symmetry about its axis
  // An 8 x 3 rectangle: second moments 64 / 12, 9 / 12 and 0, gaps 55 / 64 and 9 / 64.
  const Mesh grid = make_grid(8, 3);
  EXPECT_NEAR(surface_frame(grid).axis_gap, 9.0 / 64.0, 1e-12);
  EXPECT_EQ(canonical_copy(grid).axis_gap, surface_frame(grid).axis_gap);
  const Mesh empty;
  EXPECT_EQ(surface_frame(empty).area, 0.0);
  EXPECT_EQ(canonical_copy(empty).axis_gap, 0.0);
}

}  // namespace
}  // namespace reebkit

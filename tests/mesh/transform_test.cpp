#include "reebkit/mesh/transform.h"

#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace reebkit

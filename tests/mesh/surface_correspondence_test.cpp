#include "reebkit/mesh/surface_correspondence.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace reebkit {
namespace {

TEST(SurfaceCorrespondence, ClosestPointOnATriangleInEachRegion) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(closest_point_on_triangle(Vec3(0.2, 0.2, 3), a, b, c).isApprox(Vec3(0.2, 0.2, 0)));  // face
  EXPECT_TRUE(closest_point_on_triangle(Vec3(-1, -1, 1), a, b, c).isApprox(a));                    // corner
  EXPECT_TRUE(closest_point_on_triangle(Vec3(0.5, -2, 0), a, b, c).isApprox(Vec3(0.5, 0, 0)));     // edge ab
  EXPECT_TRUE(closest_point_on_triangle(Vec3(1, 1, 0), a, b, c).isApprox(Vec3(0.5, 0.5, 0)));      // edge bc
  EXPECT_TRUE(closest_point_on_triangle(Vec3(3, 0.1, 0), a, b, c).isApprox(b));                    // corner
}

// The grid only orders the search: every answer equals the brute-force one.
TEST(SurfaceCorrespondence, ClosestPointEqualsBruteForce) {
  const Mesh mesh = make_torus(30, 12);
  const SurfaceLocator locator(mesh);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 300; ++i) {
    const Vec3 p(u(rng), u(rng), 0.5 * u(rng));
    double best = std::numeric_limits<double>::infinity();
    for (Index t = 0; t < mesh.num_triangles(); ++t)
      best = std::min(best, (closest_point_on_triangle(p, mesh.vertices.row(mesh.triangles(t, 0)),
                                                       mesh.vertices.row(mesh.triangles(t, 1)),
                                                       mesh.vertices.row(mesh.triangles(t, 2))) -
                             p)
                                .norm());
    const SurfacePoint s = locator.closest(p);
    EXPECT_NEAR(s.distance, best, 1e-12);
    EXPECT_NEAR((s.point - p).norm(), s.distance, 1e-12);
  }
}

TEST(SurfaceCorrespondence, AVertexMapsToItself) {
  const Mesh mesh = make_icosphere(3);
  const std::vector<Index> map = nearest_original_vertices(SurfaceLocator(mesh), mesh.vertices);
  for (Index v = 0; v < mesh.num_vertices(); ++v) EXPECT_EQ(map[static_cast<std::size_t>(v)], v);
}

TEST(SurfaceCorrespondence, NoTriangleIsAnError) {
  Mesh empty;
  empty.source = "empty.off";
  EXPECT_THROW(SurfaceLocator{empty}, InvalidArgument);
}

}  // namespace
}  // namespace reebkit

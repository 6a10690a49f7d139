#include "reebkit/mesh/surface_sampling.h"

#include "reebkit/core/error.h"

#include <gtest/gtest.h>

namespace reebkit {
namespace {

/// Two triangles in the plane z = 0: (0,0) (1,0) (0,1), area 0.5, and
/// (2,0) (5,0) (2,1), area 1.5.
Mesh two_triangles() {
  Mesh m;
  m.vertices.resize(6, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 5, 0, 0, 2, 1, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 3, 4, 5;
  return m;
}

TEST(SurfaceSampling, CumulativeAreasInTheOrderGiven) {
  const Mesh m = two_triangles();
  EXPECT_EQ(triangle_areas(m).cumulative, (std::vector<double>{0.5, 2.0}));
  const TriangleAreas reversed = triangle_areas(m, {1, 0});
  EXPECT_EQ(reversed.triangle, (std::vector<Index>{1, 0}));
  EXPECT_EQ(reversed.cumulative, (std::vector<double>{1.5, 2.0}));
  EXPECT_EQ(reversed.view().total(), 2.0);
}

// Per triangle the share of the points follows its area, and within the
// first one a point falls in the corner x + y < 1/2 (a quarter of its area)
// a quarter of the time and averages to the centroid: uniform over area
// (without the square root of eq. 1 the points crowd the first corner).
TEST(SurfaceSampling, PointsAreUniformOverArea) {
  const Mesh m = two_triangles();
  constexpr int kCount = 20000;
  const std::vector<Vec3> points = sample_surface(m, triangle_areas(m).view(), kCount, 7);
  ASSERT_EQ(points.size(), static_cast<std::size_t>(kCount));
  int first = 0, corner = 0;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) {
    EXPECT_EQ(p.z(), 0.0);
    const bool in_first = p.x() >= 0 && p.y() >= 0 && p.x() + p.y() <= 1 + 1e-12;
    const bool in_second = p.x() >= 2 && p.y() >= 0 && (p.x() - 2) / 3 + p.y() <= 1 + 1e-12;
    ASSERT_TRUE(in_first != in_second) << p.transpose();
    if (!in_first) continue;
    ++first;
    corner += p.x() + p.y() < 0.5;
    mean += p;
  }
  // Binomial standard deviations: sqrt(0.25 * 0.75 / n), 5 of them.
  EXPECT_NEAR(first / double(kCount), 0.25, 5 * 0.0031);
  EXPECT_NEAR(corner / double(first), 0.25, 5 * 0.0062);
  mean /= first;
  EXPECT_NEAR(mean.x(), 1.0 / 3, 0.02);
  EXPECT_NEAR(mean.y(), 1.0 / 3, 0.02);
}

TEST(SurfaceSampling, TheSeedFixesThePointsAndAViewLimitsThem) {
  const Mesh m = two_triangles();
  const TriangleAreas all = triangle_areas(m);
  EXPECT_EQ(sample_surface(m, all.view(), 50, 3), sample_surface(m, all.view(), 50, 3));
  EXPECT_NE(sample_surface(m, all.view(), 50, 3), sample_surface(m, all.view(), 50, 4));
  const TriangleAreas second = triangle_areas(m, {1});
  for (const Vec3& p : sample_surface(m, second.view(), 200, 3)) EXPECT_GE(p.x(), 2.0) << p.transpose();
  EXPECT_TRUE(sample_surface(m, all.view(), 0, 3).empty());
}

TEST(SurfaceSampling, RejectsNoAreaAndANegativeCount) {
  Mesh flat = two_triangles();
  flat.vertices.col(1).setZero();
  EXPECT_THROW(sample_surface(flat, triangle_areas(flat).view(), 10, 1), InvalidArgument);
  EXPECT_THROW(sample_surface(flat, WeightedTriangles{}, 10, 1), InvalidArgument);
  const Mesh m = two_triangles();
  EXPECT_THROW(sample_surface(m, triangle_areas(m).view(), -1, 1), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

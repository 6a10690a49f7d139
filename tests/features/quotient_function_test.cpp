#include "reebkit/features/quotient_function.h"

#include "reebkit/core/error.h"
#include "reebkit/features/feature_points.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace reebkit {
namespace {

// One multi-source pass gives the distance to the nearest feature point: with
// Dijkstra exactly the smallest single-source distance; with fast marching
// (whose triangle updates take both corners from one source) the same but
// where two fronts meet, within 1e-3 of the normalization (measured: one
// vertex of this torus, by 2.6e-4).
TEST(QuotientFunction, IsOneMinusNormalizedDistanceToNearestFeature) {
  const MeshGraph g = build_mesh_graph(make_torus(40, 14));
  const std::vector<Index> features = {0, 211, 333};
  for (const Geodesic method : {Geodesic::Dijkstra, Geodesic::FastMarching}) {
    SCOPED_TRACE(geodesic_name(method));
    const double slack = method == Geodesic::Dijkstra ? 1e-15 : 1e-3;
    const QuotientFunction fq = quotient_function(g, features, method);
    std::vector<DistanceField> single;
    for (const Index f : features) single.push_back(geodesic_distances(g, {f}, method));
    double max_min = 0;
    for (Index v = 0; v < g.num_vertices(); ++v) {
      double m = single[0].distance[v];
      for (const auto& s : single) m = std::min(m, s.distance[v]);
      max_min = std::max(max_min, m);
    }
    EXPECT_NEAR(fq.normalization, max_min, slack * max_min);
    for (Index v = 0; v < g.num_vertices(); ++v) {
      const double nearest = single[fq.nearest_feature[v]].distance[v];
      EXPECT_NEAR(fq.value[v], 1.0 - nearest / max_min, 0.5 / 16777216.0 + slack);  // rounded to 2^-24
      EXPECT_EQ(std::round(fq.value[v] * 16777216.0), fq.value[v] * 16777216.0);
      for (const auto& s : single) EXPECT_LE(nearest, s.distance[v] + slack * max_min);  // eq. (8): the closest one
    }
  }
}

TEST(QuotientFunction, SpansZeroToOneWithOnesAtFeatures) {
  const Mesh mesh = make_star(StarOptions{});
  const MeshGraph g = build_mesh_graph(mesh);
  const FeaturePoints fp = extract_feature_points(mesh, g);
  const QuotientFunction fq = quotient_function(g, fp.vertices);
  EXPECT_DOUBLE_EQ(*std::min_element(fq.value.begin(), fq.value.end()), 0.0);
  EXPECT_DOUBLE_EQ(*std::max_element(fq.value.begin(), fq.value.end()), 1.0);
  for (std::size_t i = 0; i < fp.vertices.size(); ++i) {
    EXPECT_EQ(fq.value[fp.vertices[i]], 1.0);
    EXPECT_EQ(fq.nearest_feature[fp.vertices[i]], static_cast<Index>(i));
  }
}

TEST(QuotientFunction, InvariantToSimilarityTransforms) {
  const Mesh mesh = make_star(StarOptions{});
  const MeshGraph g = build_mesh_graph(mesh);
  const FeaturePoints fp = extract_feature_points(mesh, g);
  const QuotientFunction reference = quotient_function(g, fp.vertices);
  Similarity t;
  t.rotation = random_rotation(42);
  t.scale = 37.5;
  t.translation = Vec3(-4, 2, 9);
  const QuotientFunction moved = quotient_function(build_mesh_graph(transformed(mesh, t)), fp.vertices);
  for (Index v = 0; v < g.num_vertices(); ++v) EXPECT_EQ(moved.value[v], reference.value[v]);
  EXPECT_NEAR(moved.normalization, 37.5 * reference.normalization, 1e-9);
}

TEST(QuotientFunction, RejectsEmptyFeatureList) {
  EXPECT_THROW(quotient_function(build_mesh_graph(make_cube()), {}), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

#include "reebkit/features/quotient_function.h"

#include "reebkit/core/error.h"
#include "reebkit/features/feature_points.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/geodesic/fast_marching.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

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

// After the feature step, f_q keeps the diameter ends' fields (f1, f2) and
// measures only the other points' Voronoi cells: with Dijkstra exactly the
// multi-source pass, with fast marching the same but where two cells meet.
TEST(QuotientFunction, ReusingTheEndsFieldsGivesTheMultiSourcePass) {
  const Mesh mesh = make_star(StarOptions{});
  const MeshGraph g = build_mesh_graph(mesh);
  for (const Geodesic method : {Geodesic::Dijkstra, Geodesic::FastMarching}) {
    SCOPED_TRACE(geodesic_name(method));
    FeatureOptions options;
    options.geodesic = method;
    const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(g, method);
    const FeaturePoints fp = extract_feature_points(mesh, g, options, *solver);
    ASSERT_EQ(fp.vertices.size(), 5u);  // a tip per arm, the ends among them
    const QuotientFunction reused = quotient_function(*solver, fp);
    const QuotientFunction whole = quotient_function(g, fp.vertices, method);
    EXPECT_EQ(whole.pass_share, 1.0);
    // Three of the five arms' cells: about three fifths of the surface.
    EXPECT_GT(reused.pass_share, 0.4);
    EXPECT_LT(reused.pass_share, 0.8);
    Index differ = 0;
    for (Index v = 0; v < g.num_vertices(); ++v) {
      if (method == Geodesic::Dijkstra) {
        EXPECT_EQ(reused.value[v], whole.value[v]);
        EXPECT_EQ(reused.nearest_feature[v], whole.nearest_feature[v]);
      } else {
        EXPECT_NEAR(reused.value[v], whole.value[v], 1e-3);
        differ += reused.value[v] != whole.value[v];
      }
    }
    if (method == Geodesic::FastMarching) {
      EXPECT_LT(differ, g.num_vertices() / 20);  // the cells' borders only
    }
    EXPECT_EQ(reused.normalization, whole.normalization);
    for (std::size_t i = 0; i < fp.vertices.size(); ++i) EXPECT_EQ(reused.value[fp.vertices[i]], 1.0);
  }
}

// Where the diameter ends are the only feature points, f_q is 1 - min(f1,
// f2) / max and no pass runs.
TEST(QuotientFunction, TwoEndsNeedNoPass) {
  StarOptions two;
  two.arms = 2;
  const Mesh mesh = make_star(two);
  const MeshGraph g = build_mesh_graph(mesh);
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(g, Geodesic::FastMarching);
  const FeaturePoints fp = extract_feature_points(mesh, g, {}, *solver);
  ASSERT_EQ(fp.vertices.size(), 2u);
  const QuotientFunction fq = quotient_function(*solver, fp);
  EXPECT_EQ(fq.pass_share, 0.0);
  double top = 0.0;
  for (Index v = 0; v < g.num_vertices(); ++v) top = std::max(top, std::min(fp.f1[v], fp.f2[v]));
  EXPECT_EQ(fq.normalization, top);
  for (Index v = 0; v < g.num_vertices(); ++v)
    EXPECT_NEAR(fq.value[v], 1.0 - std::min(fp.f1[v], fp.f2[v]) / top, 0.5 / 16777216.0);
}

TEST(QuotientFunction, RejectsFieldsOfAnotherMethodOrSize) {
  const Mesh mesh = make_star(StarOptions{});
  const MeshGraph g = build_mesh_graph(mesh);
  const FeaturePoints fp = extract_feature_points(mesh, g);  // fast marching
  DijkstraSolver dijkstra(g);
  EXPECT_THROW(quotient_function(dijkstra, fp), InvalidArgument);
  FeaturePoints cut = fp;
  cut.f2.pop_back();
  FastMarchingSolver fmm(g);
  EXPECT_THROW(quotient_function(fmm, cut), InvalidArgument);
  cut.vertices.clear();
  EXPECT_THROW(quotient_function(fmm, cut), InvalidArgument);
}

TEST(QuotientFunction, RejectsEmptyFeatureList) {
  EXPECT_THROW(quotient_function(build_mesh_graph(make_cube()), {}), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

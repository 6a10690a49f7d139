// What every geodesic method promises (geodesic_solver.h), checked for each:
// radius bound, reuse of a solver, farthest vertex and tie rule, argument
// checks; and the method names and factory.
#include "reebkit/geodesic/geodesic_solver.h"

#include "reebkit/core/error.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/geodesic/fast_marching.h"
#include "reebkit/mesh/resampling.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <type_traits>

namespace reebkit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <class Solver>
class EveryGeodesicSolver : public ::testing::Test {};
using Solvers = ::testing::Types<DijkstraSolver, FastMarchingSolver>;
TYPED_TEST_SUITE(EveryGeodesicSolver, Solvers);

TYPED_TEST(EveryGeodesicSolver, RadiusBoundStopsTheSearchWithoutChangingDistances) {
  const MeshGraph g = build_mesh_graph(make_icosphere(3));
  const DistanceField full = run_once<TypeParam>(g, {5}, {});
  const double radius = 0.6;
  const DistanceField near = run_once<TypeParam>(g, {5}, GeodesicOptions{radius});
  Index inside = 0;
  for (Index v = 0; v < g.num_vertices(); ++v) {
    if (full.distance[v] <= radius) {
      ++inside;
      EXPECT_EQ(near.distance[v], full.distance[v]);
      EXPECT_EQ(near.nearest_source[v], 0);
    } else {
      EXPECT_EQ(near.distance[v], kInf);
      EXPECT_EQ(near.nearest_source[v], kInvalidIndex);
    }
  }
  EXPECT_EQ(near.reached, inside);
  EXPECT_GT(inside, 1);
  EXPECT_LT(inside, g.num_vertices());
}

// A bound (the field of other sources) confines the run to where its own
// sources are strictly nearer: their Voronoi cells. Dijkstra's distances
// there are those of the unbounded run exactly; fast marching's may differ
// along the border of the cell, whose outer triangles the bounded front does
// not use.
TYPED_TEST(EveryGeodesicSolver, BoundConfinesTheRunToTheCellsOfItsSources) {
  const MeshGraph g = build_mesh_graph(resample_mesh(make_torus(24, 10)));
  const std::vector<double> bound = run_once<TypeParam>(g, {0}, {}).distance;
  const DistanceField free = run_once<TypeParam>(g, {0, 200}, {});
  GeodesicOptions options;
  options.bound = &bound;
  TypeParam solver(g);
  const DistanceField& cell = solver.run({0, 200}, options);  // vertex 0 is the bound's own source: not seeded
  const bool exact = std::is_same_v<TypeParam, DijkstraSolver>;
  double longest = 0.0;
  for (const double x : g.length) longest = std::max(longest, x);
  Index inside = 0;
  for (Index v = 0; v < g.num_vertices(); ++v) {
    if (cell.distance[v] < kInf) {
      ++inside;
      EXPECT_LT(cell.distance[v], bound[v]);
      EXPECT_EQ(cell.nearest_source[v], 1);
      if (exact) {
        EXPECT_EQ(cell.distance[v], free.distance[v]);
      }
    } else if (exact) {  // the unbounded run found vertex 0 nearer, or tied
      EXPECT_GE(free.distance[v], bound[v]);
    } else {  // fast marching: only at the border, within an edge
      EXPECT_GE(free.distance[v], bound[v] - longest);
    }
  }
  EXPECT_EQ(cell.reached, inside);
  EXPECT_GT(inside, g.num_vertices() / 10);
  EXPECT_LT(inside, g.num_vertices() * 9 / 10);
  const std::vector<double> too_few(3, 1.0);
  options.bound = &too_few;
  EXPECT_THROW(solver.run({200}, options), InvalidArgument);
}

TYPED_TEST(EveryGeodesicSolver, ReuseGivesTheSameFieldsAsFreshRuns) {
  const MeshGraph g = build_mesh_graph(resample_mesh(make_torus(24, 10)));
  TypeParam solver(g);
  const std::vector<std::pair<std::vector<Index>, double>> runs = {{{0}, kInf},
                                                                   {{17, 90}, 0.3},
                                                                   {{50}, kInf},
                                                                   {{2}, 0.1},
                                                                   {{200, 3}, kInf}};
  for (const auto& [sources, radius] : runs) {
    const DistanceField expected = run_once<TypeParam>(g, sources, GeodesicOptions{radius});
    const DistanceField& got = solver.run(sources, GeodesicOptions{radius});
    EXPECT_EQ(got.distance, expected.distance);
    EXPECT_EQ(got.nearest_source, expected.nearest_source);
    EXPECT_EQ(got.farthest, expected.farthest);
    EXPECT_EQ(got.max_distance, expected.max_distance);
    EXPECT_EQ(static_cast<Index>(solver.settled().size()), expected.reached);
  }
  solver.release();  // a released solver runs afresh
  EXPECT_EQ(solver.run({0}).distance, run_once<TypeParam>(g, {0}, {}).distance);
}

// farthest is the reached vertex of largest (distance, id).
TYPED_TEST(EveryGeodesicSolver, FarthestIsTheLargestDistanceTiesToTheLargestId) {
  const MeshGraph g = build_mesh_graph(make_grid(6, 6, 1.0));
  const DistanceField f = run_once<TypeParam>(g, {0, 48}, {});  // opposite corners: the other two corners tie
  EXPECT_EQ(f.distance[6], f.distance[42]);
  EXPECT_EQ(f.farthest, 42);
  EXPECT_EQ(f.max_distance, f.distance[42]);
}

TYPED_TEST(EveryGeodesicSolver, RejectsBadSourcesAndLabels) {
  const MeshGraph g = build_mesh_graph(make_cube());
  TypeParam solver(g);
  EXPECT_THROW(solver.run({8}), InvalidArgument);
  EXPECT_THROW(solver.run({-1}), InvalidArgument);
  const std::vector<Index> labels = {1, 2, 2, 2, 2, 2, 2, 2};
  GeodesicOptions options;
  options.labels = &labels;
  options.label = 2;
  EXPECT_THROW(solver.run({0}, options), InvalidArgument);  // vertex 0 has label 1
  EXPECT_EQ(solver.run({1}, options).distance[0], kInf);
  const std::vector<Index> too_few(3, 2);
  options.labels = &too_few;
  EXPECT_THROW(solver.run({1}, options), InvalidArgument);
}

TEST(GeodesicSolver, MethodsByNameAndThroughTheFactory) {
  EXPECT_EQ(parse_geodesic("dijkstra"), Geodesic::Dijkstra);
  EXPECT_EQ(parse_geodesic("fmm"), Geodesic::FastMarching);
  EXPECT_STREQ(geodesic_name(Geodesic::FastMarching), "fmm");
  EXPECT_THROW(parse_geodesic("heat"), InvalidArgument);
  const MeshGraph g = build_mesh_graph(make_torus(20, 8));
  EXPECT_EQ(geodesic_distances(g, {3, 40}, Geodesic::Dijkstra).distance, dijkstra(g, {3, 40}).distance);
  EXPECT_EQ(geodesic_distances(g, {3, 40}, Geodesic::FastMarching).distance, fast_marching(g, {3, 40}).distance);
  EXPECT_EQ(make_geodesic_solver(g, Geodesic::FastMarching)->run({7}).distance, fast_marching(g, 7).distance);
  EXPECT_NE(fast_marching(g, 7).distance, dijkstra(g, 7).distance);
}

}  // namespace
}  // namespace reebkit

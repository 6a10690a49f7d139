#include "reebkit/pipeline/analyze_mesh.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace reebkit {
namespace {

TEST(AnalyzeMesh, StarGivesOneRootAndALeafPerArm) {
  StarOptions star;
  star.arms = 5;
  star.levels = 4;
  const MeshAnalysis a = analyze_mesh(make_star(star));
  ASSERT_EQ(a.features.vertices.size(), 5u);
  ASSERT_EQ(a.fq.value.size(), static_cast<std::size_t>(a.mesh.num_vertices()));
  EXPECT_EQ(a.reeb.leaf_count(), 5);
  EXPECT_EQ(a.reeb.nodes.front().type, NodeType::Root);
  EXPECT_EQ(a.reeb.independent_cycles(), 0);
  // Each leaf region holds the feature point it ends at.
  for (const Index f : a.features.vertices)
    EXPECT_EQ(a.reeb.nodes[static_cast<std::size_t>(a.reeb.vertex_node[f])].end, NodeType::Termination);
  EXPECT_GE(a.timings.reeb, 0.0);
  EXPECT_DOUBLE_EQ(a.timings.total(), a.timings.graph + a.timings.features + a.timings.quotient + a.timings.reeb);
}

TEST(AnalyzeMesh, TorusGraphHasOneCycle) { EXPECT_EQ(analyze_mesh(make_torus(60, 20)).reeb.independent_cycles(), 1); }

TEST(AnalyzeMesh, CanStopAfterTheQuotientFunction) {
  AnalysisOptions options;
  options.reeb_graph = false;
  const MeshAnalysis a = analyze_mesh(make_icosphere(2), options);
  EXPECT_TRUE(a.reeb.nodes.empty());
  EXPECT_EQ(a.timings.reeb, 0.0);
  EXPECT_TRUE(a.spectra.global.empty());  // no graph, no attributes to prepare for
  EXPECT_FALSE(a.fq.value.empty());
}

// The whole pipeline recomputed on a moved, turned and rescaled copy gives the
// identical graph: same feature points, nodes, edges and segmentation.
void expect_similarity_invariant(const Mesh& mesh) {
  const MeshAnalysis reference = analyze_mesh(mesh);
  auto sorted = [](std::vector<Index> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Similarity t;
    t.rotation = random_rotation(seed);
    t.scale = std::pow(10.0, static_cast<double>(seed % 5) - 2.0);  // 0.01 .. 100
    t.translation = Vec3(1.5, -2.0, 7.0) * static_cast<double>(seed * seed);
    const MeshAnalysis moved = analyze_mesh(transformed(mesh, t));
    EXPECT_EQ(sorted(moved.features.vertices), sorted(reference.features.vertices)) << "seed " << seed;
    EXPECT_EQ(moved.reeb.num_nodes(), reference.reeb.num_nodes()) << "seed " << seed;
    EXPECT_EQ(moved.reeb.edges, reference.reeb.edges) << "seed " << seed;
    const auto differing = std::inner_product(moved.reeb.vertex_node.begin(), moved.reeb.vertex_node.end(),
                                              reference.reeb.vertex_node.begin(), 0, std::plus<>(),
                                              [](Index a, Index b) { return a != b ? 1 : 0; });
    EXPECT_EQ(differing, 0) << "seed " << seed << ": vertices in another region";
  }
}

TEST(AnalyzeMesh, IdenticalGraphUnderSimilarityTransforms) {
  StarOptions star;
  star.arms = 7;
  star.levels = 4;
  expect_similarity_invariant(make_star(star));
  expect_similarity_invariant(load_mesh(test::embedded_dataset_dir() / "bunny.off").components.front());
  expect_similarity_invariant(load_mesh(test::embedded_dataset_dir() / "elk.off").components.front());
}

// The graph and the spectra's surface are prepared on two threads where
// two are free: one thread or two give the same analysis and attributes, and
// the surface prepared alongside gives the attributes computed without it.
TEST(AnalyzeMesh, OneThreadOrTwoGiveTheSameGraphAndAttributes) {
  const Mesh bunny = load_mesh(test::embedded_dataset_dir() / "bunny.off").components.front();
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const MeshAnalysis serial = analyze_mesh(bunny);
  const GraphAttributes serial_attributes = compute_attributes(serial);
  omp_set_num_threads(2);
  const MeshAnalysis parallel = analyze_mesh(bunny);
  const GraphAttributes parallel_attributes = compute_attributes(parallel);
  omp_set_num_threads(threads);
  EXPECT_EQ(parallel.features.vertices, serial.features.vertices);
  EXPECT_EQ(parallel.fq.value, serial.fq.value);
  EXPECT_EQ(parallel.reeb.edges, serial.reeb.edges);
  EXPECT_EQ(parallel.reeb.vertex_node, serial.reeb.vertex_node);
  ASSERT_FALSE(serial.spectra.global.empty());
  EXPECT_EQ(parallel.spectra.global, serial.spectra.global);
  EXPECT_EQ(parallel_attributes.node, serial_attributes.node);
  EXPECT_EQ(parallel_attributes.edge, serial_attributes.edge);
  EXPECT_EQ(parallel_attributes.signature, serial_attributes.signature);
  EXPECT_GT(serial.timings.spectra_surface, 0.0);
  // The region measures, taken with the feature points' solver after the
  // graph, are those compute_attributes takes with a solver of its own.
  ASSERT_EQ(serial.measures.sums.node_area.size(), serial.reeb.nodes.size());
  EXPECT_GT(serial.timings.measures, 0.0);
  const GraphAttributes unprepared = compute_attributes(serial.mesh, serial.graph, serial.fq.value, serial.features,
                                                        serial.reeb);  // prepares its own surface and measures
  EXPECT_EQ(unprepared.node, serial_attributes.node);
  EXPECT_EQ(unprepared.edge, serial_attributes.edge);
  EXPECT_EQ(unprepared.signature, serial_attributes.signature);
  // Or the analysis leaves both to compute_attributes.
  AnalysisOptions graph_alone;
  graph_alone.prepare_attributes = false;
  const MeshAnalysis bare = analyze_mesh(bunny, graph_alone);
  EXPECT_TRUE(bare.spectra.global.empty());
  EXPECT_TRUE(bare.measures.sums.node_area.empty());
  EXPECT_EQ(bare.timings.spectra_surface, 0.0);
  EXPECT_EQ(bare.timings.measures, 0.0);
  EXPECT_EQ(compute_attributes(bare).signature, serial_attributes.signature);
}

TEST(AnalyzeMesh, MeasuresOfAnotherGraphOrSolverAreRefused) {
  const MeshAnalysis torus = analyze_mesh(make_torus(40, 16, 1.0, 0.3));
  const MeshAnalysis sphere = analyze_mesh(make_icosphere(3));
  // Measures of the torus's graph handed with the sphere's.
  EXPECT_THROW(compute_attributes(sphere.mesh, sphere.graph, sphere.fq.value, sphere.features, sphere.reeb,
                                  &sphere.spectra, sphere.spectra_options, &torus.measures),
               InvalidArgument);
  // A solver of another graph, or of another method than the feature points'.
  const std::unique_ptr<GeodesicSolver> other_graph = make_geodesic_solver(torus.graph, sphere.features.geodesic);
  EXPECT_THROW(measure_regions(sphere.mesh, sphere.graph, sphere.fq.value, sphere.features, sphere.reeb,
                               other_graph.get()),
               InvalidArgument);
  const Geodesic other = sphere.features.geodesic == Geodesic::Dijkstra ? Geodesic::FastMarching : Geodesic::Dijkstra;
  const std::unique_ptr<GeodesicSolver> other_method = make_geodesic_solver(sphere.graph, other);
  EXPECT_THROW(measure_regions(sphere.mesh, sphere.graph, sphere.fq.value, sphere.features, sphere.reeb,
                               other_method.get()),
               InvalidArgument);
  // The right solver gives what a solver of its own gives.
  const std::unique_ptr<GeodesicSolver> same = make_geodesic_solver(sphere.graph, sphere.features.geodesic);
  const RegionMeasures with_solver =
      measure_regions(sphere.mesh, sphere.graph, sphere.fq.value, sphere.features, sphere.reeb, same.get());
  EXPECT_EQ(with_solver.geodesics.extent, sphere.measures.geodesics.extent);
  EXPECT_EQ(with_solver.geodesics.histogram, sphere.measures.geodesics.histogram);
}

TEST(AnalyzeMesh, RejectsADisconnectedMesh) {
  Mesh two;
  two.vertices.resize(6, 3);
  two.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0;
  two.triangles.resize(2, 3);
  two.triangles << 0, 1, 2, 3, 4, 5;
  EXPECT_THROW(analyze_mesh(two), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

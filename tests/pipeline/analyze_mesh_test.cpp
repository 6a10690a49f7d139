#include "reebkit/pipeline/analyze_mesh.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

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

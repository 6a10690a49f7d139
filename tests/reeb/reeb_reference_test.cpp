#include "reebkit/reeb/reeb_reference.h"

#include "reeb/reeb_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

namespace reebkit::test {
namespace {

class StarArms : public ::testing::TestWithParam<std::tuple<int, int>> {};

// The body is swept first, then the line splits into one line per arm, each
// ending at its tip: one root, a leaf per feature point (the maxima of f_q),
// no cycle. From 4 subdivision levels on, every arm has its feature point;
// on the coarser stars feature extraction finds fewer (see the features tests).
TEST_P(StarArms, OneRootAndOneLeafPerFeaturePoint) {
  const auto [arms, levels] = GetParam();
  StarOptions options;
  options.arms = arms;
  options.levels = levels;
  const Mesh mesh = make_star(options);
  const MeshGraph graph = build_mesh_graph(mesh);
  const std::vector<Index> features = extract_feature_points(mesh, graph).vertices;
  const ReebInput in{mesh, graph, quotient_function(graph, features).value};
  const ReebGraph g = reference_reeb_graph(in.mesh, in.graph, in.fq);
  expect_consistent(g, in.mesh, in.fq);
  EXPECT_EQ(g.independent_cycles(), 0) << summary(g);
  if (levels >= 4) {
    EXPECT_EQ(features.size(), static_cast<std::size_t>(arms));
  }
  EXPECT_EQ(count_nodes(g, &ReebNode::end, NodeType::Termination), static_cast<Index>(features.size())) << summary(g);
  std::vector<Index> leaf_of_feature;
  for (const Index f : features) {
    const Index node = g.vertex_node[static_cast<std::size_t>(f)];
    EXPECT_EQ(g.nodes[static_cast<std::size_t>(node)].end, NodeType::Termination) << "feature " << f;
    leaf_of_feature.push_back(node);
  }
  std::sort(leaf_of_feature.begin(), leaf_of_feature.end());
  EXPECT_EQ(std::unique(leaf_of_feature.begin(), leaf_of_feature.end()), leaf_of_feature.end())
      << "two feature points in one leaf";
}

INSTANTIATE_TEST_SUITE_P(Counts, StarArms,
                         ::testing::Combine(::testing::Values(2, 3, 4, 5, 6, 7, 8), ::testing::Values(3, 4)));

TEST(ReferenceReebGraph, TorusHasOneCycle) {
  for (const auto& [major, minor] : {std::pair{40, 14}, std::pair{24, 8}, std::pair{64, 20}}) {
    const ReebInput in = reeb_input(make_torus(major, minor));
    const ReebGraph g = reference_reeb_graph(in.mesh, in.graph, in.fq);
    expect_consistent(g, in.mesh, in.fq);
    EXPECT_EQ(g.independent_cycles(), 1) << major << "x" << minor << ": " << summary(g);
  }
}

TEST(ReferenceReebGraph, SphereGivesATree) {
  for (const int levels : {1, 2, 3, 4}) {
    const ReebInput in = reeb_input(make_icosphere(levels));
    const ReebGraph g = reference_reeb_graph(in.mesh, in.graph, in.fq);
    expect_consistent(g, in.mesh, in.fq);
    EXPECT_EQ(g.independent_cycles(), 0) << "levels " << levels << ": " << summary(g);
  }
}

TEST(ReferenceReebGraph, NodeAreasSumToTheSurfaceArea) {
  const ReebInput in = reeb_input(make_star(StarOptions{}));
  const ReebGraph g = reference_reeb_graph(in.mesh, in.graph, in.fq);
  const double total = surface_area(in.mesh);
  double sum = 0;
  for (const ReebNode& n : g.nodes) sum += n.area;
  EXPECT_NEAR(sum, total, 1e-9 * total);
}

// The graph depends on f and the connectivity only, and f_q is invariant
// (section 5.3): the same nodes, edges and segmentation after a similarity,
// with areas scaled and barycenters moved along.
TEST(ReferenceReebGraph, InvariantToSimilarityTransforms) {
  StarOptions options;
  options.arms = 6;
  options.levels = 4;
  options.twist = 0.3;
  const ReebInput in = reeb_input(make_star(options));
  const ReebGraph g = reference_reeb_graph(in.mesh, in.graph, in.fq);
  Similarity t;
  t.rotation = random_rotation(7);
  t.scale = 12.5;
  t.translation = Vec3(3, -8, 0.5);
  const ReebInput moved = reeb_input(transformed(in.mesh, t));
  const ReebGraph h = reference_reeb_graph(moved.mesh, moved.graph, moved.fq);
  ASSERT_EQ(h.num_nodes(), g.num_nodes());
  EXPECT_EQ(h.edges, g.edges);
  EXPECT_EQ(h.vertex_node, g.vertex_node);
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    EXPECT_EQ(h.nodes[n].type, g.nodes[n].type);
    EXPECT_EQ(h.nodes[n].end, g.nodes[n].end);
    EXPECT_NEAR(h.nodes[n].fq_min, g.nodes[n].fq_min, 1e-9);
    EXPECT_NEAR(h.nodes[n].area, t.scale * t.scale * g.nodes[n].area, 1e-9 * h.nodes[n].area + 1e-12);
    const Vec3 expected = t.scale * t.rotation * g.nodes[n].barycenter + t.translation;
    EXPECT_LT((h.nodes[n].barycenter - expected).norm(), 1e-9 * t.scale);
  }
}

TEST(ReferenceReebGraph, RejectsMismatchedInputs) {
  const ReebInput in = reeb_input(make_icosphere(1));
  EXPECT_THROW(reference_reeb_graph(in.mesh, in.graph, {}), InvalidArgument);
  std::vector<double> nan = in.fq;
  nan[3] = std::nan("");
  EXPECT_THROW(reference_reeb_graph(in.mesh, in.graph, nan), InvalidArgument);
  EXPECT_THROW(reference_reeb_graph(make_cube(), in.graph, in.fq), InvalidArgument);
  const ReebInput two = reeb_input(make_icosphere(1));  // one component's f_q, reused below
  const Mesh pair = disjoint_union(two.mesh, two.mesh);
  std::vector<double> f = two.fq;
  f.insert(f.end(), two.fq.begin(), two.fq.end());
  EXPECT_THROW(reference_reeb_graph(pair, build_mesh_graph(pair), f), InvalidArgument);
}

}  // namespace
}  // namespace reebkit::test

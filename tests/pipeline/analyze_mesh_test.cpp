#include "reebkit/pipeline/analyze_mesh.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace reebkit {
namespace {

TEST(AnalyzeMesh, StarGivesOneRootAndALeafPerArm) {
  StarOptions star;
  star.arms = 5;
  star.levels = 4;
  const MeshAnalysis a = analyze_mesh(make_star(star));
  ASSERT_EQ(a.features.vertices.size(), 5u);
  ASSERT_EQ(a.fq.value.size(), static_cast<std::size_t>(a.mesh.num_vertices()));
  const auto leaves = std::count_if(a.reeb.nodes.begin(), a.reeb.nodes.end(),
                                    [](const ReebNode& n) { return n.end == NodeType::Termination; });
  EXPECT_EQ(leaves, 5);
  EXPECT_EQ(a.reeb.nodes.front().type, NodeType::Root);
  EXPECT_EQ(a.reeb.independent_cycles(), 0);
  // Each leaf region holds the feature point it ends at.
  for (const Index f : a.features.vertices)
    EXPECT_EQ(a.reeb.nodes[static_cast<std::size_t>(a.reeb.vertex_node[f])].end, NodeType::Termination);
  EXPECT_GE(a.timings.reeb, 0.0);
  EXPECT_DOUBLE_EQ(a.timings.total(), a.timings.graph + a.timings.features + a.timings.quotient + a.timings.reeb);
}

TEST(AnalyzeMesh, TorusGraphHasOneCycle) {
  EXPECT_EQ(analyze_mesh(make_torus(60, 20)).reeb.independent_cycles(), 1);
}

TEST(AnalyzeMesh, CanStopAfterTheQuotientFunction) {
  AnalysisOptions options;
  options.reeb_graph = false;
  const MeshAnalysis a = analyze_mesh(make_icosphere(2), options);
  EXPECT_TRUE(a.reeb.nodes.empty());
  EXPECT_EQ(a.timings.reeb, 0.0);
  EXPECT_FALSE(a.fq.value.empty());
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

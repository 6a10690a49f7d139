#include "reebkit/reeb/pit_cancellation.h"

#include "reeb/reeb_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/features/critical_points.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/remeshing.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/pipeline/analyze_mesh.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace reebkit::test {
namespace {

/// The nodes whose region holds a local maximum of f.
std::vector<bool> peaks(const ReebGraph& g, const MeshGraph& graph, const std::vector<double>& f) {
  std::vector<bool> peak(static_cast<std::size_t>(g.num_nodes()), false);
  for (Index v = 0; v < graph.num_vertices(); ++v)
    if (is_local_maximum(graph, f, v))
      peak[static_cast<std::size_t>(g.vertex_node[static_cast<std::size_t>(v)])] = true;
  return peak;
}

/// Terminations whose region holds no local maximum of f.
Index pits(const ReebGraph& g, const MeshGraph& graph, const std::vector<double>& f) {
  const std::vector<bool> peak = peaks(g, graph, f);
  Index count = 0;
  for (Index n = 0; n < g.num_nodes(); ++n)
    count += g.nodes[static_cast<std::size_t>(n)].end == NodeType::Termination && !peak[static_cast<std::size_t>(n)];
  return count;
}

/// Each node's region (vertex count, f range, area) is that of the vertices
/// labelled with it, and its end matches its edges: a Termination feeds no
/// node, a Bifurcation at least two; and expect_consistent's checks.
void expect_regions_match(const ReebGraph& g, const Mesh& mesh, const std::vector<double>& f) {
  const auto n = static_cast<std::size_t>(g.num_nodes());
  std::vector<Index> count(n, 0), out(n, 0);
  std::vector<double> low(n, 1e300), high(n, -1e300), area(n, 0.0);
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index v = mesh.triangles(t, k);
      area[static_cast<std::size_t>(g.vertex_node[static_cast<std::size_t>(v)])] += triangle_area(mesh, t) / 3.0;
    }
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const auto node = static_cast<std::size_t>(g.vertex_node[static_cast<std::size_t>(v)]);
    ASSERT_LT(node, n);
    ++count[node];
    low[node] = std::min(low[node], f[static_cast<std::size_t>(v)]);
    high[node] = std::max(high[node], f[static_cast<std::size_t>(v)]);
  }
  for (const auto& [a, b] : g.edges) {
    EXPECT_LT(a, b);
    ++out[static_cast<std::size_t>(a)];
  }
  for (std::size_t k = 0; k < n; ++k) {
    SCOPED_TRACE("node " + std::to_string(k));
    const ReebNode& node = g.nodes[k];
    EXPECT_EQ(node.vertex_count, count[k]);
    EXPECT_NEAR(node.area, area[k], 1e-9 * (1.0 + area[k]));
    if (count[k] > 0) {
      EXPECT_EQ(node.fq_min, low[k]);
      EXPECT_EQ(node.fq_max, high[k]);
    }
    EXPECT_EQ(node.end == NodeType::Termination, out[k] == 0);
    if (node.end == NodeType::Bifurcation) {
      EXPECT_GE(out[k], 2);
    }
  }
  expect_consistent(g, mesh, f);
}

void expect_same_graph(const ReebGraph& a, const ReebGraph& b) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.vertex_node, b.vertex_node);
  for (std::size_t k = 0; k < a.nodes.size(); ++k) {
    EXPECT_EQ(a.nodes[k].end, b.nodes[k].end) << "node " << k;
    EXPECT_EQ(a.nodes[k].area, b.nodes[k].area) << "node " << k;
    EXPECT_EQ(a.nodes[k].skeleton, b.nodes[k].skeleton) << "node " << k;
  }
}

TEST(CancelPits, EveryLeafHoldsAMaximumOfFAndTheCyclesStay) {
  const std::vector<Mesh> meshes = {make_icosphere(3), make_torus(30, 12), make_grid(20, 15), make_holed_plate(2)};
  ReebOptions propagation;
  propagation.leaves = Leaves::Propagation;
  unsigned seed = 1;
  Index cancelled = 0;
  for (const Mesh& mesh : meshes) {
    const MeshGraph graph = build_mesh_graph(mesh);
    for (int run = 0; run < 5; ++run, ++seed) {
      SCOPED_TRACE("seed " + std::to_string(seed));
      const std::vector<double> f = random_ranks(mesh.num_vertices(), seed);
      const ReebGraph raw = build_reeb_graph(mesh, graph, f, propagation);
      const ReebGraph g = build_reeb_graph(mesh, graph, f);
      const Index raw_pits = pits(raw, graph, f);
      cancelled += raw_pits;
      EXPECT_EQ(pits(g, graph, f), 0);
      EXPECT_EQ(g.leaf_count(), raw.leaf_count() - raw_pits);
      EXPECT_EQ(g.independent_cycles(), raw.independent_cycles());
      EXPECT_EQ(g.connected_components(), raw.connected_components());
      EXPECT_LE(g.num_nodes(), raw.num_nodes() - raw_pits);
      expect_regions_match(raw, mesh, f);
      expect_regions_match(g, mesh, f);
      expect_same_graph(cancel_pits(raw, graph, f), g);
    }
  }
  EXPECT_GT(cancelled, 0) << "no random function made a pit: the test checks nothing";
}

// A remeshed elk (datasets/, CC0) on which the propagation of f_q closes
// around two vertices it had passed above: two terminations with no feature
// point. Cancelled, the leaves are the feature points (eq. 11), and the
// one cycle of the elk (genus 1) stays.
TEST(CancelPits, LeavesAreTheFeaturePointsOfARemeshedElk) {
  const Mesh elk = load_mesh(embedded_dataset_dir() / "elk.off").components.front();
  RemeshOptions options;
  options.target_vertices = elk.num_vertices();
  options.seed = 3;
  const Mesh remeshed = remesh(elk, options).mesh;
  // Feature points at the scale of a toe (epsilon 0.05), where this remeshed
  // elk's propagation closes around two pits.
  AnalysisOptions maxima;
  maxima.features.epsilon = 0.05;
  maxima.features.min_persistence = 0.01;
  AnalysisOptions propagation = maxima;
  propagation.reeb.leaves = Leaves::Propagation;
  const MeshAnalysis raw = analyze_mesh(remeshed, propagation);
  const MeshAnalysis a = analyze_mesh(remeshed, maxima);
  ASSERT_EQ(a.features.vertices, raw.features.vertices);
  const auto features = static_cast<Index>(a.features.vertices.size());
  EXPECT_EQ(pits(raw.reeb, raw.graph, raw.fq.value), 2);
  EXPECT_EQ(raw.reeb.leaf_count(), features + 2);
  EXPECT_EQ(a.reeb.leaf_count(), features);
  EXPECT_EQ(a.reeb.num_nodes(), raw.reeb.num_nodes() - 4);
  EXPECT_EQ(a.reeb.independent_cycles(), 1);
  EXPECT_EQ(raw.reeb.independent_cycles(), 1);
  expect_regions_match(a.reeb, a.mesh, a.fq.value);
}

TEST(Leaves, NamesRoundTrip) {
  for (const Leaves leaves : {Leaves::Maxima, Leaves::Propagation})
    EXPECT_EQ(parse_leaves(leaves_name(leaves)), leaves);
  EXPECT_NE(thrown_message<InvalidArgument>([] { parse_leaves("peaks"); }).find("expected maxima or propagation"),
            std::string::npos);
}

}  // namespace
}  // namespace reebkit::test

// Helpers shared by the reeb tests: a mesh with its graph and the quotient
// function of its own feature points, and graph summaries for messages.
#pragma once

#include "reebkit/features/feature_points.h"
#include "reebkit/features/quotient_function.h"
#include "reebkit/mesh/mesh_graph.h"
#include "reebkit/reeb/reeb_graph.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace reebkit::test {

/// A mesh ready for the Reeb graph: its graph and f_q of its feature points.
struct ReebInput {
  Mesh mesh;
  MeshGraph graph;
  std::vector<double> fq;
};

inline ReebInput reeb_input(Mesh mesh) {
  ReebInput in;
  in.mesh = std::move(mesh);
  in.graph = build_mesh_graph(in.mesh);
  in.fq = quotient_function(in.graph, extract_feature_points(in.mesh, in.graph).vertices).value;
  return in;
}

inline Index count_nodes(const ReebGraph& g, NodeType ReebNode::*field, NodeType type) {
  return static_cast<Index>(
      std::count_if(g.nodes.begin(), g.nodes.end(), [&](const ReebNode& n) { return n.*field == type; }));
}

/// `a` and `b` side by side as one mesh (b's vertices numbered after a's).
inline Mesh disjoint_union(const Mesh& a, const Mesh& b) {
  Mesh m;
  m.vertices.resize(a.num_vertices() + b.num_vertices(), 3);
  m.vertices << a.vertices, b.vertices;
  m.triangles.resize(a.num_triangles() + b.num_triangles(), 3);
  m.triangles << a.triangles, b.triangles.array() + a.num_vertices();
  return m;
}

/// The skeleton of each node lies in the bounding box of the vertices its
/// level line goes on to absorb: those of the node and of the nodes after it
/// (edges run from earlier to later nodes), and v_t of the event that ends
/// it (the birth vertex of the nodes after it), which a contour line holds
/// even where another line absorbs it. The root's starts at the global
/// minimum; a leaf's ends at one of its own vertices, where its line vanished.
inline void expect_skeleton_in_place(const ReebGraph& g, const Mesh& mesh, const std::vector<double>& f) {
  const double tolerance = 1e-9 * (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
  const Eigen::AlignedBox3d empty;
  std::vector<Eigen::AlignedBox3d> box(g.nodes.size(), empty);
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    box[static_cast<std::size_t>(g.vertex_node[static_cast<std::size_t>(v)])].extend(Vec3(mesh.vertices.row(v)));
  for (auto e = g.edges.rbegin(); e != g.edges.rend(); ++e) {
    Eigen::AlignedBox3d& before = box[static_cast<std::size_t>((*e)[0])];
    before.extend(box[static_cast<std::size_t>((*e)[1])]);
    before.extend(Vec3(mesh.vertices.row(g.nodes[static_cast<std::size_t>((*e)[1])].birth_vertex)));
  }
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    const std::vector<Vec3>& skeleton = g.nodes[n].skeleton;
    ASSERT_FALSE(skeleton.empty()) << "node " << n;
    for (const Vec3& p : skeleton)
      EXPECT_LE(box[n].exteriorDistance(p), tolerance) << "node " << n << " point " << p.transpose();
    if (g.nodes[n].end != NodeType::Termination) continue;
    bool at_own_vertex = false;
    for (Index v = 0; v < mesh.num_vertices(); ++v)
      at_own_vertex |= g.vertex_node[static_cast<std::size_t>(v)] == static_cast<Index>(n) &&
                       (Vec3(mesh.vertices.row(v)) - skeleton.back()).norm() <= tolerance;
    EXPECT_TRUE(at_own_vertex) << "leaf " << n;
  }
  const auto minimum = std::min_element(f.begin(), f.end()) - f.begin();
  EXPECT_EQ(g.nodes[0].skeleton.front(), Vec3(mesh.vertices.row(minimum)));
}

/// Every vertex labeled, node counts and f ranges consistent with the labels,
/// nodes without vertices placed at their birth vertex, the root the region of
/// the global minimum, edges from earlier to later nodes, one component, the
/// skeleton in place.
inline void expect_consistent(const ReebGraph& g, const Mesh& mesh, const std::vector<double>& f) {
  ASSERT_EQ(g.vertex_node.size(), f.size());
  std::vector<Index> count(g.nodes.size(), 0);
  for (std::size_t v = 0; v < f.size(); ++v) {
    const Index node = g.vertex_node[v];
    ASSERT_TRUE(node >= 0 && node < g.num_nodes()) << "vertex " << v;
    ++count[static_cast<std::size_t>(node)];
    EXPECT_GE(f[v], g.nodes[static_cast<std::size_t>(node)].fq_min);
    EXPECT_LE(f[v], g.nodes[static_cast<std::size_t>(node)].fq_max);
  }
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    const ReebNode& node = g.nodes[n];
    EXPECT_EQ(count[n], node.vertex_count) << "node " << n;
    if (node.vertex_count > 0) continue;
    EXPECT_EQ(node.area, 0.0);
    EXPECT_EQ(node.fq_min, f[static_cast<std::size_t>(node.birth_vertex)]);
    EXPECT_EQ(node.barycenter, Vec3(mesh.vertices.row(node.birth_vertex)));
  }
  EXPECT_EQ(count_nodes(g, &ReebNode::type, NodeType::Root), 1);
  EXPECT_EQ(g.nodes[0].type, NodeType::Root);
  EXPECT_EQ(g.nodes[0].fq_min, *std::min_element(f.begin(), f.end()));
  for (const auto& [a, b] : g.edges) EXPECT_LT(a, b);
  // A leaf is a node that hands over to no later node.
  std::vector<char> hands_over(g.nodes.size(), 0);
  for (const auto& [a, b] : g.edges) hands_over[static_cast<std::size_t>(a)] = 1;
  EXPECT_EQ(g.leaf_count(), std::count(hands_over.begin(), hands_over.end(), 0));
  EXPECT_EQ(g.connected_components(), 1);
  expect_skeleton_in_place(g, mesh, f);
}

/// f = a random ranking of the vertices: level lines split and merge at
/// almost every step, often several times at one vertex.
inline std::vector<double> random_ranks(Index n, unsigned seed) {
  std::vector<double> f(static_cast<std::size_t>(n));
  std::iota(f.begin(), f.end(), 0.0);
  std::shuffle(f.begin(), f.end(), std::mt19937(seed));
  return f;
}

/// f = a coordinate: the height function of the classic Reeb graph pictures.
inline std::vector<double> height(const Mesh& mesh, int axis) {
  std::vector<double> f(static_cast<std::size_t>(mesh.num_vertices()));
  for (Index v = 0; v < mesh.num_vertices(); ++v) f[static_cast<std::size_t>(v)] = mesh.vertices(v, axis);
  return f;
}

/// "N nodes, E edges, C cycles, L leaves" for failure messages.
inline std::string summary(const ReebGraph& g) {
  std::ostringstream s;
  s << g.num_nodes() << " nodes, " << g.num_edges() << " edges, " << g.independent_cycles() << " cycles, "
    << g.leaf_count() << " leaves";
  return s.str();
}

}  // namespace reebkit::test

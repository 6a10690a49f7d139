// Helpers shared by the reeb tests: a mesh with its graph and the quotient
// function of its own feature points, and graph summaries for messages.
#pragma once

#include "reebkit/features/feature_points.h"
#include "reebkit/features/quotient_function.h"
#include "reebkit/mesh/mesh_graph.h"
#include "reebkit/reeb/reeb_graph.h"

#include <algorithm>
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
  in.fq = quotient_function(in.graph, extract_feature_points(in.graph).vertices).value;
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

/// "N nodes, E edges, C cycles, L leaves" for failure messages.
inline std::string summary(const ReebGraph& g) {
  std::ostringstream s;
  s << g.num_nodes() << " nodes, " << g.num_edges() << " edges, " << g.independent_cycles() << " cycles, "
    << count_nodes(g, &ReebNode::end, NodeType::Termination) << " leaves";
  return s.str();
}

}  // namespace reebkit::test

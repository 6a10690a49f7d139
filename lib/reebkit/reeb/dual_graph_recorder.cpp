#include "reebkit/reeb/dual_graph_recorder.h"

#include "reebkit/core/error.h"
#include "reebkit/features/critical_points.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace reebkit {

void check_reeb_inputs(const char* who, const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f) {
  const std::string name(who);
  if (mesh.num_vertices() == 0) throw InvalidArgument(name + ": empty mesh");
  if (graph.num_vertices() != mesh.num_vertices())
    throw InvalidArgument(name + ": the mesh graph has " + std::to_string(graph.num_vertices()) +
                          " vertices, the mesh " + std::to_string(mesh.num_vertices()));
  if (f.size() != static_cast<std::size_t>(mesh.num_vertices()))
    throw InvalidArgument(name + ": f has " + std::to_string(f.size()) + " values for " +
                          std::to_string(mesh.num_vertices()) + " vertices");
  for (std::size_t v = 0; v < f.size(); ++v)
    if (!std::isfinite(f[v])) throw InvalidArgument(name + ": f is not finite at vertex " + std::to_string(v));
}

Index global_minimum(const std::vector<double>& f) {
  Index best = 0;
  for (Index v = 1; v < static_cast<Index>(f.size()); ++v)
    if (sos_less(f, v, best)) best = v;
  return best;
}

DualGraphRecorder::DualGraphRecorder(Index num_vertices) {
  graph_.vertex_node.assign(static_cast<std::size_t>(num_vertices), kInvalidIndex);
}

Index DualGraphRecorder::add_node(NodeType type, Index birth_vertex) {
  ReebNode node;
  node.type = type;
  node.birth_vertex = birth_vertex;
  graph_.nodes.push_back(node);
  return graph_.num_nodes() - 1;
}

Index DualGraphRecorder::start_root(Index minimum) { return add_node(NodeType::Root, minimum); }

void DualGraphRecorder::step(Index v, const LineChange& change, std::vector<Index>& new_nodes) {
  new_nodes.clear();
  if (change.old_nodes.size() == 1 && change.new_lines == 1) {  // no event
    new_nodes.push_back(change.old_nodes[0]);
    return;
  }
  parents_.assign(static_cast<std::size_t>(change.new_lines), 0);
  for (const auto& link : change.links) ++parents_[static_cast<std::size_t>(link[1])];
  for (const Index parents : parents_)
    new_nodes.push_back(add_node(parents > 1 ? NodeType::Junction : NodeType::Bifurcation, v));
  for (const Index old : change.old_nodes) graph_.nodes[static_cast<std::size_t>(old)].end = NodeType::Termination;
  for (const auto& [old, line] : change.links) {
    const Index from = change.old_nodes[static_cast<std::size_t>(old)];
    graph_.edges.push_back({from, new_nodes[static_cast<std::size_t>(line)]});
    // First link: the old line continues in one line only (a junction, or
    // one of several old lines feeding a line); a second: it split.
    NodeType& end = graph_.nodes[static_cast<std::size_t>(from)].end;
    end = end == NodeType::Termination ? NodeType::Junction : NodeType::Bifurcation;
  }
}

ReebGraph DualGraphRecorder::finish(const Mesh& mesh, const std::vector<double>& f) {
  // One third of each triangle's area to each of its corners (section 5.2).
  std::vector<double> vertex_area(static_cast<std::size_t>(mesh.num_vertices()), 0.0);
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const Vec3 a = mesh.vertices.row(mesh.triangles(t, 0));
    const Vec3 b = mesh.vertices.row(mesh.triangles(t, 1));
    const Vec3 c = mesh.vertices.row(mesh.triangles(t, 2));
    const double third = (b - a).cross(c - a).norm() / 6.0;
    for (int k = 0; k < 3; ++k) vertex_area[static_cast<std::size_t>(mesh.triangles(t, k))] += third;
  }
  std::vector<Vec3> position_sum(graph_.nodes.size(), Vec3::Zero());  // unweighted, for area-less regions
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const auto i = static_cast<std::size_t>(v);
    ReebNode& node = graph_.nodes[static_cast<std::size_t>(graph_.vertex_node[i])];
    const Vec3 x = mesh.vertices.row(v);
    if (node.vertex_count == 0) node.fq_min = node.fq_max = f[i];
    node.fq_min = std::min(node.fq_min, f[i]);
    node.fq_max = std::max(node.fq_max, f[i]);
    ++node.vertex_count;
    node.area += vertex_area[i];
    node.barycenter += vertex_area[i] * x;
    position_sum[static_cast<std::size_t>(graph_.vertex_node[i])] += x;
  }
  for (std::size_t n = 0; n < graph_.nodes.size(); ++n) {
    ReebNode& node = graph_.nodes[n];
    if (node.area > 0.0) {
      node.barycenter /= node.area;
    } else if (node.vertex_count > 0) {
      node.barycenter = position_sum[n] / node.vertex_count;
    } else {
      node.fq_min = node.fq_max = f[static_cast<std::size_t>(node.birth_vertex)];
      node.barycenter = mesh.vertices.row(node.birth_vertex);
    }
  }
  std::sort(graph_.edges.begin(), graph_.edges.end());
  return std::move(graph_);
}

}  // namespace reebkit

#include "reebkit/reeb/dual_graph_recorder.h"

#include "reebkit/core/error.h"
#include "reebkit/features/critical_points.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace reebkit {

void check_reeb_inputs(const char* who, const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                       const ReebOptions& options) {
  const std::string name(who);
  if (options.skeleton_levels < 1)
    throw InvalidArgument(name + ": skeleton_levels is " + std::to_string(options.skeleton_levels) +
                          ", must be at least 1");
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

DualGraphRecorder::DualGraphRecorder(const Mesh& mesh, const std::vector<double>& f, const ReebOptions& options)
    : mesh_(mesh), f_(f), levels_(options.skeleton_levels) {
  graph_.vertex_node.assign(f.size(), kInvalidIndex);
  const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
  f_min_ = *lo;
  if (*hi > *lo) level_scale_ = levels_ / (*hi - *lo);
}

Index DualGraphRecorder::add_node(NodeType type, Index birth_vertex) {
  ReebNode node;
  node.type = type;
  node.birth_vertex = birth_vertex;
  graph_.nodes.push_back(node);
  last_level_.push_back(0);
  line_shown_.push_back(0);
  return graph_.num_nodes() - 1;
}

Index DualGraphRecorder::level_of(Index v) const {
  const double t = (f_[static_cast<std::size_t>(v)] - f_min_) * level_scale_;
  return std::min(static_cast<Index>(t), levels_ - 1);
}

void DualGraphRecorder::sample(Index node, const Vec3& center, Index level) {
  const auto n = static_cast<std::size_t>(node);
  graph_.nodes[n].skeleton.push_back(center);
  last_level_[n] = level;
  line_shown_[n] = 1;
}

Index DualGraphRecorder::start_root(Index minimum) {
  const Index root = add_node(NodeType::Root, minimum);
  sample(root, mesh_.vertices.row(minimum), level_of(minimum));
  return root;
}

void DualGraphRecorder::link(Index from, Index to) {
  graph_.edges.push_back({from, to});
  // First link: the old line continues in one line only (a junction, or
  // one of several old lines feeding a line); a second: it split.
  NodeType& end = graph_.nodes[static_cast<std::size_t>(from)].end;
  end = end == NodeType::Termination ? NodeType::Junction : NodeType::Bifurcation;
}

void DualGraphRecorder::step(Index v, const LineChange& change, std::vector<Index>& new_nodes) {
  new_nodes.clear();
  const Index level = level_of(v);
  if (change.old_nodes.size() == 1 && change.new_lines == 1 && change.cycles <= 0) {  // no event
    new_nodes.push_back(change.old_nodes[0]);
    continue_line(v, change.old_nodes[0], [&change] { return change.new_centers[0]; });
    return;
  }
  for (std::size_t k = 0; k < change.old_nodes.size(); ++k) {
    const auto old = static_cast<std::size_t>(change.old_nodes[k]);
    graph_.nodes[old].end = NodeType::Termination;
    if (line_shown_[old] == 0) sample(change.old_nodes[k], change.old_centers[k], level);
  }
  // Each link adds an edge and each new line a node: the links close
  // links - new_lines cycles among nodes that were connected already.
  const auto linked_cycles = static_cast<Index>(change.links.size()) - change.new_lines;
  if (change.cycles >= 0 && change.cycles != linked_cycles &&
      change.cycles >= static_cast<Index>(change.old_nodes.size()) - 1) {
    unfold(v, level, change, new_nodes);
    return;
  }
  parents_.assign(static_cast<std::size_t>(change.new_lines), 0);
  for (const auto& link : change.links) ++parents_[static_cast<std::size_t>(link[1])];
  for (std::size_t k = 0; k < parents_.size(); ++k) {
    new_nodes.push_back(add_node(parents_[k] > 1 ? NodeType::Junction : NodeType::Bifurcation, v));
    sample(new_nodes.back(), change.new_centers[k], level);
  }
  for (const auto& [old, line] : change.links)
    link(change.old_nodes[static_cast<std::size_t>(old)], new_nodes[static_cast<std::size_t>(line)]);
}

void DualGraphRecorder::unfold(Index v, Index level, const LineChange& change, std::vector<Index>& new_nodes) {
  Vec3 center = mesh_.vertices.row(v);
  if (change.new_lines > 0) {
    center.setZero();
    for (const Vec3& c : change.new_centers) center += c;
    center /= static_cast<double>(change.new_centers.size());
  }
  const auto saddle_node = [&](NodeType type) {
    const Index node = add_node(type, v);
    sample(node, center, level);
    return node;
  };
  // The old lines merge (closing old_nodes - 1 cycles), ...
  Index hub = saddle_node(change.old_nodes.size() > 1 ? NodeType::Junction : NodeType::Bifurcation);
  for (const Index old : change.old_nodes) link(old, hub);
  // ... every further cycle is a split and a merge, ...
  for (Index c = static_cast<Index>(change.old_nodes.size()) - 1; c < change.cycles; ++c) {
    const Index a = saddle_node(NodeType::Bifurcation);
    const Index b = saddle_node(NodeType::Bifurcation);
    link(hub, a);
    link(hub, b);
    hub = saddle_node(NodeType::Junction);
    link(a, hub);
    link(b, hub);
  }
  // ... and the last node splits into the new lines.
  for (Index k = 0; k < change.new_lines; ++k) {
    new_nodes.push_back(add_node(NodeType::Bifurcation, v));
    sample(new_nodes.back(), change.new_centers[static_cast<std::size_t>(k)], level);
    link(hub, new_nodes.back());
  }
}

ReebGraph DualGraphRecorder::finish() {
  const Mesh& mesh = mesh_;
  const std::vector<double>& f = f_;
  // One third of each triangle's area to each of its corners (section 5.2).
  std::vector<double> vertex_area(static_cast<std::size_t>(mesh.num_vertices()), 0.0);
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const double third = triangle_area(mesh, t) / 3.0;
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

#include "reebkit/reeb/pit_cancellation.h"

#include "reebkit/features/critical_points.h"

#include <algorithm>

namespace reebkit {

namespace {

/// Region `from` joins region `into`: vertex count, area, f range and the
/// area-weighted barycenter (by vertex count where both are area-less, as
/// DualGraphRecorder::finish does).
void join_region(ReebNode& into, const ReebNode& from) {
  const double area = into.area + from.area;
  if (area > 0.0) {
    into.barycenter = (into.area * into.barycenter + from.area * from.barycenter) / area;
  } else if (into.vertex_count + from.vertex_count > 0) {
    into.barycenter = (static_cast<double>(into.vertex_count) * into.barycenter +
                       static_cast<double>(from.vertex_count) * from.barycenter) /
                      static_cast<double>(into.vertex_count + from.vertex_count);
  }
  into.area = area;
  into.vertex_count += from.vertex_count;
  into.fq_min = std::min(into.fq_min, from.fq_min);
  into.fq_max = std::max(into.fq_max, from.fq_max);
}

void erase_value(std::vector<Index>& list, Index value) { list.erase(std::find(list.begin(), list.end(), value)); }

}  // namespace

ReebGraph cancel_pits(ReebGraph graph, const MeshGraph& mesh_graph, const std::vector<double>& f) {
  const auto n = graph.nodes.size();
  const auto at = [](Index i) { return static_cast<std::size_t>(i); };
  std::vector<char> peak(n, 0);  // the region holds a local maximum of f
  for (Index v = 0; v < mesh_graph.num_vertices(); ++v)
    if (is_local_maximum(mesh_graph, f, v)) peak[at(graph.vertex_node[at(v)])] = 1;
  std::vector<std::vector<Index>> in(n), out(n);
  for (const auto& [a, b] : graph.edges) {
    out[at(a)].push_back(b);
    in[at(b)].push_back(a);
  }
  std::vector<Index> joined(n, kInvalidIndex);  // the node a cancelled node's region went to
  // Later nodes first: a node whose every successor was a pit is checked after them.
  for (Index pit = static_cast<Index>(n) - 1; pit >= 0; --pit) {
    ReebNode& node = graph.nodes[at(pit)];
    if (joined[at(pit)] != kInvalidIndex || node.end != NodeType::Termination || peak[at(pit)] ||
        in[at(pit)].size() != 1)
      continue;
    const Index parent = in[at(pit)][0];
    ReebNode& kept = graph.nodes[at(parent)];
    join_region(kept, node);
    joined[at(pit)] = parent;
    erase_value(out[at(parent)], pit);
    in[at(pit)].clear();
    if (out[at(parent)].empty()) {
      kept.end = NodeType::Termination;
    } else if (out[at(parent)].size() == 1) {
      const Index next = out[at(parent)][0];
      if (in[at(next)].size() == 1) {  // the split was the pit's: one line goes on
        ReebNode& later = graph.nodes[at(next)];
        join_region(kept, later);
        kept.end = later.end;
        kept.skeleton.insert(kept.skeleton.end(), later.skeleton.begin(), later.skeleton.end());
        peak[at(parent)] = static_cast<char>(peak[at(parent)] || peak[at(next)]);
        out[at(parent)] = std::move(out[at(next)]);
        for (const Index successor : out[at(parent)])
          std::replace(in[at(successor)].begin(), in[at(successor)].end(), next, parent);
        in[at(next)].clear();
        out[at(next)].clear();
        joined[at(next)] = parent;
      } else {  // its line only merges with others now
        kept.end = NodeType::Junction;
      }
    }
  }
  // Renumber the nodes that stay, in creation order.
  std::vector<Index> id(n, kInvalidIndex);
  std::vector<ReebNode> nodes;
  for (std::size_t k = 0; k < n; ++k)
    if (joined[k] == kInvalidIndex) {
      id[k] = static_cast<Index>(nodes.size());
      nodes.push_back(std::move(graph.nodes[k]));
    }
  const auto final_id = [&](Index x) {
    while (joined[at(x)] != kInvalidIndex) x = joined[at(x)];
    return id[at(x)];
  };
  for (Index& node : graph.vertex_node) node = final_id(node);
  graph.edges.clear();
  for (std::size_t k = 0; k < n; ++k)
    if (joined[k] == kInvalidIndex)
      for (const Index successor : out[k]) graph.edges.push_back({id[k], id[at(successor)]});
  std::sort(graph.edges.begin(), graph.edges.end());
  graph.nodes = std::move(nodes);
  return graph;
}

}  // namespace reebkit

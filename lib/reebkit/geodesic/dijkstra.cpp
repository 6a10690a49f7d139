#include "reebkit/geodesic/dijkstra.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <string>

namespace reebkit {

DijkstraSolver::DijkstraSolver(const MeshGraph& graph) : graph_(graph) {
  const auto n = static_cast<std::size_t>(graph.num_vertices());
  field_.distance.assign(n, std::numeric_limits<double>::infinity());
  field_.nearest_source.assign(n, kInvalidIndex);
}

const DistanceField& DijkstraSolver::run(const std::vector<Index>& sources, const DijkstraOptions& options) {
  const Index n = graph_.num_vertices();
  double* dist = field_.distance.data();
  Index* nearest = field_.nearest_source.data();
  if (field_.distance.size() != static_cast<std::size_t>(n)) {  // released before
    field_.distance.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
    field_.nearest_source.assign(static_cast<std::size_t>(n), kInvalidIndex);
    dist = field_.distance.data();
    nearest = field_.nearest_source.data();
  } else {
    for (const Index v : touched_) {
      dist[v] = std::numeric_limits<double>::infinity();
      nearest[v] = kInvalidIndex;
    }
  }
  touched_.clear();
  settled_.clear();
  heap_.clear();
  field_.farthest = kInvalidIndex;
  field_.max_distance = 0.0;
  field_.reached = 0;

  const Index* labels = options.labels ? options.labels->data() : nullptr;
  if (labels && options.labels->size() != static_cast<std::size_t>(n))
    throw InvalidArgument("dijkstra: " + std::to_string(options.labels->size()) + " vertex labels for " +
                          std::to_string(n) + " vertices");
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const Index v = sources[s];
    if (v < 0 || v >= n)
      throw InvalidArgument("dijkstra: source vertex " + std::to_string(v) + " out of range [0, " +
                            std::to_string(n) + ")");
    if (labels && labels[v] != options.label)
      throw InvalidArgument("dijkstra: source vertex " + std::to_string(v) + " has label " +
                            std::to_string(labels[v]) + ", the search is restricted to label " +
                            std::to_string(options.label));
    if (nearest[v] != kInvalidIndex) continue;  // listed twice
    dist[v] = 0.0;
    nearest[v] = static_cast<Index>(s);
    touched_.push_back(v);
    heap_.push(0.0, v);
  }

  const Index* offset = graph_.offset.data();
  const Index* neighbor = graph_.neighbor.data();
  const double* length = graph_.length.data();
  while (!heap_.empty()) {
    const auto [d, v] = heap_.pop();
    if (d > dist[v]) continue;  // stale entry
    settled_.push_back(v);
    // The maximum by (distance, id), as sos_less orders vertices.
    if (field_.farthest == kInvalidIndex || d > field_.max_distance ||
        (d == field_.max_distance && v > field_.farthest)) {
      field_.max_distance = d;
      field_.farthest = v;
    }
    for (Index i = offset[v]; i < offset[v + 1]; ++i) {
      const Index w = neighbor[i];
      if (labels && labels[w] != options.label) continue;
      const double dw = d + length[i];
      if (dw < dist[w] && dw <= options.radius) {
        if (dist[w] == std::numeric_limits<double>::infinity()) touched_.push_back(w);
        dist[w] = dw;
        nearest[w] = nearest[v];
        heap_.push(dw, w);
      }
    }
  }
  field_.reached = static_cast<Index>(settled_.size());
  return field_;
}

DistanceField DijkstraSolver::release() {
  DistanceField out = std::move(field_);
  field_ = DistanceField{};
  touched_.clear();
  return out;
}

DistanceField dijkstra(const MeshGraph& graph, const std::vector<Index>& sources, const DijkstraOptions& options) {
  DijkstraSolver solver(graph);
  solver.run(sources, options);
  return solver.release();
}

DistanceField dijkstra(const MeshGraph& graph, Index source, const DijkstraOptions& options) {
  return dijkstra(graph, std::vector<Index>{source}, options);
}

}  // namespace reebkit

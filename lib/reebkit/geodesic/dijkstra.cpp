#include "reebkit/geodesic/dijkstra.h"

namespace reebkit {

const DistanceField& DijkstraSolver::run(const std::vector<Index>& sources, const DijkstraOptions& options) {
  start(sources, options, "dijkstra");
  const Index* labels = options.labels ? options.labels->data() : nullptr;
  const double* dist = field_.distance.data();
  const Index* nearest = field_.nearest_source.data();
  const Index* offset = graph_.offset.data();
  const Index* neighbor = graph_.neighbor.data();
  const double* length = graph_.length.data();
  while (!heap_.empty()) {
    const auto [d, v] = heap_.pop();
    if (d > dist[v]) continue;  // stale entry
    settle(v, d);
    for (Index i = offset[v]; i < offset[v + 1]; ++i) {
      const Index w = neighbor[i];
      if (labels && labels[w] != options.label) continue;
      const double dw = d + length[i];
      if (dw < dist[w] && dw <= options.radius) improve(w, dw, nearest[v]);
    }
  }
  return finish();
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

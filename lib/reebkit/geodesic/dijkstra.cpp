#include "reebkit/geodesic/dijkstra.h"

namespace reebkit {

const DistanceField& DijkstraSolver::run(const std::vector<Index>& sources, const DijkstraOptions& options) {
  const auto [labels, dist, nearest, offset, neighbor, length, bound] = start(sources, options, "dijkstra");
  while (!heap_.empty()) {
    const auto [d, v] = heap_.pop();
    if (d > dist[v]) continue;  // stale entry
    settle(v, d);
    for (Index i = offset[v]; i < offset[v + 1]; ++i) {
      const Index w = neighbor[i];
      if (labels && labels[w] != options.label) continue;
      const double dw = d + length[i];
      if (dw < dist[w] && within(dw, w, options.radius, bound)) improve(w, dw, nearest[v]);
    }
  }
  return finish();
}

DistanceField dijkstra(const MeshGraph& graph, const std::vector<Index>& sources, const DijkstraOptions& options) {
  return run_once<DijkstraSolver>(graph, sources, options);
}

DistanceField dijkstra(const MeshGraph& graph, Index source, const DijkstraOptions& options) {
  return run_once<DijkstraSolver>(graph, {source}, options);
}

}  // namespace reebkit

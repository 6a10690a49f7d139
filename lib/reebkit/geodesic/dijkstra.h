// Geodesic distances approximated by shortest paths on the mesh graph
// ("Moore-Dijkstra", Tierny et al. 2006, section 4.1.1).
#pragma once

#include "reebkit/geodesic/geodesic_solver.h"

#include <vector>

namespace reebkit {

/// The options of a Dijkstra run (radius, labels): those of every method.
using DijkstraOptions = GeodesicOptions;

/// Shortest-path distances from the nearest of `sources` (vertex ids) to
/// every vertex, with a radix heap (radix_heap.h). Deterministic: the same
/// inputs give the same result, nearest sources included (between sources at
/// exactly the same distance, the heap's order decides). O(E + 64 V).
DistanceField dijkstra(const MeshGraph& graph, const std::vector<Index>& sources, const DijkstraOptions& options = {});

/// Single-source convenience overload.
DistanceField dijkstra(const MeshGraph& graph, Index source, const DijkstraOptions& options = {});

/// The same search, for many runs on one graph (see GeodesicSolver).
class DijkstraSolver final : public GeodesicSolver {
 public:
  explicit DijkstraSolver(const MeshGraph& graph) : GeodesicSolver(graph) {}

  /// Runs from `sources`; the returned field stays valid until the next run.
  const DistanceField& run(const std::vector<Index>& sources, const DijkstraOptions& options = {}) override;
  Geodesic method() const override { return Geodesic::Dijkstra; }
};

}  // namespace reebkit

// Geodesic distances approximated by shortest paths on the mesh graph
// ("Moore-Dijkstra", Tierny et al. 2006, section 4.1.1).
#pragma once

#include "reebkit/geodesic/radix_heap.h"
#include "reebkit/mesh/mesh_graph.h"

#include <limits>
#include <utility>
#include <vector>

namespace reebkit {

struct DijkstraOptions {
  /// Vertices farther than this from every source are left unreached
  /// (distance +inf): the search stops at the radius. +inf = whole mesh.
  double radius = std::numeric_limits<double>::infinity();
  /// Restricts the search to the vertices v with (*labels)[v] == label (one
  /// region of a segmentation, e.g. ReebGraph::vertex_node): paths never
  /// leave them and the others stay unreached. nullptr (default): every
  /// vertex. Holds #V labels; every source must carry `label`.
  const std::vector<Index>* labels = nullptr;
  Index label = 0;
};

/// Result of a (multi-source) Dijkstra pass.
struct DistanceField {
  std::vector<double> distance;       ///< #V, +inf where unreached
  std::vector<Index> nearest_source;  ///< #V, index into the source list (not a vertex id); -1 where unreached
  Index farthest = kInvalidIndex;     ///< reached vertex of largest (distance, id): ties go to the largest id, as in sos_less
  double max_distance = 0.0;          ///< distance[farthest]
  Index reached = 0;                  ///< number of vertices within the radius
};

/// Shortest-path distances from the nearest of `sources` (vertex ids) to
/// every vertex, with a radix heap (radix_heap.h). Deterministic: the same
/// inputs give the same result, nearest sources included (between sources at
/// exactly the same distance, the heap's order decides). O(E + 64 V).
DistanceField dijkstra(const MeshGraph& graph, const std::vector<Index>& sources,
                       const DijkstraOptions& options = {});

/// Single-source convenience overload.
DistanceField dijkstra(const MeshGraph& graph, Index source, const DijkstraOptions& options = {});

/// The same search, for many runs on one graph: buffers are allocated once
/// and a run resets only the vertices the previous run reached, so a run with
/// a small radius costs time proportional to the vertices it reaches.
class DijkstraSolver {
 public:
  explicit DijkstraSolver(const MeshGraph& graph);

  /// Runs from `sources`; the returned field stays valid until the next run.
  const DistanceField& run(const std::vector<Index>& sources, const DijkstraOptions& options = {});

  /// Vertices reached by the last run, in the order they were settled.
  const std::vector<Index>& settled() const { return settled_; }

  /// Moves the last result out (the solver is left ready for a fresh run).
  DistanceField release();

 private:
  const MeshGraph& graph_;
  DistanceField field_;
  std::vector<Index> settled_;
  std::vector<Index> touched_;  // vertices whose distance is finite
  RadixHeap heap_;
};

}  // namespace reebkit

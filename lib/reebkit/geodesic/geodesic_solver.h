// What every geodesic distance method of reebkit shares: the options of a
// run (multi-source, radius, restriction to one label), the distance field it
// returns, and a solver base class that owns the buffers reused from run to
// run, the front's priority queue (a radix heap) and the bookkeeping of the
// settled vertices. The methods (dijkstra.h, fast_marching.h) differ only in
// how a settled vertex updates its neighbours.
#pragma once

#include "reebkit/geodesic/radix_heap.h"
#include "reebkit/mesh/mesh_graph.h"

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace reebkit {

/// How geodesic distances are approximated.
enum class Geodesic {
  /// Shortest paths along mesh edges (dijkstra.h): exact on the edge graph,
  /// but paths zig-zag, so distances overestimate the surface's by up to 8 %
  /// on a regular grid, by an amount that depends on the sampling.
  Dijkstra,
  /// Kimmel-Sethian fast marching across the triangles (fast_marching.h):
  /// converges to the surface's geodesic distance as the mesh is refined.
  FastMarching,
};

/// "dijkstra" or "fmm": the names of the command-line option --geodesic.
const char* geodesic_name(Geodesic method);
/// Inverse of geodesic_name; throws InvalidArgument naming the accepted values.
Geodesic parse_geodesic(const std::string& name);

struct GeodesicOptions {
  /// Vertices farther than this from every source are left unreached
  /// (distance +inf): the search stops at the radius. +inf = whole mesh.
  double radius = std::numeric_limits<double>::infinity();
  /// Restricts the search to the vertices v with (*labels)[v] == label (one
  /// region of a segmentation, e.g. ReebGraph::vertex_node): paths never
  /// leave them and the others stay unreached. nullptr (default): every
  /// vertex. Holds #V labels; every source must carry `label`.
  const std::vector<Index>* labels = nullptr;
  Index label = 0;
  /// The sources are separate points, and a vertex's distance is that to
  /// the nearest of them (eq. 8's nearest feature point): fast marching then
  /// never combines two sources' fronts in one triangle, which would cut the
  /// corner between them. false (default): the sources sample one front (a
  /// curve, a region), whose neighbouring samples' fronts combine into one
  /// (a plane wave from a line of sources). Dijkstra is the same either way.
  bool separate_sources = false;
  /// Distances already known from other sources (#V): a vertex is reached
  /// only where the sources are strictly nearer than bound[v], so the run
  /// covers their Voronoi cells against the sources the bound measured (f_q
  /// with the fields of the diameter ends, quotient_function.h); a source
  /// whose bound is 0 (one the bound measured) is not seeded. Holds #V
  /// distances. nullptr (default): no bound.
  const std::vector<double>* bound = nullptr;
};

/// Result of a (multi-source) geodesic pass.
struct DistanceField {
  std::vector<double> distance;       ///< #V, +inf where unreached
  std::vector<Index> nearest_source;  ///< #V, index into the source list (not a vertex id); -1 where unreached
  Index farthest =
      kInvalidIndex;          ///< reached vertex of largest (distance, id): ties go to the largest id, as in sos_less
  double max_distance = 0.0;  ///< distance[farthest]
  Index reached = 0;          ///< number of vertices within the radius
};

/// A solver for many runs on one graph: buffers are allocated once and a run
/// resets only the vertices the previous run reached, so a run with a small
/// radius costs time proportional to the vertices it reaches.
class GeodesicSolver {
 public:
  explicit GeodesicSolver(const MeshGraph& graph);
  virtual ~GeodesicSolver() = default;
  GeodesicSolver(const GeodesicSolver&) = delete;
  GeodesicSolver& operator=(const GeodesicSolver&) = delete;

  /// Distances from the nearest of `sources` (vertex ids, each within
  /// `options.label` when restricted); the returned field stays valid until
  /// the next run. Throws InvalidArgument for a source out of range or off
  /// the label, or labels not of size #V.
  virtual const DistanceField& run(const std::vector<Index>& sources, const GeodesicOptions& options = {}) = 0;

  /// The method this solver implements.
  virtual Geodesic method() const = 0;

  /// The graph the solver runs on.
  const MeshGraph& graph() const { return graph_; }

  /// Vertices reached by the last run, in the order they were settled
  /// (increasing distance).
  const std::vector<Index>& settled() const { return settled_; }

  /// Moves the last result out (the solver is left ready for a fresh run).
  DistanceField release();

 protected:
  /// The arrays a run reads in its loop, as plain pointers (no aliasing
  /// with the vectors' bookkeeping): labels is nullptr when unrestricted.
  struct RunArrays {
    const Index* labels;
    const double* dist;
    const Index* nearest;
    const Index* offset;
    const Index* neighbor;
    const double* length;
    const double* bound;  ///< nullptr without GeodesicOptions::bound
  };

  /// Whether distance `dw` at vertex `w` is within the run's reach: the
  /// radius, and below the bound where there is one.
  static bool within(double dw, Index w, double radius, const double* bound) {
    return dw <= radius && (bound == nullptr || dw < bound[w]);
  }

  /// Resets what the previous run reached, checks the options and the
  /// sources (`who` names the method in error messages) and puts every
  /// source at distance 0 on the heap.
  RunArrays start(const std::vector<Index>& sources, const GeodesicOptions& options, const char* who);

  /// Records `v` settled at distance `d`: the settled list, and the farthest
  /// vertex by (distance, id), as sos_less orders vertices.
  void settle(Index v, double d) {
    settled_.push_back(v);
    if (field_.farthest == kInvalidIndex || d > field_.max_distance ||
        (d == field_.max_distance && v > field_.farthest)) {
      field_.max_distance = d;
      field_.farthest = v;
    }
  }

  /// Sets `w` to distance `dw` reached from source `source` and queues it.
  void improve(Index w, double dw, Index source) {
    double& dist = field_.distance[static_cast<std::size_t>(w)];
    if (dist == std::numeric_limits<double>::infinity()) touched_.push_back(w);
    dist = dw;
    field_.nearest_source[static_cast<std::size_t>(w)] = source;
    heap_.push(dw, w);
  }

  /// Completes the field once the heap is empty.
  const DistanceField& finish() {
    field_.reached = static_cast<Index>(settled_.size());
    return field_;
  }

  const MeshGraph& graph_;
  DistanceField field_;
  std::vector<Index> settled_;
  RadixHeap heap_;

 private:
  std::vector<Index> touched_;  // vertices whose distance is finite
};

/// One run of a solver of type Solver (DijkstraSolver, FastMarchingSolver):
/// the one-shot functions dijkstra() and fast_marching().
template <class Solver>
DistanceField run_once(const MeshGraph& graph, const std::vector<Index>& sources, const GeodesicOptions& options) {
  Solver solver(graph);
  solver.run(sources, options);
  return solver.release();
}

/// A solver of the given method for `graph` (which must outlive it).
std::unique_ptr<GeodesicSolver> make_geodesic_solver(const MeshGraph& graph, Geodesic method);

/// One run of `method` from `sources`.
DistanceField geodesic_distances(const MeshGraph& graph, const std::vector<Index>& sources, Geodesic method,
                                 const GeodesicOptions& options = {});

}  // namespace reebkit

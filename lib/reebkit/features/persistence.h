// Topological persistence of the local extrema of a scalar function on a mesh
// graph (0-dimensional persistent homology of the superlevel and sublevel
// sets; Edelsbrunner, Letscher and Zomorodian, "Topological persistence and
// simplification", Discrete Comput. Geom. 28, 2002). A maximum is born when
// the sweep from the top reaches it and dies where its superlevel-set
// component merges into one holding a higher maximum (the elder rule); its
// persistence, f(max) - f(death vertex), is how far f must be lowered around
// it before it stops being a maximum. Minima likewise, sweeping upwards.
// Only vertices and edges matter for connected components, so the pairs are
// those of the lower-star (upper-star) filtration of the triangulation.
#pragma once

#include "reebkit/mesh/mesh_graph.h"

#include <limits>
#include <vector>

namespace reebkit {

/// One local extremum and where it dies.
struct PersistencePair {
  Index extremum = kInvalidIndex;  ///< the local maximum (minimum)
  /// The vertex where its component merges into one with a more extreme
  /// extremum: a saddle (classify_vertex), which may kill several extrema
  /// (at most L+ - 1 maxima, L- - 1 minima). kInvalidIndex for the most
  /// extreme vertex of each connected component, which never dies.
  Index saddle = kInvalidIndex;
  /// |f(extremum) - f(saddle)| >= 0; +infinity for a component's global one.
  double persistence = std::numeric_limits<double>::infinity();
};

struct ExtremaPersistence {
  /// Every local maximum (no neighbour above it), by increasing vertex id.
  std::vector<PersistencePair> maxima;
  /// Every local minimum (no neighbour below it), by increasing vertex id.
  std::vector<PersistencePair> minima;
};

/// Persistence of every local maximum and minimum of f on `graph`. f is
/// compared as sos_less does (value, then vertex id), so the extrema are
/// exactly those of local_extrema, and the elder of two merging components is
/// the one whose extremum comes later (earlier) in that order. O(n log n):
/// one sort of the vertices, then union-find over the edges in each direction.
/// \pre f.size() == graph.num_vertices(); throws InvalidArgument otherwise.
ExtremaPersistence extrema_persistence(const MeshGraph& graph, const std::vector<double>& f);

/// The local minima and maxima of f with persistence >= min_persistence (in
/// f's units), vertex ids increasing: the extrema of extrema_persistence
/// that pass, found without sorting the mesh (a best-first search from each
/// extremum through the vertices within min_persistence of it, stopped at the
/// first vertex beyond it). With min_persistence = 0 this is
/// local_extrema(graph, f).
/// \pre min_persistence >= 0 (not NaN) and f.size() == graph.num_vertices();
///      throws InvalidArgument otherwise.
std::vector<Index> persistent_extrema(const MeshGraph& graph, const std::vector<double>& f, double min_persistence);

}  // namespace reebkit

// Discrete critical points of a scalar function on a triangulated surface,
// classified from the vertex link (Tierny et al. 2006, section 2, figure 3):
// L+ / L- = number of connected sets of link vertices above / below v.
#pragma once

#include "reebkit/mesh/mesh_graph.h"

#include <vector>

namespace reebkit {

/// Symbolic perturbation ("simulation of simplicity"): f is compared by
/// (value, vertex id), so no two vertices are ever equal and every result
/// below is deterministic.
inline bool sos_less(const std::vector<double>& f, Index a, Index b) {
  return f[static_cast<std::size_t>(a)] < f[static_cast<std::size_t>(b)] ||
         (f[static_cast<std::size_t>(a)] == f[static_cast<std::size_t>(b)] && a < b);
}

/// True when no neighbour of v lies above it (sos order): L+ = 0.
inline bool is_local_maximum(const MeshGraph& graph, const std::vector<double>& f, Index v) {
  for (Index i = graph.offset[static_cast<std::size_t>(v)]; i < graph.offset[static_cast<std::size_t>(v) + 1]; ++i)
    if (sos_less(f, v, graph.neighbor[static_cast<std::size_t>(i)])) return false;
  return true;
}

enum class CriticalType : unsigned char { Regular, Minimum, Maximum, Saddle };

struct LinkCount {
  int upper = 0;  ///< L+: connected sets of link vertices above v
  int lower = 0;  ///< L-: connected sets of link vertices below v
};

/// L+ and L- of vertex v, counted along its one-ring (the ring order and
/// link_next flags of MeshGraph). On a boundary (Open ring) the link is a path.
LinkCount count_link_components(const MeshGraph& graph, const std::vector<double>& f, Index v);

/// Minimum: L- = 0; maximum: L+ = 0; saddle: L+ >= 2 or L- >= 2 on an
/// interior vertex (L+ + L- >= 3 on a boundary one); regular otherwise.
CriticalType classify_vertex(const MeshGraph& graph, const std::vector<double>& f, Index v);

/// Every local minimum and maximum of f (vertex ids, increasing).
std::vector<Index> local_extrema(const MeshGraph& graph, const std::vector<double>& f);

}  // namespace reebkit

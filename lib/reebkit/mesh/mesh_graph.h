// The mesh as a weighted graph: CSR adjacency with Euclidean edge lengths,
// each vertex's one-ring stored in cyclic order so that critical points can be
// classified from their link (Tierny et al. 2006, section 2, figure 3).
#pragma once

#include "reebkit/core/mesh.h"

#include <cstdint>
#include <vector>

namespace reebkit {

/// Shape of a vertex's link (the polygon of its neighbours).
enum class RingKind : std::uint8_t {
  Closed,    ///< interior manifold vertex: the ring is one cycle
  Open,      ///< boundary manifold vertex: the ring is one path
  Irregular  ///< non-manifold vertex: several fans (paths), concatenated
};

/// CSR adjacency of a triangle mesh. The neighbours of v are
/// neighbor[offset[v] .. offset[v+1]), ordered around v so that consecutive
/// neighbours i, i+1 form a triangle with v whenever link_next[i] is 1; the
/// last neighbour links back to the first exactly for Closed rings. For a
/// consistently oriented mesh the order is counter-clockwise.
struct MeshGraph {
  std::vector<Index> offset;            ///< #V + 1
  std::vector<Index> neighbor;          ///< 2 #E half-edges
  std::vector<double> length;           ///< |x_v - x_neighbor|, parallel to neighbor
  std::vector<std::uint8_t> link_next;  ///< 1 if slot i and its successor share a triangle with v
  std::vector<RingKind> ring;           ///< #V

  Index num_vertices() const { return static_cast<Index>(offset.size()) - 1; }
  Index num_half_edges() const { return static_cast<Index>(neighbor.size()); }
  Index degree(Index v) const { return offset[v + 1] - offset[v]; }
};

/// Builds the graph of `mesh` in O(#F) (plus the squares of vertex degrees).
/// Works for any cleaned mesh: boundaries give Open rings, non-manifold
/// vertices Irregular ones, and inconsistent face orientation is tolerated.
MeshGraph build_mesh_graph(const Mesh& mesh);

}  // namespace reebkit

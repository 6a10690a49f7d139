// Geodesic distances by fast marching on the triangles of the mesh
// (R. Kimmel, J. A. Sethian, "Computing geodesic paths on manifolds", PNAS
// 1998): Dijkstra's front, but a vertex is reached across a triangle by a
// planar wavefront through its two settled corners, not only along edges.
// Shortest edge paths zig-zag (up to 8 % too long on a regular grid, with an
// error pattern that follows the sampling); fast marching converges to the
// surface's geodesic distance as the mesh is refined.
#pragma once

#include "reebkit/geodesic/geodesic_solver.h"

#include <cstdint>
#include <vector>

namespace reebkit {

/// Fast marching for many runs on one graph (see GeodesicSolver and
/// fast_marching below): the triangles' third sides and the splits of the
/// obtuse corners are computed once, in the constructor.
class FastMarchingSolver final : public GeodesicSolver {
 public:
  /// Most triangles unfolded to split one obtuse corner.
  static constexpr int kMaxUnfoldings = 16;

  explicit FastMarchingSolver(const MeshGraph& graph);

  /// Runs from `sources`; the returned field stays valid until the next run.
  const DistanceField& run(const std::vector<Index>& sources, const GeodesicOptions& options = {}) override;
  Geodesic method() const override { return Geodesic::FastMarching; }

  /// Obtuse corners split by a virtual vertex (a statistic of the mesh).
  Index split_corners() const { return static_cast<Index>(virtual_.size() / 4); }

 private:
  /// A virtual triangle (target, trigger, other) of a split obtuse corner,
  /// stored at its corner `trigger`: when trigger is settled and `other`
  /// already is, `target` gets the triangle update.
  struct VirtualTriangle {
    Index target;
    Index other;
    /// The real vertex of the obtuse triangle that this virtual one leaves
    /// out, when the unfolded strip is that single triangle; -1 when the
    /// strip is longer (then skipped by label-restricted runs).
    Index strip_vertex;
    double to_target;        ///< |trigger target|
    double other_to_target;  ///< |other target| (in the unfolded plane)
    double to_other;         ///< |trigger other| (in the unfolded plane)
  };

  /// Parallel to graph.neighbor: for a slot i with link_next[i], the length
  /// of the link edge from neighbor[i] to the next neighbour of the ring
  /// (the third side of the triangle (v, neighbor[i], next)); NaN otherwise.
  std::vector<double> link_length_;
  /// CSR by trigger vertex: virtual_[virtual_offset_[v] .. virtual_offset_[v + 1]).
  std::vector<Index> virtual_offset_;
  std::vector<VirtualTriangle> virtual_;
  std::vector<std::uint8_t> alive_;  // settled in the current run
};

/// Fast-marching distances from the nearest of `sources` (vertex ids) to
/// every vertex. Intrinsic: only the edge lengths and the triangles of the
/// graph's one-rings are used, so the result depends on the surface's metric,
/// not on its placement in space.
///
/// Vertex w, when a neighbour v is settled, takes the smallest of the edge
/// update T(v) + |vw| (Dijkstra's) and, for each triangle (w, v, u) whose
/// corner u is settled too, the Kimmel-Sethian update: the value at w of the
/// plane wave T(x) = t + g.x with |g| = 1 through T(v) and T(u), used only
/// when it is causal (the wave reaches w from inside the triangle, -g within
/// the angle at w, and t >= T(v), T(u)). An obtuse angle at w can hide the
/// wave's direction from every triangle with two settled corners, so each
/// obtuse corner (above 90.6 degrees) is split as Kimmel and Sethian do: the
/// triangles beyond the opposite side are unfolded into the plane of
/// (w, v, u) until one brings a vertex y into the section of directions at
/// less than right angles to both wv and wu (by a cosine of 1e-9 at least,
/// so that similar copies of a mesh pick the same y); the virtual
/// triangles (w, v, y) and (w, y, u), acute at w, then update w as real ones
/// do when their corners are settled. A corner whose
/// unfolding meets a boundary, or needs more than kMaxUnfoldings triangles,
/// keeps only its real triangle; degenerate triangles give edge updates only.
///
/// Distances never exceed Dijkstra's on the same graph (edge updates are
/// always candidates) and converge to the surface's geodesic distance as
/// the edge length h goes to 0 (error about O(h), largest near the sources,
/// where the planar wave approximates a circular front). nearest_source is
/// the source of the corner nearer to where the wave crosses the triangle.
/// With labels, a virtual triangle is used only when its whole unfolded
/// strip is one triangle whose corners carry the label. Deterministic;
/// O(E + 64 V) per run, as Dijkstra, after a precomputation in O(E * degree).
inline DistanceField fast_marching(const MeshGraph& graph, const std::vector<Index>& sources,
                                   const GeodesicOptions& options = {}) {
  return run_once<FastMarchingSolver>(graph, sources, options);
}

/// Single-source convenience overload.
inline DistanceField fast_marching(const MeshGraph& graph, Index source, const GeodesicOptions& options = {}) {
  return run_once<FastMarchingSolver>(graph, {source}, options);
}

}  // namespace reebkit

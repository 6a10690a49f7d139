// Remeshing: a new triangulation of the same surface that shares no vertex
// with the original, as an independent scan or a remodelled copy of a shape
// would have. Tierny et al. 2006 (section 5.3) claim robustness to "mesh
// sampling"; a subdivision keeps every original vertex, a remeshing does not.
#pragma once

#include "reebkit/mesh/surface_correspondence.h"

#include <cstdint>

namespace reebkit {

struct RemeshOptions {
  /// Vertices of the result (met within DecimationOptions::tolerance, see
  /// decimate_mesh). 0: from target_edge_length.
  Index target_vertices = 0;
  /// Mean edge length wanted, used when target_vertices is 0: an equilateral
  /// mesh of the surface's area A has about 2 A / (sqrt(3) L^2) vertices.
  double target_edge_length = 0.0;
  /// Rounds of tangential smoothing (each vertex moves by smoothing_step
  /// towards the centroid of its neighbours within its tangent plane, then
  /// back onto the original surface): they even out the edge lengths and move
  /// the vertices off the original ones. Few and damped, because each round
  /// also pulls the vertices near a thin tip down the tip.
  int smoothing_iterations = 1;
  double smoothing_step = 0.5;  ///< in [0, 1]
  std::uint64_t seed = 1;       ///< the jitter of the dense sampling; same seed, same mesh
  /// No triangle of the result has an area at or below this fraction of its
  /// mean triangle area (degenerate_triangles.h), so no vertex has a star
  /// without area: decimation, smoothing and projection can leave slivers
  /// and needles of zero area, which are flipped or collapsed away. 1e-6: far above a triangle of zero
  /// area to rounding (1e-12 of the largest, see laplace_beltrami.h), far
  /// below the small but well-shaped triangles that quadric collapse keeps
  /// on fine detail (an ear, a finger), which no flip or collapse could
  /// remove without folding the surface.
  double min_triangle_area = 1e-6;
};

/// A new triangulation of the surface of `mesh` with about target vertices:
/// the surface sampled densely (jittered 1-to-4 subdivisions, resample_mesh,
/// until it has at least 4 times the target), decimated by quadric edge
/// collapse to the target (decimate_mesh), its vertices then smoothed
/// tangentially and projected back onto the original surface
/// (SurfaceLocator). A vertex still at an original vertex's position (a
/// projection onto a convex corner) is moved into its closest original
/// triangle by 5 % towards each other corner, so no vertex is shared.
/// Last, the triangles that decimation, smoothing, projection or that nudge
/// left degenerate are flipped or collapsed away
/// (repair_degenerate_triangles with min_triangle_area; no vertex moves).
/// Every vertex lies on the original surface (to rounding); the genus is kept
/// unless the target is too small for the shape. original_vertex: the nearest
/// original vertex on the surface.
/// Throws InvalidArgument naming mesh.source for a target below 4 vertices,
/// neither target given, or options out of range. Where a degenerate
/// triangle is left that no flip or collapse removes (rare; it depends on
/// the dense sampling), the remeshing is made again from up to three other
/// dense samplings drawn from the seed (the same seed, the same mesh; the
/// first try is the seed's own); InvalidMeshError naming mesh.source, the
/// seed and each try's problem where all four fail.
MeshVariant remesh(const Mesh& mesh, const RemeshOptions& options);

}  // namespace reebkit

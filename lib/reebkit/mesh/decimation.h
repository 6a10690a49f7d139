// Decimation: the same shape with fewer vertices, by quadric edge collapse
// (Garland-Heckbert) from meshoptimizer (libmeshoptimizer-dev, MIT). The
// sampling experiments of Tierny et al. 2006 (section 5.3: robustness to
// "mesh sampling") need meshes of one surface at several resolutions.
#pragma once

#include "reebkit/mesh/surface_correspondence.h"

namespace reebkit {

struct DecimationOptions {
  /// The share of the vertices to keep, in (0, 1]. 1 returns the mesh unchanged.
  double vertex_ratio = 0.5;
  /// The target may be missed by this share of the target count: the
  /// collapses are steered by triangle count, then corrected.
  double tolerance = 0.02;
  /// No triangle of the result has an area at or below this fraction of its
  /// mean triangle area (degenerate_triangles.h), so no vertex has a star
  /// without area: the collapses can fold slivers and needles of zero area,
  /// which are flipped or collapsed away. 1e-6: far above a triangle of zero
  /// area to rounding (1e-12 of the largest, see laplace_beltrami.h), far
  /// below the small but well-shaped triangles that quadric collapse keeps
  /// on fine detail (an ear, a finger), which no flip or collapse could
  /// remove without folding the surface.
  double min_triangle_area = 1e-6;
  /// A try that keeps too many vertices is decimated further by the next
  /// try (with the quadrics of that coarser copy), instead of the next one
  /// starting again from the whole mesh: each further try then costs what
  /// the copy's size does. Regions cut with a border miss their target on
  /// the first try nearly always, and always on the side of too many
  /// vertices (the collapses spare the border). false: every try from the
  /// whole mesh (the robustness experiments' variants).
  bool refine_last_try = false;
};

/// `mesh` decimated by quadric edge collapse to about vertex_ratio x #V
/// vertices (within the tolerance unless the collapses stop first: a collapse
/// that would flip a triangle is refused, so a very small target on a coarse
/// mesh may not be reached; two triangles folded onto each other by a
/// collapse, a fin on one edge, are both removed), then its degenerate
/// triangles repaired (repair_degenerate_triangles with min_triangle_area),
/// which may remove a few more vertices. The kept vertices keep their
/// positions, so original_vertex[v] is the vertex of `mesh` that v is.
/// Throws InvalidArgument naming mesh.source for a ratio outside (0, 1] or a
/// min_triangle_area outside [0, 1), InvalidMeshError naming mesh.source and
/// the ratio when a degenerate triangle cannot be repaired.
MeshVariant decimate_mesh(const Mesh& mesh, const DecimationOptions& options = {});

}  // namespace reebkit

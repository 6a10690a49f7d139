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
};

/// `mesh` decimated by quadric edge collapse to about vertex_ratio x #V
/// vertices (within the tolerance unless the collapses stop first: a collapse
/// that would flip a triangle is refused, so a very small target on a coarse
/// mesh may not be reached; two triangles folded onto each other by a
/// collapse, a fin on one edge, are both removed). The kept vertices keep
/// their positions, so original_vertex[v] is the vertex of `mesh` that v is.
/// Throws InvalidArgument naming mesh.source for a ratio outside (0, 1].
MeshVariant decimate_mesh(const Mesh& mesh, const DecimationOptions& options = {});

}  // namespace reebkit

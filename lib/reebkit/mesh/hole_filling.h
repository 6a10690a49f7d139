// Closing the small holes of a mesh: scanning and modelling leave small
// boundary loops (eyes, mouths, hoof soles of the TOSCA meshes) that the
// level-line propagation of the Reeb graph (Tierny et al. 2006, section 4.2,
// Definition 6) would see as places where a level line ends or splits. The
// paper assumes a closed surface; filling the small loops restores that
// without touching the rest of the mesh.
#pragma once

#include "reebkit/core/mesh.h"

namespace reebkit {

struct HoleFillingOptions {
  /// A boundary loop is filled when its length (sum of its edge lengths) is at
  /// most this fraction of sqrt(surface area) of the loop's connected
  /// component: a scale that pose changes (isometries) and similarity
  /// transforms leave unchanged (the lengths of the TOSCA holes, and why
  /// this default: results/tosca_graphs.md). 0 fills nothing, infinity
  /// fills every loop.
  double max_loop_length = 0.2;
};

/// `mesh` with each small boundary loop (see HoleFillingOptions) closed by a
/// fan of triangles around one new vertex at the mean of the loop's vertices,
/// oriented like the triangles along the loop.
/// The original vertices keep their index, position and source_vertex, and
/// the original triangles come first in their order; the new vertices follow
/// the original ones (one per filled loop) with source_vertex = kInvalidIndex,
/// so source_vertex is filled in (identity for the originals) whenever a loop
/// is filled. Whoever reports results in file numbering must leave those
/// vertices out (Mesh::source_index returns kInvalidIndex for them).
/// Loops are the chains of boundary half-edges (edges of one triangle), in
/// triangle direction. Two holes touching at a vertex may be traced as one
/// loop through it twice (its fan then makes a non-manifold edge). Chains
/// that cannot be closed (inconsistently oriented triangles along the
/// boundary) are left open. O(F log F).
/// \pre options.max_loop_length >= 0 (throws InvalidArgument otherwise);
///      triangle indices in [0, #V).
Mesh fill_holes(const Mesh& mesh, const HoleFillingOptions& options = {});

/// Number of vertices of `mesh` that are not added by fill_holes (they come
/// first): per-vertex results for the input surface are their first entries.
Index original_vertex_count(const Mesh& mesh);

/// `mesh` without what fill_holes added: its first original_vertex_count(mesh)
/// vertices and the triangles among them, in their order. The surface that
/// outputs show and number as in the file.
Mesh original_surface(const Mesh& mesh);

}  // namespace reebkit

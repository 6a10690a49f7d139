// Degenerate triangles: slivers and needles of (nearly) zero area, which a
// generated mesh (decimation, remeshing) must not hold. Such a triangle spans
// no surface, its angles and cotangents are undefined, and a vertex whose
// star is made of them has no area: a robustness figure measured on such a
// variant would partly measure the defect, not the perturbation (Tierny et
// al. 2006, section 5.3, perturb the sampling of a surface, not its validity).
//
// The repair changes the connectivity only, never a position: an edge flip
// (a sliver, whose corner lies near its opposite edge, becomes two fat
// triangles) or an edge collapse onto one of its endpoints (a needle, whose
// edge is very short, disappears). So every vertex stays where it was (on the
// original surface, off the original vertices), and the collapses keep the
// topology (the link condition: no genus change, no non-manifold edge).
#pragma once

#include "reebkit/core/mesh.h"

#include <vector>

namespace reebkit {

/// Triangles of `mesh` whose area is not above min_area_fraction x the mean
/// triangle area (with 0: the triangles of zero area), in increasing order.
std::vector<Index> degenerate_triangles(const Mesh& mesh, double min_area_fraction);

struct TriangleRepair {
  Mesh mesh;  ///< the repaired mesh (source and source_vertex kept per vertex)
  /// #V of `mesh`: the vertex of the input that vertex v is (the collapsed
  /// vertices are gone, the others keep their order).
  std::vector<Index> input_vertex;
  Index flips = 0;
  Index collapses = 0;
  Index pockets = 0;  ///< closed tetrahedra removed (see repair_degenerate_triangles)
  /// Degenerate triangles still there (see degenerate_triangles): none
  /// unless no flip or collapse of theirs is allowed.
  Index remaining = 0;
};

/// `mesh` with its degenerate triangles (degenerate_triangles with
/// min_area_fraction) flipped or collapsed away. A degenerate triangle of a
/// closed tetrahedron that hangs on the rest of the mesh (a vertex with
/// three neighbours joined by a fourth triangle: a pocket that quadric edge
/// collapse folded onto a non-manifold edge) goes with the tetrahedron and
/// the vertices left without triangles. Else the allowed operation whose new
/// triangles have the largest smallest area: a flip of
/// an interior edge when the new edge is not already there, no new triangle
/// is degenerate and none turns against the triangles it replaces; else the
/// collapse of an edge onto one endpoint when the link condition holds, no
/// vertex is left with fewer than 3 neighbours, a border vertex moves only
/// along the border and no remaining triangle turns over or becomes
/// degenerate (one that was may stay so: a cluster of small triangles, or a
/// fan of flat ones on one line, goes by successive operations). Each
/// operation removes at least one degenerate triangle. A mesh without
/// degenerate triangles comes back unchanged.
TriangleRepair repair_degenerate_triangles(const Mesh& mesh, double min_area_fraction);

}  // namespace reebkit

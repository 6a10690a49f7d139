// From a polygon soup as read from a file to clean triangle meshes:
// triangulate, drop what no later step can use, split into connected
// components, and report every change and every topological oddity.
#pragma once

#include "reebkit/core/mesh.h"
#include "reebkit/core/types.h"

#include <string>
#include <vector>

namespace reebkit {

/// Options of clean_mesh.
struct CleanupOptions {
  /// false: keep only the largest component (by surface area) and warn about the rest.
  bool keep_all_components = false;
  /// Weld vertices with exactly equal coordinates first (off by default: it
  /// can make a closed mesh non-manifold, e.g. where two sheets touch).
  bool merge_coincident_vertices = false;
};

/// What clean_mesh found and changed. Face counts are file polygons unless
/// they say triangles; the topology counts describe all cleaned triangles,
/// before components are dropped.
struct CleanupReport {
  Index input_vertices = 0;
  Index input_polygons = 0;
  Index polygons_triangulated = 0;          ///< usable polygons with more than 3 vertices
  Index triangles_created = 0;              ///< triangles made from those polygons (n - 2 each)
  Index degenerate_faces_dropped = 0;       ///< polygons with < 3 distinct vertices or a repeated vertex
  Index duplicate_faces_dropped = 0;        ///< triangles on the vertex set of an earlier one (either orientation)
  Index unreferenced_vertices_dropped = 0;  ///< vertices no kept triangle uses (merged ones not counted)
  Index coincident_vertices_merged = 0;     ///< vertices welded onto an earlier vertex at the same position
  Index boundary_edges = 0;
  Index boundary_loops = 0;
  Index non_manifold_edges = 0;
  Index non_manifold_vertices = 0;
  Index components = 0;
  Index components_dropped = 0;
  /// One line per dropped face kind, non-manifold feature and dropped
  /// components; each starts with "<source>: ".
  std::vector<std::string> warnings;
};

/// The result of clean_mesh.
struct CleanedMesh {
  /// Connected components, largest surface area first (ties: more triangles,
  /// then smaller source vertex id); only the largest unless keep_all_components.
  /// Each has source_vertex filled (vertex -> index in the soup), vertices in
  /// increasing source order and triangles in file order.
  std::vector<Mesh> components;
  CleanupReport report;
};

/// Cleans `soup`:
/// - a non-finite coordinate, a vertex index outside the soup, no vertices,
///   no polygons, no usable triangle, or triangles of zero total area (every
///   one flat) throw InvalidMeshError naming soup.source and the problem;
/// - (optional) coincident vertices are welded;
/// - consecutive repeats in a polygon are collapsed; a polygon left with fewer
///   than 3 vertices or with a repeated vertex is dropped as degenerate;
/// - polygons are triangulated by ear clipping in their best-fit plane (a
///   strictly convex polygon gives a fan), n - 2 triangles for n vertices,
///   keeping the polygon's orientation and avoiding flat triangles at corners
///   that lie on a straight edge;
/// - duplicate triangles (same vertex set) are dropped, the first kept;
/// - unreferenced vertices are dropped;
/// - boundaries are kept; non-manifold edges and vertices are kept and warned about.
/// O((V + F) log(V + F)).
CleanedMesh clean_mesh(const PolygonSoup& soup, const CleanupOptions& options = {});

/// The same, taking the soup's vertex array into the mesh instead of copying
/// it (load_mesh: the soup of a file read for this alone).
CleanedMesh clean_mesh(PolygonSoup&& soup, const CleanupOptions& options = {});

}  // namespace reebkit

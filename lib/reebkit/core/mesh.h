// Mesh containers: the polygon soup a reader returns, and the cleaned
// triangle mesh every later pipeline step works on.
#pragma once

#include "reebkit/core/types.h"

#include <initializer_list>
#include <string>
#include <vector>

namespace reebkit {

/// What a file reader returns: vertices and polygons exactly as stored in the
/// file (0-based indices, no validation beyond index range), polygons in CSR
/// form. Polygon p has vertices face_vertex[face_offset[p] .. face_offset[p+1]).
struct PolygonSoup {
  Points vertices;                    ///< #V x 3
  std::vector<Index> face_offset{0};  ///< #P + 1, starts with 0
  std::vector<Index> face_vertex;     ///< concatenated polygon vertex indices
  /// Optional per-vertex RGB colors in [0,1] (#V x 3) when the file had them, else empty.
  Points vertex_colors;
  std::string source;  ///< file the soup came from ("" = built in memory)

  Index num_vertices() const { return static_cast<Index>(vertices.rows()); }
  Index num_polygons() const { return static_cast<Index>(face_offset.size()) - 1; }
  void add_polygon(std::initializer_list<Index> polygon) {
    face_vertex.insert(face_vertex.end(), polygon.begin(), polygon.end());
    face_offset.push_back(static_cast<Index>(face_vertex.size()));
  }
};

/// A triangle mesh after cleaning (see mesh/mesh_cleanup.h): every triangle
/// has three distinct vertices, no triangle appears twice, every vertex is
/// referenced, coordinates are finite.
struct Mesh {
  Points vertices;      ///< #V x 3
  Triangles triangles;  ///< #F x 3
  /// source_vertex[v] = index of v in the file it was read from, so results
  /// (feature points, segment labels) can be reported in the file's numbering.
  /// Empty means the identity.
  std::vector<Index> source_vertex;
  std::string source;  ///< file the mesh came from ("" = built in memory)

  Index num_vertices() const { return static_cast<Index>(vertices.rows()); }
  Index num_triangles() const { return static_cast<Index>(triangles.rows()); }
  Index source_index(Index v) const { return source_vertex.empty() ? v : source_vertex[v]; }
};

/// Area of triangle t of `mesh`.
inline double triangle_area(const Mesh& mesh, Index t) {
  const Vec3 a = mesh.vertices.row(mesh.triangles(t, 0));
  const Vec3 b = mesh.vertices.row(mesh.triangles(t, 1));
  const Vec3 c = mesh.vertices.row(mesh.triangles(t, 2));
  return 0.5 * (b - a).cross(c - a).norm();
}

/// Length of the diagonal of the axis-aligned bounding box of the vertices
/// of `mesh` (0 without vertices): the scale that perturbation strengths are
/// fractions of.
inline double bounding_box_diagonal(const Mesh& mesh) {
  if (mesh.num_vertices() == 0) return 0.0;
  return (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
}

/// Total area of the triangles of `mesh`.
inline double surface_area(const Mesh& mesh) {
  double area = 0.0;
  for (Index t = 0; t < mesh.num_triangles(); ++t) area += triangle_area(mesh, t);
  return area;
}

}  // namespace reebkit

// Where a point lies on a triangle mesh: the closest point of its surface and
// the nearest of that triangle's corners. Every perturbation that moves or
// replaces vertices (remeshing, decimation, subdivision) reports, with this,
// which vertex of the original each new vertex stands for, so that feature
// points of a variant can be compared with those of the original.
#pragma once

#include "reebkit/core/mesh.h"

#include <cstdint>
#include <vector>

namespace reebkit {

/// A mesh that a perturbation made from an original, and its correspondence.
struct MeshVariant {
  Mesh mesh;
  /// #V of `mesh`: the vertex of the original that vertex v stands for (the
  /// nearest corner of the original triangle closest to v, see
  /// SurfaceLocator::nearest_vertex, or v itself where the vertices are kept).
  std::vector<Index> original_vertex;
};

/// `mesh` as a variant that keeps the vertices of its original (moved or
/// not): original_vertex[v] = v.
MeshVariant same_vertices(Mesh mesh);

/// The point of a surface closest to a query point.
struct SurfacePoint {
  Index triangle = kInvalidIndex;  ///< the triangle it lies on
  Vec3 point = Vec3::Zero();       ///< its position
  double distance = 0.0;           ///< Euclidean distance from the query
};

/// Closest-point queries on one mesh's triangles, through a uniform grid of
/// their bounding boxes (cells about twice the mean edge length, at most
/// about 8 triangles per cell on a regular mesh), built once. Keeps a
/// reference to the mesh, which must outlive it.
class SurfaceLocator {
 public:
  /// \pre mesh has at least one triangle (else InvalidArgument naming mesh.source).
  explicit SurfaceLocator(const Mesh& mesh);

  /// The closest point of the surface to p (exact: the grid only orders the search).
  SurfacePoint closest(const Vec3& p) const;

  /// The corner of closest(p).triangle nearest to closest(p).point: the
  /// original vertex that p stands for, on the right side of a thin part
  /// even where another sheet holds a nearer vertex.
  Index nearest_vertex(const Vec3& p) const;

  const Mesh& mesh() const { return mesh_; }

 private:
  const Mesh& mesh_;
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 1.0;
  Eigen::Vector3i cells_ = Eigen::Vector3i::Ones();
  std::vector<Index> cell_start_;  ///< CSR: cell c holds cell_triangle_[cell_start_[c] .. cell_start_[c+1])
  std::vector<Index> cell_triangle_;

  Eigen::Vector3i cell_of(const Vec3& p) const;
};

/// The closest point of triangle (a, b, c) to p (Ericson, Real-Time
/// Collision Detection, 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// original_vertex of every row of `points` (SurfaceLocator::nearest_vertex).
std::vector<Index> nearest_original_vertices(const SurfaceLocator& original, const Points& points);

/// The largest distance from `samples` points drawn uniformly on the
/// surface of `from` (sample_surface, `seed`) to the surface of `to`: one
/// side of a sampled Hausdorff distance.
double sampled_distance_to_surface(const Mesh& from, const SurfaceLocator& to, int samples, std::uint64_t seed);

}  // namespace reebkit

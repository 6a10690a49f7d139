// Similarity transforms of meshes: the rotations, translations and uniform
// scalings under which reebkit's results must not change.
#pragma once

#include "reebkit/core/mesh.h"

#include <cstdint>
#include <random>
#include <vector>

namespace reebkit {

/// A similarity transform x -> scale * rotation * x + translation.
struct Similarity {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double scale = 1.0;
  Vec3 translation = Vec3::Zero();
};

/// A rotation drawn uniformly from SO(3) (from a unit quaternion), repeatable
/// for a given seed.
Eigen::Matrix3d random_rotation(std::uint64_t seed);

/// A random similarity for `mesh`: a uniform rotation (random_rotation), a
/// scale 2^u and a translation (u_x, u_y, u_z) x the bounding box diagonal,
/// each u uniform in [-1, 1]; repeatable for a given seed.
Similarity random_similarity(const Mesh& mesh, std::uint64_t seed);

/// The same, drawn from `rng` (a generator shared with other draws).
Similarity random_similarity(const Mesh& mesh, std::mt19937_64& rng);

/// A copy of `mesh` with every vertex transformed; connectivity unchanged.
Mesh transformed(const Mesh& mesh, const Similarity& transform);

/// `mesh` with its vertices renumbered: vertex v becomes to[v], the
/// triangles and source_vertex following; the same surface, numbered as
/// another file of it could be. Throws InvalidArgument unless `to` is a
/// permutation of 0 .. #V - 1.
Mesh renumbered(const Mesh& mesh, const std::vector<Index>& to);

/// A permutation of 0 .. n - 1, repeatable for a given seed.
std::vector<Index> random_permutation(Index n, std::uint64_t seed);

/// The frame of its own that canonical_copy puts a surface in.
struct SurfaceFrame {
  /// The vertex the moments were summed about (vertex 0), and the area
  /// centroid relative to it: a point x goes to axes (x - origin - centroid).
  Vec3 origin = Vec3::Zero(), centroid = Vec3::Zero();
  /// Rows: the principal axes, largest second moment first, each pointing to
  /// the side of positive third moment, over the square root of the area.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  /// The smaller gap between consecutive second moments of the surface
  /// about its principal axes, relative to the largest, in [0, 1]: where it
  /// is small the axes are ill-defined (a shape with a symmetry axis, a
  /// sphere), and they turn with the rounding of the input.
  double axis_gap = 0.0;
  double area = 0.0;  ///< 0: no frame (a mesh without area)
};

/// The frame of `mesh` (canonical_copy): its moments alone, without the
/// copy's sorts.
SurfaceFrame surface_frame(const Mesh& mesh);

/// A mesh in a frame of its own (canonical_copy).
struct CanonicalCopy {
  Mesh mesh;
  /// #V of `mesh`: the vertex of the input that vertex v is.
  std::vector<Index> original_vertex;
  double axis_gap = 0.0;  ///< SurfaceFrame::axis_gap
};

/// `mesh` in a frame of its own, so that its similar copies (any rotation,
/// reflection, translation and uniform scale, any vertex and triangle order)
/// give the same copy, for computations that depend on the frame, the
/// rounding or the order (a decimation) but should not: the area centroid at
/// the origin, unit area, the principal axes of the surface's second moments
/// as x, y, z (largest first), each pointing to the side of positive third
/// moment (the normalization of Vranic and Saupe's feature vectors for 3D
/// retrieval, "Tools for 3D-object retrieval: Karhunen-Loeve transform and
/// spherical harmonics", MMSP 2001, with area weights); each coordinate then
/// rounded to a multiple of 2^-20, so that copies that differ only by
/// rounding agree in every bit (but for the rare coordinate near half a
/// step), the vertices sorted by position and the triangles by vertex (each
/// rotated to start at its smallest). Where two second moments nearly tie
/// (a small axis_gap) copies may differ by a rotation, and where a third
/// moment vanishes (a mirror symmetry) by a reflection. A mesh without area
/// is returned as it is, with axis_gap 0.
CanonicalCopy canonical_copy(const Mesh& mesh);

/// The same in `frame`, surface_frame(mesh).
CanonicalCopy canonical_copy(const Mesh& mesh, const SurfaceFrame& frame);

}  // namespace reebkit

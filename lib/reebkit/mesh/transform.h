// Similarity transforms of meshes: the rotations, translations and uniform
// scalings under which reebkit's results must not change.
#pragma once

#include "reebkit/core/mesh.h"

#include <cstdint>
#include <random>

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

}  // namespace reebkit

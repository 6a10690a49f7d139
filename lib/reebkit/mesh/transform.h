// Similarity transforms of meshes: the rotations, translations and uniform
// scalings under which reebkit's results must not change.
#pragma once

#include "reebkit/core/mesh.h"

#include <cstdint>

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

/// A copy of `mesh` with every vertex transformed; connectivity unchanged.
Mesh transformed(const Mesh& mesh, const Similarity& transform);

}  // namespace reebkit

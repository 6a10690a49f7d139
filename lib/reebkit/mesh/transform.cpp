#include "reebkit/mesh/transform.h"

#include <Eigen/Geometry>

#include <random>

namespace reebkit {

Eigen::Matrix3d random_rotation(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

Mesh transformed(const Mesh& mesh, const Similarity& transform) {
  Mesh out = mesh;
  const Eigen::Matrix3d m = transform.scale * transform.rotation;
  for (Eigen::Index v = 0; v < out.vertices.rows(); ++v)
    out.vertices.row(v) = (m * mesh.vertices.row(v).transpose() + transform.translation).transpose();
  return out;
}

}  // namespace reebkit

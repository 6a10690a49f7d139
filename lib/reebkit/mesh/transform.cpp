#include "reebkit/mesh/transform.h"

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace reebkit {

Eigen::Matrix3d random_rotation(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

Similarity random_similarity(const Mesh& mesh, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  return random_similarity(mesh, rng);
}

Similarity random_similarity(const Mesh& mesh, std::mt19937_64& rng) {
  const double diagonal = bounding_box_diagonal(mesh);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Similarity s;
  s.rotation = random_rotation(rng());
  s.scale = std::exp2(unit(rng));
  s.translation = Vec3(unit(rng), unit(rng), unit(rng)) * diagonal;
  return s;
}

Mesh transformed(const Mesh& mesh, const Similarity& transform) {
  Mesh out = mesh;
  const Eigen::Matrix3d m = transform.scale * transform.rotation;
  for (Eigen::Index v = 0; v < out.vertices.rows(); ++v)
    out.vertices.row(v) = (m * mesh.vertices.row(v).transpose() + transform.translation).transpose();
  return out;
}

}  // namespace reebkit

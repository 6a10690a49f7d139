#include "reebkit/mesh/transform.h"

#include "reebkit/core/error.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <numeric>

#include <cmath>
#include <random>
#include <string>

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

Mesh renumbered(const Mesh& mesh, const std::vector<Index>& to) {
  const auto n = static_cast<std::size_t>(mesh.num_vertices());
  std::vector<char> taken(n, 0);
  bool permutation = to.size() == n;
  for (std::size_t v = 0; permutation && v < n; ++v) {
    const Index w = to[v];
    permutation = w >= 0 && static_cast<std::size_t>(w) < n && !taken[static_cast<std::size_t>(w)];
    if (permutation) taken[static_cast<std::size_t>(w)] = 1;
  }
  if (!permutation)
    throw InvalidArgument("renumbered: " + (mesh.source.empty() ? std::string("the mesh") : mesh.source) +
                          ": the new numbering is not a permutation of its " + std::to_string(n) + " vertices");
  Mesh out = mesh;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Index w = to[static_cast<std::size_t>(v)];
    out.vertices.row(w) = mesh.vertices.row(v);
    if (!mesh.source_vertex.empty()) out.source_vertex[static_cast<std::size_t>(w)] = mesh.source_index(v);
  }
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) out.triangles(t, k) = to[static_cast<std::size_t>(mesh.triangles(t, k))];
  return out;
}

std::vector<Index> random_permutation(Index n, std::uint64_t seed) {
  std::vector<Index> order(static_cast<std::size_t>(std::max<Index>(n, 0)));
  std::iota(order.begin(), order.end(), 0);
  std::mt19937_64 rng(seed);
  std::shuffle(order.begin(), order.end(), rng);
  return order;
}

SurfaceFrame surface_frame(const Mesh& mesh) {
  // Moments of the surface: each triangle's integrals of 1, x and x x^T
  // (exact for the linear triangle: area / 12 (sum v_i v_i^T + s s^T), s the
  // sum of its corners), about the first vertex to keep them small.
  SurfaceFrame out;
  out.origin = mesh.num_vertices() > 0 ? Vec3(mesh.vertices.row(0)) : Vec3::Zero();
  double area = 0.0;
  Vec3 first = Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  std::vector<double> triangle_areas(static_cast<std::size_t>(mesh.num_triangles()));
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const double a = triangle_areas[static_cast<std::size_t>(t)] = triangle_area(mesh, t);
    Vec3 sum = Vec3::Zero();
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
    for (int c = 0; c < 3; ++c) {
      const Vec3 p = mesh.vertices.row(mesh.triangles(t, c)).transpose() - out.origin;
      sum += p;
      outer += p * p.transpose();
    }
    area += a;
    first += a / 3.0 * sum;
    second += a / 12.0 * (outer + sum * sum.transpose());
  }
  if (!(area > 0.0)) return out;
  out.area = area;
  out.centroid = first / area;
  const Eigen::Matrix3d covariance = second / area - out.centroid * out.centroid.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance);  // ascending
  const Vec3 moment = axes.eigenvalues();
  out.axis_gap = moment(2) > 0.0 ? std::min(moment(2) - moment(1), moment(1) - moment(0)) / moment(2) : 0.0;
  for (int d = 0; d < 3; ++d) out.axes.row(d) = axes.eigenvectors().col(2 - d).transpose() / std::sqrt(area);
  // Third moments about each axis, from the triangle centroids (each vertex
  // placed in the frame once).
  std::vector<Vec3> placed(static_cast<std::size_t>(mesh.num_vertices()));
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    placed[static_cast<std::size_t>(v)] = out.axes * (mesh.vertices.row(v).transpose() - out.origin - out.centroid);
  const auto place = [&](Index t, int c) -> const Vec3& {
    return placed[static_cast<std::size_t>(mesh.triangles(t, c))];
  };
  Vec3 third = Vec3::Zero();
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const Vec3 c = (place(t, 0) + place(t, 1) + place(t, 2)) / 3.0;
    third += triangle_areas[static_cast<std::size_t>(t)] * c.cwiseProduct(c).cwiseProduct(c);
  }
  for (int d = 0; d < 3; ++d)
    if (third(d) < 0.0) out.axes.row(d) *= -1.0;
  return out;
}

CanonicalCopy canonical_copy(const Mesh& mesh) { return canonical_copy(mesh, surface_frame(mesh)); }

CanonicalCopy canonical_copy(const Mesh& mesh, const SurfaceFrame& frame) {
  constexpr double kGrid = 1048576.0;  // 2^20
  CanonicalCopy out;
  if (!(frame.area > 0.0)) {
    out.mesh = mesh;
    out.original_vertex.resize(static_cast<std::size_t>(mesh.num_vertices()));
    std::iota(out.original_vertex.begin(), out.original_vertex.end(), Index{0});
    return out;
  }
  out.axis_gap = frame.axis_gap;
  const auto place = [&](Index v) -> Vec3 {
    return frame.axes * (mesh.vertices.row(v).transpose() - frame.origin - frame.centroid);
  };

  const Index n = mesh.num_vertices();
  // Each vertex's place snapped to a grid of 2^-20 (exact: a power of two
  // scales without rounding), beside its id, sorted in place (no look-up
  // per comparison): lexicographic, ties by id, as a stable sort would.
  struct Snapped {
    std::array<double, 3> position;
    Index vertex;
  };
  std::vector<Snapped> snapped(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) {
    const Vec3 p = place(v);
    Snapped& s = snapped[static_cast<std::size_t>(v)];
    for (int d = 0; d < 3; ++d) s.position[static_cast<std::size_t>(d)] = std::nearbyint(p(d) * kGrid) / kGrid;
    s.vertex = v;
  }
  std::sort(snapped.begin(), snapped.end(), [](const Snapped& a, const Snapped& b) {
    return a.position != b.position ? a.position < b.position : a.vertex < b.vertex;
  });
  std::vector<Index> new_id(static_cast<std::size_t>(n));
  out.original_vertex.resize(static_cast<std::size_t>(n));
  out.mesh.source = mesh.source;
  out.mesh.vertices.resize(n, 3);
  if (!mesh.source_vertex.empty()) out.mesh.source_vertex.resize(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) {
    const Snapped& s = snapped[static_cast<std::size_t>(v)];
    out.original_vertex[static_cast<std::size_t>(v)] = s.vertex;
    new_id[static_cast<std::size_t>(s.vertex)] = v;
    if (!mesh.source_vertex.empty()) out.mesh.source_vertex[static_cast<std::size_t>(v)] = mesh.source_index(s.vertex);
    for (int d = 0; d < 3; ++d) out.mesh.vertices(v, d) = s.position[static_cast<std::size_t>(d)];
  }
  // The triangles, each rotated to start at its smallest new id (the
  // orientation kept), in lexicographic order: grouped by that first id (a
  // counting sort), each group (a vertex's few triangles) sorted on the rest.
  const Index m = mesh.num_triangles();
  std::vector<Index> first(static_cast<std::size_t>(n) + 1, 0);
  std::vector<std::array<Index, 3>> rotated(static_cast<std::size_t>(m));
  for (Index t = 0; t < m; ++t) {
    std::array<Index, 3>& k = rotated[static_cast<std::size_t>(t)];
    for (int c = 0; c < 3; ++c) k[static_cast<std::size_t>(c)] = new_id[static_cast<std::size_t>(mesh.triangles(t, c))];
    std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
    ++first[static_cast<std::size_t>(k[0]) + 1];
  }
  for (std::size_t v = 0; v < static_cast<std::size_t>(n); ++v) first[v + 1] += first[v];
  std::vector<std::array<Index, 3>> triangles(static_cast<std::size_t>(m));
  std::vector<Index> fill(first.begin(), first.end() - 1);
  for (const std::array<Index, 3>& k : rotated)
    triangles[static_cast<std::size_t>(fill[static_cast<std::size_t>(k[0])]++)] = k;
  for (std::size_t v = 0; v < static_cast<std::size_t>(n); ++v)
    std::sort(triangles.begin() + first[v], triangles.begin() + first[v + 1]);
  out.mesh.triangles.resize(m, 3);
  for (Index t = 0; t < m; ++t)
    for (int c = 0; c < 3; ++c)
      out.mesh.triangles(t, c) = triangles[static_cast<std::size_t>(t)][static_cast<std::size_t>(c)];
  return out;
}

}  // namespace reebkit

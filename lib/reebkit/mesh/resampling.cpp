#include "reebkit/mesh/resampling.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/surface_correspondence.h"

#include <cmath>
#include <random>
#include <unordered_map>

namespace reebkit {

Mesh resample_mesh(const Mesh& mesh, const ResamplingOptions& options) {
  if (!(options.jitter >= 0.0 && options.jitter < 0.5))
    throw InvalidArgument("resample_mesh: jitter " + std::to_string(options.jitter) + " is outside [0, 0.5)");
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> offset(-options.jitter, options.jitter);

  const Index nv = mesh.num_vertices();
  std::vector<Vec3> added;
  std::unordered_map<std::int64_t, Index> edge_vertex;
  const auto split = [&](Index a, Index b) {
    const Index lo = std::min(a, b), hi = std::max(a, b);
    const auto [it, inserted] = edge_vertex.try_emplace(static_cast<std::int64_t>(lo) * nv + hi, 0);
    if (inserted) {
      it->second = nv + static_cast<Index>(added.size());
      const double t = 0.5 + offset(rng);
      added.push_back((1.0 - t) * mesh.vertices.row(lo).transpose() + t * mesh.vertices.row(hi).transpose());
    }
    return it->second;
  };

  Mesh out;
  out.source = mesh.source;
  out.triangles.resize(4 * mesh.num_triangles(), 3);
  for (Index f = 0; f < mesh.num_triangles(); ++f) {
    const Index a = mesh.triangles(f, 0), b = mesh.triangles(f, 1), c = mesh.triangles(f, 2);
    const Index ab = split(a, b), bc = split(b, c), ca = split(c, a);
    out.triangles.row(4 * f) << a, ab, ca;
    out.triangles.row(4 * f + 1) << ab, b, bc;
    out.triangles.row(4 * f + 2) << ca, bc, c;
    out.triangles.row(4 * f + 3) << ab, bc, ca;
  }
  out.vertices.resize(nv + static_cast<Index>(added.size()), 3);
  out.vertices.topRows(nv) = mesh.vertices;
  for (std::size_t i = 0; i < added.size(); ++i) out.vertices.row(nv + static_cast<Index>(i)) = added[i].transpose();
  return out;
}

MeshVariant subdivide_mesh(const Mesh& mesh, int rounds) {
  if (rounds < 0) throw InvalidArgument(mesh.source + ": negative number of subdivision rounds");
  MeshVariant out;
  out.mesh = mesh;
  for (int round = 0; round < rounds; ++round) out.mesh = resample_mesh(out.mesh, ResamplingOptions{0.0, 1});
  out.original_vertex = nearest_original_vertices(SurfaceLocator(mesh), out.mesh.vertices);
  return out;
}

Mesh add_normal_noise(const Mesh& mesh, const NoiseOptions& options) {
  if (!(options.amplitude >= 0.0 && std::isfinite(options.amplitude)))
    throw InvalidArgument("add_normal_noise: amplitude " + std::to_string(options.amplitude) +
                          " is not a finite number >= 0");
  Points normals = Points::Zero(mesh.num_vertices(), 3);
  for (Index f = 0; f < mesh.num_triangles(); ++f) {
    const Vec3 p0 = mesh.vertices.row(mesh.triangles(f, 0)), p1 = mesh.vertices.row(mesh.triangles(f, 1)),
               p2 = mesh.vertices.row(mesh.triangles(f, 2));
    const Vec3 n = (p1 - p0).cross(p2 - p0);  // twice the area times the unit normal
    for (int k = 0; k < 3; ++k) normals.row(mesh.triangles(f, k)) += n.transpose();
  }
  const double diagonal = bounding_box_diagonal(mesh);
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> uniform(-options.amplitude * diagonal, options.amplitude * diagonal);
  std::normal_distribution<double> gaussian;  // x amplitude x diagonal
  Mesh out = mesh;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const double shift =
        options.shape == NoiseShape::Uniform ? uniform(rng) : options.amplitude * diagonal * gaussian(rng);
    const double length = normals.row(v).norm();
    if (length > 0.0) out.vertices.row(v) += shift / length * normals.row(v);
  }
  return out;
}

}  // namespace reebkit

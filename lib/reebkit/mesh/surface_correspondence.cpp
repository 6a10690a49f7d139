#include "reebkit/mesh/surface_correspondence.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/surface_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace reebkit {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denominator = va + vb + vc;
  if (!(denominator > 0.0)) return (a + b + c) / 3.0;  // a degenerate triangle: any point of it
  return a + (vb / denominator) * ab + (vc / denominator) * ac;
}

SurfaceLocator::SurfaceLocator(const Mesh& mesh) : mesh_(mesh) {
  if (mesh.num_triangles() == 0) throw InvalidArgument(mesh.source + ": no triangle to locate points on");
  const Vec3 lo = mesh.vertices.colwise().minCoeff(), hi = mesh.vertices.colwise().maxCoeff();
  double edges = 0.0;
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      edges += (mesh.vertices.row(mesh.triangles(t, k)) - mesh.vertices.row(mesh.triangles(t, (k + 1) % 3))).norm();
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
  cell_ = std::max(2.0 * edges / (3.0 * mesh.num_triangles()), extent / 256.0);
  origin_ = lo;
  for (int d = 0; d < 3; ++d) cells_[d] = std::max(1, static_cast<int>(std::ceil((hi[d] - lo[d]) / cell_)) + 1);

  const auto for_cells = [&](Index t, const auto& visit) {
    Vec3 tlo = mesh.vertices.row(mesh.triangles(t, 0)), thi = tlo;
    for (int k = 1; k < 3; ++k) {
      tlo = tlo.cwiseMin(mesh.vertices.row(mesh.triangles(t, k)).transpose());
      thi = thi.cwiseMax(mesh.vertices.row(mesh.triangles(t, k)).transpose());
    }
    const Eigen::Vector3i a = cell_of(tlo), b = cell_of(thi);
    for (int x = a[0]; x <= b[0]; ++x)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int z = a[2]; z <= b[2]; ++z) visit((static_cast<Index>(z) * cells_[1] + y) * cells_[0] + x);
  };
  const auto num_cells = static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2];
  cell_start_.assign(num_cells + 1, 0);
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for_cells(t, [&](Index c) { ++cell_start_[static_cast<std::size_t>(c) + 1]; });
  for (std::size_t c = 0; c < num_cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_triangle_.resize(static_cast<std::size_t>(cell_start_.back()));
  std::vector<Index> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for_cells(t, [&](Index c) { cell_triangle_[static_cast<std::size_t>(fill[static_cast<std::size_t>(c)]++)] = t; });
}

Eigen::Vector3i SurfaceLocator::cell_of(const Vec3& p) const {
  Eigen::Vector3i c;
  for (int d = 0; d < 3; ++d)
    c[d] = std::clamp(static_cast<int>(std::floor((p[d] - origin_[d]) / cell_)), 0, cells_[d] - 1);
  return c;
}

SurfacePoint SurfaceLocator::closest(const Vec3& p) const {
  SurfacePoint best;
  best.distance = std::numeric_limits<double>::infinity();
  const Eigen::Vector3i center = cell_of(p);
  // Distance from p to the outside of the box of cells within `ring` of its
  // own cell: a triangle first met in a farther ring cannot be nearer.
  const auto covered = [&](int ring) {
    double d = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const double lo = origin_[k] + (center[k] - ring) * cell_, hi = origin_[k] + (center[k] + ring + 1) * cell_;
      if (center[k] - ring > 0) d = std::min(d, p[k] - lo);
      if (center[k] + ring < cells_[k] - 1) d = std::min(d, hi - p[k]);
    }
    return d;
  };
  const int rings = cells_.maxCoeff();
  for (int ring = 0; ring <= rings; ++ring) {
    for (int x = center[0] - ring; x <= center[0] + ring; ++x)
      for (int y = center[1] - ring; y <= center[1] + ring; ++y)
        for (int z = center[2] - ring; z <= center[2] + ring; ++z) {
          if (std::max({std::abs(x - center[0]), std::abs(y - center[1]), std::abs(z - center[2])}) != ring) continue;
          if (x < 0 || y < 0 || z < 0 || x >= cells_[0] || y >= cells_[1] || z >= cells_[2]) continue;
          const auto c = static_cast<std::size_t>((static_cast<Index>(z) * cells_[1] + y) * cells_[0] + x);
          for (Index i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
            const Index t = cell_triangle_[static_cast<std::size_t>(i)];
            const Vec3 q = closest_point_on_triangle(p, mesh_.vertices.row(mesh_.triangles(t, 0)),
                                                     mesh_.vertices.row(mesh_.triangles(t, 1)),
                                                     mesh_.vertices.row(mesh_.triangles(t, 2)));
            const double d = (q - p).norm();
            if (d < best.distance || (d == best.distance && t < best.triangle)) best = SurfacePoint{t, q, d};
          }
        }
    if (best.distance <= covered(ring)) break;
  }
  return best;
}

Index SurfaceLocator::nearest_vertex(const Vec3& p) const {
  const SurfacePoint s = closest(p);
  Index best = mesh_.triangles(s.triangle, 0);
  for (int k = 1; k < 3; ++k) {
    const Index v = mesh_.triangles(s.triangle, k);
    if ((mesh_.vertices.row(v).transpose() - s.point).squaredNorm() <
        (mesh_.vertices.row(best).transpose() - s.point).squaredNorm())
      best = v;
  }
  return best;
}

MeshVariant same_vertices(Mesh mesh) {
  MeshVariant out{std::move(mesh), {}};
  out.original_vertex.resize(static_cast<std::size_t>(out.mesh.num_vertices()));
  for (Index v = 0; v < out.mesh.num_vertices(); ++v) out.original_vertex[static_cast<std::size_t>(v)] = v;
  return out;
}

std::vector<Index> nearest_original_vertices(const SurfaceLocator& original, const Points& points) {
  std::vector<Index> out(static_cast<std::size_t>(points.rows()));
  for (Eigen::Index v = 0; v < points.rows(); ++v)
    out[static_cast<std::size_t>(v)] = original.nearest_vertex(points.row(v).transpose());
  return out;
}

double sampled_distance_to_surface(const Mesh& from, const SurfaceLocator& to, int samples, std::uint64_t seed) {
  const TriangleAreas areas = triangle_areas(from);
  double worst = 0.0;
  for (const Vec3& p : sample_surface(from, areas.view(), samples, seed))
    worst = std::max(worst, to.closest(p).distance);
  return worst;
}

}  // namespace reebkit

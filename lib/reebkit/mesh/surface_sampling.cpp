#include "reebkit/mesh/surface_sampling.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace reebkit {
namespace {

/// A uniform number in [0, 1) from the top 53 bits of `rng`.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

Vec3 point(const Mesh& mesh, Index v) { return mesh.vertices.row(v).transpose(); }

}  // namespace

TriangleAreas triangle_areas(const Mesh& mesh, std::vector<Index> triangles) {
  TriangleAreas out;
  out.cumulative.resize(triangles.size());
  double total = 0.0;
  for (std::size_t k = 0; k < triangles.size(); ++k) out.cumulative[k] = total += triangle_area(mesh, triangles[k]);
  out.triangle = std::move(triangles);
  return out;
}

TriangleAreas triangle_areas(const Mesh& mesh) {
  std::vector<Index> every(static_cast<std::size_t>(mesh.num_triangles()));
  std::iota(every.begin(), every.end(), Index{0});
  return triangle_areas(mesh, std::move(every));
}

std::vector<Vec3> sample_surface(const Mesh& mesh, const WeightedTriangles& from, int count, std::uint64_t seed) {
  if (count < 0) throw InvalidArgument("sample_surface: count must be >= 0");
  if (!(from.total() > 0.0))
    throw InvalidArgument("sample_surface: " + (mesh.source.empty() ? std::string("mesh in memory") : mesh.source) +
                          ": the triangles to sample have no area");
  std::mt19937_64 rng(seed);
  std::vector<Vec3> points(static_cast<std::size_t>(count));
  const double* end = from.cumulative + from.size;
  for (Vec3& p : points) {
    const auto k = std::min(std::upper_bound(from.cumulative, end, unit(rng) * from.total()) - from.cumulative,
                            static_cast<std::ptrdiff_t>(from.size) - 1);
    const Index t = from.triangle[k];
    const double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
    p = (1.0 - r1) * point(mesh, mesh.triangles(t, 0)) + r1 * (1.0 - r2) * point(mesh, mesh.triangles(t, 1)) +
        r1 * r2 * point(mesh, mesh.triangles(t, 2));
  }
  return points;
}

}  // namespace reebkit

#include "reebkit/mesh/remeshing.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/decimation.h"
#include "reebkit/mesh/degenerate_triangles.h"
#include "reebkit/mesh/mesh_graph.h"
#include "reebkit/mesh/resampling.h"

#include <cmath>
#include <string>
#include <utility>

namespace reebkit {

namespace {

Index target_count(const Mesh& mesh, const RemeshOptions& options) {
  if (options.target_vertices > 0) return options.target_vertices;
  if (!(options.target_edge_length > 0.0 && std::isfinite(options.target_edge_length)))
    throw InvalidArgument(mesh.source + ": remeshing needs a vertex count or an edge length > 0");
  const double n =
      2.0 * surface_area(mesh) / (std::sqrt(3.0) * options.target_edge_length * options.target_edge_length);
  return n < 1e9 ? static_cast<Index>(std::llround(n)) : Index{1000000000};
}

/// Per vertex, the sum of its triangles' area-weighted normals, normalized (0 where it vanishes).
Points vertex_normals(const Mesh& mesh) {
  Points normals = Points::Zero(mesh.num_vertices(), 3);
  for (Index f = 0; f < mesh.num_triangles(); ++f) {
    const Vec3 p0 = mesh.vertices.row(mesh.triangles(f, 0)), p1 = mesh.vertices.row(mesh.triangles(f, 1)),
               p2 = mesh.vertices.row(mesh.triangles(f, 2));
    const Vec3 n = (p1 - p0).cross(p2 - p0);
    for (int k = 0; k < 3; ++k) normals.row(mesh.triangles(f, k)) += n.transpose();
  }
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const double length = normals.row(v).norm();
    if (length > 0.0) normals.row(v) /= length;
  }
  return normals;
}

// How many dense samplings remesh tries before it gives up.
constexpr int kRemeshAttempts = 4;

// One remeshing of `mesh` (remesh, below) from the dense sampling of `seed`;
// InvalidMeshError where a degenerate triangle is left that no flip or
// collapse removes.
MeshVariant remesh_from(const Mesh& mesh, const RemeshOptions& options, Index target, std::uint64_t seed,
                        const SurfaceLocator& original) {
  MeshVariant out;

  Mesh dense = resample_mesh(mesh, ResamplingOptions{0.2, seed});
  for (std::uint64_t round = 1; dense.num_vertices() < 4 * static_cast<std::int64_t>(target); ++round)
    dense = resample_mesh(dense, ResamplingOptions{0.2, seed + round});
  out.mesh = decimate_mesh(dense, DecimationOptions{static_cast<double>(target) / dense.num_vertices(), 0.02,
                                                    options.min_triangle_area})
                 .mesh;
  out.mesh.source = mesh.source;
  Mesh& result = out.mesh;

  const MeshGraph graph = build_mesh_graph(result);
  Points next = result.vertices;
  for (int iteration = 0; iteration < options.smoothing_iterations; ++iteration) {
    const Points normals = vertex_normals(result);
    for (Index v = 0; v < result.num_vertices(); ++v) {
      if (graph.ring[static_cast<std::size_t>(v)] != RingKind::Closed || graph.degree(v) == 0)
        continue;  // borders stay
      Vec3 centroid = Vec3::Zero();
      for (Index i = graph.offset[v]; i < graph.offset[v + 1]; ++i)
        centroid += result.vertices.row(graph.neighbor[static_cast<std::size_t>(i)]).transpose();
      centroid /= graph.degree(v);
      const Vec3 p = result.vertices.row(v), n = normals.row(v);
      const Vec3 step = options.smoothing_step * (centroid - p - n.dot(centroid - p) * n);
      next.row(v) = original.closest(p + step).point.transpose();
    }
    result.vertices = next;
  }

  const double tiny = 1e-9 * bounding_box_diagonal(mesh);
  for (Index v = 0; v < result.num_vertices(); ++v) {
    const Vec3 p = result.vertices.row(v);
    const SurfacePoint s = original.closest(p);
    for (int k = 0; k < 3; ++k) {
      const Index corner = mesh.triangles(s.triangle, k);
      if ((mesh.vertices.row(corner).transpose() - p).norm() > tiny) continue;
      const Vec3 a = mesh.vertices.row(corner), b = mesh.vertices.row(mesh.triangles(s.triangle, (k + 1) % 3)),
                 c = mesh.vertices.row(mesh.triangles(s.triangle, (k + 2) % 3));
      result.vertices.row(v) = (0.9 * a + 0.05 * b + 0.05 * c).transpose();
      break;
    }
  }

  TriangleRepair repaired = repair_degenerate_triangles(result, options.min_triangle_area);
  if (repaired.remaining > 0)
    throw InvalidMeshError(mesh.source, std::to_string(repaired.remaining) + " triangles of at most " +
                                            std::to_string(options.min_triangle_area) +
                                            " x the mean area are left that no edge flip or collapse removes");
  result = std::move(repaired.mesh);
  out.original_vertex.resize(static_cast<std::size_t>(result.num_vertices()));
  for (Index v = 0; v < result.num_vertices(); ++v)
    out.original_vertex[static_cast<std::size_t>(v)] = original.nearest_vertex(result.vertices.row(v).transpose());
  return out;
}

}  // namespace

MeshVariant remesh(const Mesh& mesh, const RemeshOptions& options) {
  const Index target = target_count(mesh, options);
  if (target < 4)
    throw InvalidArgument(mesh.source + ": remeshing target of " + std::to_string(target) + " vertices is below 4");
  if (options.smoothing_iterations < 0 || !(options.smoothing_step >= 0.0 && options.smoothing_step <= 1.0))
    throw InvalidArgument(mesh.source + ": negative smoothing iterations or a smoothing step outside [0, 1]");
  if (!(options.min_triangle_area >= 0.0 && options.min_triangle_area < 1.0))
    throw InvalidArgument(mesh.source + ": smallest triangle area " + std::to_string(options.min_triangle_area) +
                          " x the mean is outside [0, 1)");
  const SurfaceLocator original(mesh);
  // A sliver that no flip or collapse removes is rare and depends on the
  // dense sampling: the remeshing is made again from other samplings, each
  // drawn from the seed, so that the same seed still gives the same mesh.
  std::string failures;
  for (int attempt = 0; attempt < kRemeshAttempts; ++attempt) {
    const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(attempt) * 0x9E3779B97F4A7C15ULL;
    try {
      return remesh_from(mesh, options, target, seed, original);
    } catch (const InvalidMeshError& e) {
      failures += (attempt > 0 ? "; " : "") + e.problem();
    }
  }
  throw InvalidMeshError(mesh.source, "remeshing with seed " + std::to_string(options.seed) + " failed " +
                                          std::to_string(kRemeshAttempts) + " times: " + failures);
}

}  // namespace reebkit

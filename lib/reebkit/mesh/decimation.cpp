#include "reebkit/mesh/decimation.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/degenerate_triangles.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace reebkit {

namespace {

/// The triangles meshoptimizer keeps for a target of `target_triangles`.
std::vector<unsigned> simplify(const std::vector<unsigned>& indices, const std::vector<float>& positions,
                               std::size_t target_triangles) {
  std::vector<unsigned> out(indices.size());
  // target_error 1 = the whole extent of the mesh: the count alone stops the collapses.
  const std::size_t n =
      meshopt_simplify(out.data(), indices.data(), indices.size(), positions.data(), positions.size() / 3,
                       3 * sizeof(float), 3 * target_triangles, 1.0f, 0, nullptr);
  out.resize(n);
  return out;
}

/// `indices` without the triangles whose vertex set appears more than once:
/// a collapse can fold two triangles onto each other (a fin of zero volume
/// hanging on one edge, which makes that edge non-manifold); both go.
std::vector<unsigned> without_fins(const std::vector<unsigned>& indices) {
  const std::size_t n = indices.size() / 3;
  // Each triangle's sorted corners with its index, sorted: equal vertex
  // sets side by side.
  std::vector<std::pair<std::array<unsigned, 3>, std::size_t>> keys(n);
  for (std::size_t t = 0; t < n; ++t) {
    std::array<unsigned, 3> k{indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
    std::sort(k.begin(), k.end());
    keys[t] = {k, t};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> fin(n, 0);
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (keys[i].first == keys[i + 1].first) fin[keys[i].second] = fin[keys[i + 1].second] = 1;
  std::vector<unsigned> out;
  out.reserve(indices.size());
  for (std::size_t t = 0; t < n; ++t)
    if (!fin[t])
      out.insert(out.end(), indices.begin() + static_cast<std::ptrdiff_t>(3 * t),
                 indices.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  return out;
}

/// Triangles on vertices of their own: `vertex` the mesh's vertex that each is.
struct Coarser {
  std::vector<unsigned> indices;
  std::vector<float> positions;
  std::vector<unsigned> vertex;
};

/// The triangles `indices` (of the mesh's vertices, `positions`) on the
/// vertices they use alone, so that simplifying them costs what their size
/// does, not what the mesh's does.
Coarser coarser(const std::vector<unsigned>& indices, const std::vector<float>& positions) {
  Coarser out;
  std::vector<unsigned> local(positions.size() / 3, ~0u);
  out.indices.reserve(indices.size());
  for (const unsigned v : indices) {
    if (local[v] == ~0u) {
      local[v] = static_cast<unsigned>(out.vertex.size());
      out.vertex.push_back(v);
      out.positions.insert(out.positions.end(), positions.begin() + 3 * static_cast<std::ptrdiff_t>(v),
                           positions.begin() + 3 * static_cast<std::ptrdiff_t>(v) + 3);
    }
    out.indices.push_back(local[v]);
  }
  return out;
}

std::size_t used_vertices(const std::vector<unsigned>& indices, std::size_t num_vertices) {
  std::vector<char> used(num_vertices, 0);
  for (const unsigned v : indices) used[v] = 1;
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
}

}  // namespace

MeshVariant decimate_mesh(const Mesh& mesh, const DecimationOptions& options) {
  if (!(options.vertex_ratio > 0.0 && options.vertex_ratio <= 1.0))
    throw InvalidArgument(mesh.source + ": decimation ratio " + std::to_string(options.vertex_ratio) +
                          " is outside (0, 1]");
  if (!(options.min_triangle_area >= 0.0 && options.min_triangle_area < 1.0))
    throw InvalidArgument(mesh.source + ": smallest triangle area " + std::to_string(options.min_triangle_area) +
                          " x the mean is outside [0, 1)");
  MeshVariant out;
  const auto nv = static_cast<std::size_t>(mesh.num_vertices());
  const auto target = static_cast<std::size_t>(std::llround(options.vertex_ratio * static_cast<double>(nv)));
  std::vector<unsigned> indices(static_cast<std::size_t>(mesh.triangles.size()));
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      indices[static_cast<std::size_t>(3 * t + k)] = static_cast<unsigned>(mesh.triangles(t, k));
  std::vector<unsigned> kept = indices;
  if (target < nv) {
    std::vector<float> positions(3 * nv);
    for (std::size_t v = 0; v < nv; ++v)
      for (int d = 0; d < 3; ++d)
        positions[3 * v + static_cast<std::size_t>(d)] = static_cast<float>(mesh.vertices(static_cast<Index>(v), d));
    // Steered by triangles (Euler: #F/#V stays about constant), corrected
    // from the vertex count each try gives.
    double triangles = static_cast<double>(mesh.num_triangles()) * options.vertex_ratio;
    // What a try simplifies: the whole mesh, or (refine_last_try) the copy
    // of the last try that kept too many vertices.
    Coarser copy;
    const std::vector<unsigned>* from = &indices;
    const std::vector<float>* from_positions = &positions;
    for (int attempt = 0; attempt < 6; ++attempt) {
      const double most = static_cast<double>(from->size() / 3);  // meshoptimizer adds no triangle
      kept = without_fins(
          simplify(*from, *from_positions, static_cast<std::size_t>(std::clamp(std::round(triangles), 1.0, most))));
      if (from == &copy.indices)
        for (unsigned& v : kept) v = copy.vertex[v];
      const auto got = static_cast<double>(used_vertices(kept, nv));
      if (std::abs(got - static_cast<double>(target)) <= options.tolerance * static_cast<double>(target)) break;
      if (options.refine_last_try && got > static_cast<double>(target)) {
        copy = coarser(kept, positions);
        from = &copy.indices;
        from_positions = &copy.positions;
        triangles = static_cast<double>(kept.size() / 3);  // steered from the copy's own count
      }
      triangles *= static_cast<double>(target) / std::max(got, 1.0);
    }
  }
  std::vector<Index> new_id(nv, kInvalidIndex);
  for (const unsigned v : kept)
    if (new_id[v] == kInvalidIndex) new_id[v] = 0;
  for (std::size_t v = 0; v < nv; ++v)
    if (new_id[v] != kInvalidIndex) {
      new_id[v] = static_cast<Index>(out.original_vertex.size());
      out.original_vertex.push_back(static_cast<Index>(v));
    }
  out.mesh.source = mesh.source;
  out.mesh.vertices.resize(static_cast<Index>(out.original_vertex.size()), 3);
  for (std::size_t i = 0; i < out.original_vertex.size(); ++i)
    out.mesh.vertices.row(static_cast<Index>(i)) = mesh.vertices.row(out.original_vertex[i]);
  out.mesh.triangles.resize(static_cast<Index>(kept.size() / 3), 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
    out.mesh.triangles(static_cast<Index>(i / 3), static_cast<Index>(i % 3)) = new_id[kept[i]];
  if (target >= nv) return out;
  TriangleRepair repaired = repair_degenerate_triangles(out.mesh, options.min_triangle_area);
  if (repaired.remaining > 0)
    throw InvalidMeshError(mesh.source, "decimation to " + std::to_string(options.vertex_ratio) +
                                            " of the vertices left " + std::to_string(repaired.remaining) +
                                            " triangles of at most " + std::to_string(options.min_triangle_area) +
                                            " x the mean area that no edge flip or collapse removes");
  for (Index& v : repaired.input_vertex) v = out.original_vertex[static_cast<std::size_t>(v)];
  out.original_vertex = std::move(repaired.input_vertex);
  out.mesh = std::move(repaired.mesh);
  return out;
}

}  // namespace reebkit

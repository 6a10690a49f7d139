#include "reebkit/mesh/hole_filling.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/mesh_topology.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

namespace reebkit {

namespace {

/// Boundary half-edges (a, b): the edges exactly one triangle uses, in that
/// triangle's direction.
std::vector<std::array<Index, 2>> boundary_halfedges(const Triangles& triangles) {
  // (smaller endpoint, larger endpoint, half-edge), sorted so that the uses of
  // one edge are adjacent.
  std::vector<std::array<Index, 3>> uses;
  uses.reserve(static_cast<std::size_t>(3 * triangles.rows()));
  for (Index t = 0; t < triangles.rows(); ++t)
    for (Index k = 0; k < 3; ++k) {
      const Index a = triangles(t, k);
      const Index b = triangles(t, (k + 1) % 3);
      uses.push_back({std::min(a, b), std::max(a, b), 3 * t + k});
    }
  std::sort(uses.begin(), uses.end());
  std::vector<std::array<Index, 2>> boundary;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j][0] == uses[i][0] && uses[j][1] == uses[i][1]) ++j;
    if (j == i + 1) {
      const Index h = uses[i][2];
      boundary.push_back({triangles(h / 3, h % 3), triangles(h / 3, (h % 3 + 1) % 3)});
    }
    i = j;
  }
  return boundary;
}

/// The closed chains of boundary half-edges, each as its vertex sequence
/// (half-edge i of a loop runs from vertex i to vertex i + 1, cyclically).
/// At a vertex with several outgoing boundary half-edges the first unused one
/// is taken; a chain that reaches a vertex with none left is dropped.
std::vector<std::vector<Index>> boundary_loops(const Triangles& triangles, Index num_vertices) {
  const auto halfedges = boundary_halfedges(triangles);
  // Outgoing boundary half-edges per vertex, CSR.
  std::vector<Index> out_start(static_cast<std::size_t>(num_vertices) + 1, 0);
  for (const auto& [a, b] : halfedges) ++out_start[static_cast<std::size_t>(a) + 1];
  std::partial_sum(out_start.begin(), out_start.end(), out_start.begin());
  std::vector<Index> out_target(halfedges.size());
  std::vector<Index> fill(out_start.begin(), out_start.end() - 1);
  for (const auto& [a, b] : halfedges) out_target[static_cast<std::size_t>(fill[a]++)] = b;
  // out_start[v] .. next_unused[v] are taken.
  std::vector<Index> next_unused(out_start.begin(), out_start.end() - 1);

  std::vector<std::vector<Index>> loops;
  for (Index start = 0; start < num_vertices; ++start) {
    while (next_unused[start] < out_start[start + 1]) {
      std::vector<Index> loop{start};
      Index v = out_target[static_cast<std::size_t>(next_unused[start]++)];
      while (v != start && next_unused[v] < out_start[v + 1]) {
        loop.push_back(v);
        v = out_target[static_cast<std::size_t>(next_unused[v]++)];
      }
      if (v == start) loops.push_back(std::move(loop));
    }
  }
  return loops;
}

/// Surface area of each vertex-connected component of `mesh`, by vertex.
std::vector<double> component_area_by_vertex(const Mesh& mesh) {
  const ComponentLabels labels = connected_components(mesh.triangles, mesh.num_vertices());
  std::vector<double> area(static_cast<std::size_t>(labels.count), 0.0);
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    area[static_cast<std::size_t>(labels.vertex_component[mesh.triangles(t, 0)])] += triangle_area(mesh, t);
  std::vector<double> by_vertex(static_cast<std::size_t>(mesh.num_vertices()));
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    by_vertex[static_cast<std::size_t>(v)] = area[static_cast<std::size_t>(labels.vertex_component[v])];
  return by_vertex;
}

}  // namespace

Mesh fill_holes(const Mesh& mesh, const HoleFillingOptions& options) {
  if (!(options.max_loop_length >= 0))
    throw InvalidArgument("fill_holes(" + (mesh.source.empty() ? std::string("<memory>") : mesh.source) +
                          "): max_loop_length must be >= 0, got " + std::to_string(options.max_loop_length));
  const auto loops = boundary_loops(mesh.triangles, mesh.num_vertices());
  if (loops.empty()) return mesh;
  const std::vector<double> component_area = component_area_by_vertex(mesh);

  std::vector<const std::vector<Index>*> small;
  Index new_triangles = 0;
  for (const auto& loop : loops) {
    double length = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i)
      length += (mesh.vertices.row(loop[i]) - mesh.vertices.row(loop[(i + 1) % loop.size()])).norm();
    if (length <= options.max_loop_length * std::sqrt(component_area[static_cast<std::size_t>(loop.front())])) {
      small.push_back(&loop);
      new_triangles += static_cast<Index>(loop.size());
    }
  }
  if (small.empty()) return mesh;

  Mesh filled;
  filled.source = mesh.source;
  const Index n = mesh.num_vertices();
  filled.vertices.resize(n + static_cast<Index>(small.size()), 3);
  filled.vertices.topRows(n) = mesh.vertices;
  filled.triangles.resize(mesh.num_triangles() + new_triangles, 3);
  filled.triangles.topRows(mesh.num_triangles()) = mesh.triangles;
  filled.source_vertex.resize(static_cast<std::size_t>(filled.num_vertices()), kInvalidIndex);
  for (Index v = 0; v < n; ++v) filled.source_vertex[static_cast<std::size_t>(v)] = mesh.source_index(v);

  Index t = mesh.num_triangles();
  for (std::size_t l = 0; l < small.size(); ++l) {
    const std::vector<Index>& loop = *small[l];
    const Index center = n + static_cast<Index>(l);
    Vec3 mean = Vec3::Zero();
    for (const Index v : loop) mean += mesh.vertices.row(v).transpose();
    filled.vertices.row(center) = mean / static_cast<double>(loop.size());
    // Boundary half-edge a -> b lies in a triangle running a -> b, so the
    // fan triangle runs b -> a to be oriented like it.
    for (std::size_t i = 0; i < loop.size(); ++i)
      filled.triangles.row(t++) << loop[(i + 1) % loop.size()], loop[i], center;
  }
  return filled;
}

Index original_vertex_count(const Mesh& mesh) {
  const auto& source = mesh.source_vertex;
  const auto added = std::find(source.begin(), source.end(), kInvalidIndex);
  return source.empty() ? mesh.num_vertices() : static_cast<Index>(added - source.begin());
}

Mesh original_surface(const Mesh& mesh) {
  const Index n = original_vertex_count(mesh);
  if (n == mesh.num_vertices()) return mesh;
  Mesh out;
  out.source = mesh.source;
  out.vertices = mesh.vertices.topRows(n);
  out.source_vertex.assign(mesh.source_vertex.begin(), mesh.source_vertex.begin() + n);
  Index kept = 0;
  out.triangles.resize(mesh.num_triangles(), 3);
  for (Index f = 0; f < mesh.num_triangles(); ++f)
    if ((mesh.triangles.row(f).array() < n).all()) out.triangles.row(kept++) = mesh.triangles.row(f);
  out.triangles.conservativeResize(kept, 3);
  return out;
}

}  // namespace reebkit

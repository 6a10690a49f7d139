#include "reebkit/mesh/mesh_topology.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>

namespace reebkit {

namespace {

/// Union-find with path halving; the smaller index becomes the root, so a
/// root is the smallest element of its set.
class DisjointSets {
 public:
  explicit DisjointSets(Index n) : parent_(static_cast<std::size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }
  Index find(Index x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a > b) std::swap(a, b);
    parent_[b] = a;
  }

 private:
  std::vector<Index> parent_;
};

/// Throws InvalidArgument unless every index lies in [0, num_vertices) and,
/// when `distinct`, the three indices of each triangle differ.
void check_triangles(const Triangles& triangles, Index num_vertices, bool distinct, const std::string& caller) {
  for (Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Index v = triangles(t, k);
      if (v < 0 || v >= num_vertices)
        throw InvalidArgument(caller + ": triangle " + std::to_string(t) + " has vertex index " + std::to_string(v) +
                              " outside [0, " + std::to_string(num_vertices) + ")");
    }
    if (distinct && (triangles(t, 0) == triangles(t, 1) || triangles(t, 1) == triangles(t, 2) ||
                     triangles(t, 0) == triangles(t, 2)))
      throw InvalidArgument(caller + ": triangle " + std::to_string(t) + " repeats a vertex");
  }
}

// Half-edge h = 3 t + k of triangle t runs from corner k to corner (k + 1) % 3;
// corner c = 3 t + k is vertex triangles(t, k) as seen from triangle t.
Index corner_vertex(const Triangles& triangles, Index c) { return triangles(c / 3, c % 3); }
Index next_corner(Index c) { return c - c % 3 + (c % 3 + 1) % 3; }

/// The half-edges grouped by undirected edge: edge e owns
/// halfedges[edge_start[e] .. edge_start[e + 1]). Built by a counting sort on
/// the smaller endpoint and small sorts on the larger one: O(F log d), d = max degree.
struct EdgeTable {
  std::vector<Index> halfedges;
  std::vector<Index> edge_start{0};

  Index num_edges() const { return static_cast<Index>(edge_start.size()) - 1; }
  Index size(Index e) const { return edge_start[e + 1] - edge_start[e]; }
};

EdgeTable build_edge_table(const Triangles& triangles, Index num_vertices) {
  const Index num_halfedges = 3 * static_cast<Index>(triangles.rows());
  std::vector<Index> bucket_start(static_cast<std::size_t>(num_vertices) + 1, 0);
  for (Index h = 0; h < num_halfedges; ++h) {
    const Index a = corner_vertex(triangles, h);
    const Index b = corner_vertex(triangles, next_corner(h));
    ++bucket_start[std::min(a, b) + 1];
  }
  std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());

  // (larger endpoint, half-edge), bucketed by the smaller endpoint.
  std::vector<std::pair<Index, Index>> entries(static_cast<std::size_t>(num_halfedges));
  std::vector<Index> fill(bucket_start.begin(), bucket_start.end() - 1);
  for (Index h = 0; h < num_halfedges; ++h) {
    const Index a = corner_vertex(triangles, h);
    const Index b = corner_vertex(triangles, next_corner(h));
    entries[fill[std::min(a, b)]++] = {std::max(a, b), h};
  }

  EdgeTable table;
  table.halfedges.reserve(entries.size());
  table.edge_start.reserve(entries.size() / 2 + 2);
  for (Index v = 0; v < num_vertices; ++v) {
    const auto first = entries.begin() + bucket_start[v];
    const auto last = entries.begin() + bucket_start[v + 1];
    std::sort(first, last);
    for (auto it = first; it != last; ++it) {
      if (it != first && it->first != (it - 1)->first)
        table.edge_start.push_back(static_cast<Index>(table.halfedges.size()));
      table.halfedges.push_back(it->second);
    }
    if (first != last) table.edge_start.push_back(static_cast<Index>(table.halfedges.size()));
  }
  return table;
}

/// True when the triangles of every component can be flipped so that each
/// manifold edge is traversed once in each direction. mate[h] is the other
/// half-edge of h's edge when that edge is manifold, else kInvalidIndex.
bool is_orientable(const Triangles& triangles, const std::vector<Index>& mate) {
  const Index num_triangles = static_cast<Index>(triangles.rows());
  std::vector<std::int8_t> flipped(static_cast<std::size_t>(num_triangles), -1);
  std::vector<Index> stack;
  for (Index seed = 0; seed < num_triangles; ++seed) {
    if (flipped[seed] >= 0) continue;
    flipped[seed] = 0;
    stack.push_back(seed);
    while (!stack.empty()) {
      const Index t = stack.back();
      stack.pop_back();
      for (Index h = 3 * t; h < 3 * t + 3; ++h) {
        const Index m = mate[h];
        if (m == kInvalidIndex) continue;
        // Same start vertex = same direction: exactly one of the two must flip.
        const bool same_direction = corner_vertex(triangles, h) == corner_vertex(triangles, m);
        const auto want = static_cast<std::int8_t>(flipped[t] ^ static_cast<std::int8_t>(same_direction));
        const Index u = m / 3;
        if (flipped[u] < 0) {
          flipped[u] = want;
          stack.push_back(u);
        } else if (flipped[u] != want) {
          return false;
        }
      }
    }
  }
  return true;
}

}  // namespace

ComponentLabels connected_components(const Triangles& triangles, Index num_vertices) {
  check_triangles(triangles, num_vertices, false, "connected_components");
  DisjointSets sets(num_vertices);
  for (Index t = 0; t < triangles.rows(); ++t) {
    sets.unite(triangles(t, 0), triangles(t, 1));
    sets.unite(triangles(t, 1), triangles(t, 2));
  }
  ComponentLabels labels;
  labels.vertex_component.assign(static_cast<std::size_t>(num_vertices), kInvalidIndex);
  for (Index v = 0; v < num_vertices; ++v) {
    const Index root = sets.find(v);  // the smallest vertex of v's component, so already labelled
    labels.vertex_component[v] = root == v ? labels.count++ : labels.vertex_component[root];
  }
  return labels;
}

MeshTopology analyze_topology(const Mesh& mesh) {
  const Triangles& triangles = mesh.triangles;
  const Index num_vertices = mesh.num_vertices();
  const Index num_corners = 3 * mesh.num_triangles();
  check_triangles(triangles, num_vertices, true,
                  "analyze_topology(" + (mesh.source.empty() ? std::string("<memory>") : mesh.source) + ")");

  MeshTopology topology;
  topology.vertices = num_vertices;
  topology.faces = mesh.num_triangles();

  // Classify edges; join the corners of the two triangles of each manifold
  // edge at both endpoints, so corner sets become the fans around each vertex.
  const EdgeTable edges = build_edge_table(triangles, num_vertices);
  topology.edges = edges.num_edges();
  std::vector<Index> mate(static_cast<std::size_t>(num_corners), kInvalidIndex);
  DisjointSets fans(num_corners);
  for (Index e = 0; e < edges.num_edges(); ++e) {
    const Index size = edges.size(e);
    if (size == 1) ++topology.boundary_edges;
    if (size > 2) ++topology.non_manifold_edges;
    if (size != 2) continue;
    const Index h = edges.halfedges[edges.edge_start[e]];
    const Index m = edges.halfedges[edges.edge_start[e] + 1];
    mate[h] = m;
    mate[m] = h;
    if (corner_vertex(triangles, h) == corner_vertex(triangles, m)) {
      fans.unite(h, m);
      fans.unite(next_corner(h), next_corner(m));
    } else {
      fans.unite(h, next_corner(m));
      fans.unite(next_corner(h), m);
    }
  }

  std::vector<Index> fans_at_vertex(static_cast<std::size_t>(num_vertices), 0);
  for (Index c = 0; c < num_corners; ++c)
    if (fans.find(c) == c) ++fans_at_vertex[corner_vertex(triangles, c)];
  topology.non_manifold_vertices =
      static_cast<Index>(std::count_if(fans_at_vertex.begin(), fans_at_vertex.end(), [](Index n) { return n != 1; }));

  // Boundary loops: two boundary edges meeting at a vertex continue each
  // other when they bound the same fan there.
  std::vector<Index> boundary_halfedges;
  boundary_halfedges.reserve(static_cast<std::size_t>(topology.boundary_edges));
  for (Index e = 0; e < edges.num_edges(); ++e)
    if (edges.size(e) == 1) boundary_halfedges.push_back(edges.halfedges[edges.edge_start[e]]);
  DisjointSets loops(topology.boundary_edges);
  std::vector<Index> fan_boundary_edge(static_cast<std::size_t>(num_corners), kInvalidIndex);
  for (Index b = 0; b < topology.boundary_edges; ++b) {
    const Index h = boundary_halfedges[b];
    for (const Index corner : {h, next_corner(h)}) {
      Index& first = fan_boundary_edge[fans.find(corner)];
      if (first == kInvalidIndex) {
        first = b;
      } else {
        loops.unite(first, b);
      }
    }
  }
  for (Index b = 0; b < topology.boundary_edges; ++b)
    if (loops.find(b) == b) ++topology.boundary_loops;

  topology.components = connected_components(triangles, num_vertices).count;
  topology.euler_characteristic = num_vertices - topology.edges + topology.faces;
  topology.closed = topology.boundary_edges == 0;
  topology.manifold = topology.non_manifold_edges == 0 && topology.non_manifold_vertices == 0;
  topology.orientable = is_orientable(triangles, mate);
  if (topology.manifold && topology.orientable)
    topology.genus = (2 * topology.components - topology.euler_characteristic - topology.boundary_loops) / 2;
  return topology;
}

}  // namespace reebkit

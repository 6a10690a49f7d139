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
  explicit DisjointSets(Index n = 0) { reset(n); }
  /// n singletons again, reusing the storage (the fans of one vertex after another).
  void reset(Index n) {
    parent_.resize(static_cast<std::size_t>(n));
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }
  Index find(Index x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  /// Joins the sets of a and b; false when they were one already.
  bool unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (a > b) std::swap(a, b);
    parent_[b] = a;
    return true;
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
// Triangles are row-major, so corner c is entry c of the index array.
Index corner_vertex(const Triangles& triangles, Index c) { return triangles.data()[c]; }
Index previous_corner(Index c) { return c % 3 == 0 ? c + 2 : c - 1; }

/// Union-find over triangles that keeps, for each triangle, whether it must be
/// flipped relative to the root of its set (path halving; the smaller index
/// becomes the root). The triangles can be oriented consistently exactly when
/// no relation contradicts the earlier ones: a two-colouring of the manifold
/// edges' constraints, found in the same pass as the edges.
class OrientationSets {
 public:
  explicit OrientationSets(Index n) : parent_(static_cast<std::size_t>(n)), flipped_(static_cast<std::size_t>(n), 0) {
    std::iota(parent_.begin(), parent_.end(), Index{0});
  }

  /// Requires t and u to be flipped alike, or differently when `differ`;
  /// false when the relations so far forbid it.
  bool relate(Index t, Index u, bool differ) {
    auto [root_t, flip_t] = find(t);
    auto [root_u, flip_u] = find(u);
    const auto flip = static_cast<std::uint8_t>(flip_t ^ flip_u ^ static_cast<std::uint8_t>(differ));
    if (root_t == root_u) return flip == 0;
    if (root_t > root_u) std::swap(root_t, root_u);
    parent_[root_u] = root_t;
    flipped_[root_u] = flip;
    return true;
  }

 private:
  /// The root of x's set and whether x is flipped relative to it. A root's
  /// own flag stays 0.
  std::pair<Index, std::uint8_t> find(Index x) {
    std::uint8_t flip = 0;
    while (parent_[x] != x) {
      const Index p = parent_[x];
      flipped_[x] ^= flipped_[p];
      parent_[x] = parent_[p];
      flip ^= flipped_[x];
      x = parent_[x];
    }
    return {x, flip};
  }

  std::vector<Index> parent_;
  std::vector<std::uint8_t> flipped_;
};

/// The edges at one vertex v, found from its corners and their links: each
/// incident triangle gives two half-edges, one leaving v and one entering it,
/// grouped by their other endpoint. A neighbour's entry (#V of them) holds the vertex whose star
/// last saw it and its edge there, so nothing is cleared between vertices and
/// finding an edge takes one look-up.
class VertexStar {
 public:
  struct Edge {
    Index other = 0;           ///< the endpoint that is not v
    Index count = 0;           ///< triangles on the edge
    Index halfedge[2] = {};    ///< the first two half-edges
    Index fan_corner[2] = {};  ///< their triangles' corners at v, as positions among v's corners
    bool leaves[2] = {};       ///< whether each of the two half-edges leaves v (else it enters v)
  };

  explicit VertexStar(Index num_vertices) : seen_(static_cast<std::size_t>(num_vertices), Seen{kInvalidIndex, 0}) {}

  /// Collects the edges of vertex v of `corners` (corner positions 0, 1, ...),
  /// which must hold both the corners and their links (CornerParts::Both).
  void collect(const VertexCorners& corners, Index v) {
    const Index degree = corners.degree(v);
    const Index* first_corner = corners.corner.data() + corners.start[v];
    const std::array<Index, 2>* link = corners.link.data() + corners.start[v];
    if (edges_.size() < 2 * static_cast<std::size_t>(degree)) edges_.resize(2 * static_cast<std::size_t>(degree));
    size_ = 0;
    for (Index i = 0; i < degree; ++i) {
      const Index c = first_corner[i];
      add(v, link[i][0], c, i, true);
      add(v, link[i][1], previous_corner(c), i, false);
    }
  }

  const Edge* begin() const { return edges_.data(); }
  const Edge* end() const { return edges_.data() + size_; }

 private:
  struct Seen {
    Index star;  ///< the vertex whose star saw this neighbour last
    Index edge;  ///< its edge there
  };

  void add(Index v, Index other, Index halfedge, Index fan_corner, bool leaves) {
    Seen& seen = seen_[static_cast<std::size_t>(other)];
    if (seen.star != v) {
      seen = Seen{v, size_};
      edges_[static_cast<std::size_t>(size_++)] = Edge{other, 1, {halfedge, 0}, {fan_corner, 0}, {leaves, false}};
      return;
    }
    Edge& edge = edges_[static_cast<std::size_t>(seen.edge)];
    if (edge.count == 1) {
      edge.halfedge[1] = halfedge;
      edge.fan_corner[1] = fan_corner;
      edge.leaves[1] = leaves;
    }
    ++edge.count;
  }

  std::vector<Seen> seen_;
  std::vector<Edge> edges_;  // the first size_ are v's
  Index size_ = 0;
};

/// The two triangles of a manifold edge run along it the same way (the same
/// start vertex): one of them must flip for the two to agree.
bool same_direction(const VertexStar::Edge& edge) { return edge.leaves[0] == edge.leaves[1]; }

/// Whether flipping some triangles orients every manifold edge once each way:
/// a two-colouring of the triangles under the edges' constraints, by a second
/// pass over the stars. Needed only where the triangles as given disagree on
/// an edge, so a consistently oriented file (the usual case) never pays for it.
bool orientable_by_flips(const VertexCorners& corners) {
  OrientationSets orientation(static_cast<Index>(corners.corner.size() / 3));
  const auto num_vertices = static_cast<Index>(corners.start.size()) - 1;
  VertexStar star(num_vertices);
  for (Index v = 0; v < num_vertices; ++v) {
    star.collect(corners, v);
    for (const VertexStar::Edge& edge : star)
      if (edge.other > v && edge.count == 2 &&
          !orientation.relate(edge.halfedge[0] / 3, edge.halfedge[1] / 3, same_direction(edge)))
        return false;
  }
  return true;
}

/// Closed chains of boundary edges, given each boundary edge by its one
/// half-edge (`boundary_halfedges`, any order) and the pairs of boundary
/// half-edges that continue each other at a vertex.
Index count_boundary_loops(std::vector<Index> boundary_halfedges,
                           const std::vector<std::pair<Index, Index>>& continuations) {
  std::sort(boundary_halfedges.begin(), boundary_halfedges.end());
  const auto id = [&](Index h) {
    return static_cast<Index>(std::lower_bound(boundary_halfedges.begin(), boundary_halfedges.end(), h) -
                              boundary_halfedges.begin());
  };
  const auto count = static_cast<Index>(boundary_halfedges.size());
  DisjointSets loops(count);
  Index loops_left = count;
  for (const auto& [a, b] : continuations)
    if (loops.unite(id(a), id(b))) --loops_left;
  return loops_left;
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

VertexCorners corners_by_vertex(const Triangles& triangles, Index num_vertices, CornerParts parts) {
  const Index num_corners = 3 * static_cast<Index>(triangles.rows());
  VertexCorners corners;
  corners.start.assign(static_cast<std::size_t>(num_vertices) + 1, 0);
  for (Index c = 0; c < num_corners; ++c) ++corners.start[static_cast<std::size_t>(corner_vertex(triangles, c)) + 1];
  std::partial_sum(corners.start.begin(), corners.start.end(), corners.start.begin());
  const bool with_corners = parts != CornerParts::Links, links = parts != CornerParts::Corners;
  if (with_corners) corners.corner.resize(static_cast<std::size_t>(num_corners));
  if (links) corners.link.resize(static_cast<std::size_t>(num_corners));
  std::vector<Index> fill(corners.start.begin(), corners.start.end() - 1);
  const Index* index = triangles.data();
  for (Index c = 0; c < num_corners; c += 3) {
    const Index a = index[c], b = index[c + 1], d = index[c + 2];
    const Index at[3] = {fill[a]++, fill[b]++, fill[d]++};
    if (with_corners)
      for (int k = 0; k < 3; ++k) corners.corner[static_cast<std::size_t>(at[k])] = c + k;
    if (!links) continue;
    corners.link[static_cast<std::size_t>(at[0])] = {b, d};
    corners.link[static_cast<std::size_t>(at[1])] = {d, a};
    corners.link[static_cast<std::size_t>(at[2])] = {a, b};
  }
  return corners;
}

MeshTopology analyze_topology(const Mesh& mesh) {
  const Triangles& triangles = mesh.triangles;
  const Index num_vertices = mesh.num_vertices();
  check_triangles(triangles, num_vertices, true,
                  "analyze_topology(" + (mesh.source.empty() ? std::string("<memory>") : mesh.source) + ")");

  MeshTopology topology;
  topology.vertices = num_vertices;
  topology.faces = mesh.num_triangles();

  // One pass over the vertices, each with its star: an edge is counted at its
  // smaller endpoint; at every endpoint the two triangles of a manifold edge
  // join their corners there into one fan; two boundary edges at a vertex
  // continue each other when they bound the same fan there (as if the vertex
  // were split into its fans); the endpoints of every edge join one component.
  const VertexCorners corners = corners_by_vertex(triangles, num_vertices, CornerParts::Both);
  VertexStar star(num_vertices);
  DisjointSets fans;  // over the corners of one vertex, by their position among them
  DisjointSets components(num_vertices);
  bool oriented_as_given = true;
  std::vector<Index> boundary_halfedges;
  std::vector<std::pair<Index, Index>> continuations;
  std::vector<Index> fan_boundary_halfedge;  // per corner position of the vertex: first boundary half-edge of its fan
  for (Index v = 0; v < num_vertices; ++v) {
    const Index degree = corners.degree(v);
    star.collect(corners, v);
    fans.reset(degree);
    Index fan_count = degree;
    bool boundary = false;
    for (const VertexStar::Edge& edge : star) {
      if (edge.count == 2 && fans.unite(edge.fan_corner[0], edge.fan_corner[1])) --fan_count;
      boundary = boundary || edge.count == 1;
      if (edge.other < v) {
        components.unite(edge.other, v);
        continue;
      }
      ++topology.edges;
      if (edge.count == 1) boundary_halfedges.push_back(edge.halfedge[0]);
      if (edge.count > 2) ++topology.non_manifold_edges;
      if (edge.count == 2 && same_direction(edge)) oriented_as_given = false;
    }
    if (fan_count != 1) ++topology.non_manifold_vertices;
    if (!boundary) continue;
    fan_boundary_halfedge.assign(static_cast<std::size_t>(degree), kInvalidIndex);
    for (const VertexStar::Edge& edge : star) {
      if (edge.count != 1) continue;
      Index& first = fan_boundary_halfedge[static_cast<std::size_t>(fans.find(edge.fan_corner[0]))];
      if (first == kInvalidIndex) {
        first = edge.halfedge[0];
      } else {
        continuations.emplace_back(first, edge.halfedge[0]);
      }
    }
  }
  topology.orientable = oriented_as_given || orientable_by_flips(corners);
  topology.boundary_edges = static_cast<Index>(boundary_halfedges.size());
  topology.boundary_loops = count_boundary_loops(std::move(boundary_halfedges), continuations);

  for (Index v = 0; v < num_vertices; ++v)
    if (components.find(v) == v) ++topology.components;
  topology.euler_characteristic = num_vertices - topology.edges + topology.faces;
  topology.closed = topology.boundary_edges == 0;
  topology.manifold = topology.non_manifold_edges == 0 && topology.non_manifold_vertices == 0;
  if (topology.manifold && topology.orientable)
    topology.genus = (2 * topology.components - topology.euler_characteristic - topology.boundary_loops) / 2;
  return topology;
}

}  // namespace reebkit

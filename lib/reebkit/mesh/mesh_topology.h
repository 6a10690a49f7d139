// Topology of a triangle mesh: Euler characteristic, boundary loops,
// manifoldness, orientability, connected components and genus.
#pragma once

#include "reebkit/core/mesh.h"
#include "reebkit/core/types.h"

#include <array>
#include <vector>

namespace reebkit {

/// Topological counts of a triangle mesh. An edge is a boundary edge when one
/// triangle uses it and non-manifold when more than two do. A vertex is
/// manifold when its incident triangles form exactly one fan, i.e. one set
/// connected across manifold edges (edges with exactly two triangles) that
/// contain the vertex; so a bowtie vertex, an endpoint of a non-manifold edge
/// and an isolated vertex are all non-manifold vertices.
struct MeshTopology {
  Index vertices = 0;
  Index edges = 0;
  Index faces = 0;
  Index boundary_edges = 0;
  /// Closed chains of boundary edges (holes), followed fan by fan: at a
  /// non-manifold vertex two boundary edges continue each other only when
  /// they bound the same fan (as if the vertex were split into its fans, so
  /// the two triangles of a bowtie have two loops, and two holes touching at
  /// a vertex form one).
  Index boundary_loops = 0;
  Index non_manifold_edges = 0;
  Index non_manifold_vertices = 0;
  /// Connected components (triangles sharing a vertex are connected).
  Index components = 0;
  int euler_characteristic = 0;  ///< V - E + F
  /// Sum over components of (2 - chi_i - b_i) / 2, i.e. (2 * components - chi - b) / 2;
  /// -1 where not defined: non-manifold or non-orientable meshes.
  int genus = -1;
  bool closed = false;      ///< no boundary edges
  bool manifold = false;    ///< no non-manifold edges or vertices
  bool orientable = false;  ///< triangles can be oriented so that every manifold edge is used once each way
};

/// Topology of `mesh`.
/// \pre every triangle has three distinct vertex indices in [0, #V) (true of
///      every Mesh clean_mesh returns); throws InvalidArgument otherwise.
MeshTopology analyze_topology(const Mesh& mesh);

/// The corners of a triangle mesh grouped by vertex. Corner c = 3 t + k is
/// vertex triangles(t, k) as seen from triangle t; the corners of v are
/// corner[start[v] .. start[v + 1]), in increasing order, so one per incident
/// triangle, in triangle order.
struct VertexCorners {
  std::vector<Index> start;   ///< #V + 1
  std::vector<Index> corner;  ///< 3 #F (when asked for)
  /// Beside each corner position (when asked for): the two other vertices
  /// of its triangle, the next and the previous in the triangle's order, so
  /// that a pass over a vertex's corners reads them in sequence instead of
  /// looking each triangle up (the triangles of a star lie far apart in a
  /// large mesh).
  std::vector<std::array<Index, 2>> link;

  Index degree(Index v) const { return start[v + 1] - start[v]; }  ///< incident triangles
};

/// Which arrays of VertexCorners corners_by_vertex fills beside `start`.
enum class CornerParts {
  Corners,  ///< `corner`
  Links,    ///< `link`
  Both,     ///< `corner` and `link`
};

/// Corners of `triangles` grouped by vertex, by a counting sort: O(#V + #F).
/// Indices must lie in [0, num_vertices).
VertexCorners corners_by_vertex(const Triangles& triangles, Index num_vertices,
                                CornerParts parts = CornerParts::Corners);

/// Vertex-connected components of `triangles` over `num_vertices` vertices.
struct ComponentLabels {
  std::vector<Index> vertex_component;  ///< #V, component id in [0, count); ids follow the smallest vertex
  Index count = 0;                      ///< number of components (an unreferenced vertex is one)
};

/// Components of the graph whose nodes are the vertices and whose edges are
/// the triangle edges. Indices must lie in [0, num_vertices).
ComponentLabels connected_components(const Triangles& triangles, Index num_vertices);

}  // namespace reebkit

// The high level Reeb graph by discrete level-line propagation (Tierny et al.
// 2006, section 4.2, Definitions 6-9): f is propagated from its global
// minimum, vertex by vertex in (f, vertex id) order, and the graph records how
// the level lines of the propagation front split (bifurcation), merge
// (junction) and vanish (termination). The graph is the paper's *dual* Reeb
// graph: a node per connected region swept between two events, an edge where
// a region hands over to the next.
//
// Two definitions of a level line (LevelLines): by default the connected
// curves of the front, the level set of the piecewise-linear function
// between the visited and the unvisited vertices, joined through the
// triangles it crosses (contour_lines.h), which gives a closed surface of
// genus g exactly g independent cycles; or Definition 6 as the paper states
// it, the connected sets of candidate vertices, where two curves that pass
// within one edge of each other are one line.
#pragma once

#include "reebkit/core/mesh.h"
#include "reebkit/mesh/mesh_graph.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace reebkit {

/// The event that starts or ends a node's region.
enum class NodeType : std::uint8_t {
  Root,         ///< the region grown from the global minimum of f (starts only)
  Bifurcation,  ///< eq. (9): a level line split
  Junction,     ///< eq. (10): level lines merged
  Termination   ///< eq. (11): a level line vanished (ends only: the node is a leaf)
};

/// "root", "bifurcation", "junction" or "termination".
const char* node_type_name(NodeType type);

/// One region of the segmentation: the vertices absorbed by one level line
/// between two events. The vertex v_t of an event belongs to the region that
/// ends there. A line may merge into a junction before any vertex of it was
/// absorbed; its node then has no vertices: vertex_count = 0, area = 0, and
/// the f range and barycenter of birth_vertex.
struct ReebNode {
  /// How the region starts: Root, or the Bifurcation / Junction whose new
  /// line it is. A line born at a step that both split and merged lines is a
  /// Junction when several old lines flow into it, else a Bifurcation.
  NodeType type = NodeType::Root;
  /// How the region ends: Bifurcation (its line split, or fed several new
  /// lines at a step that also merged lines), Junction (its line merged with
  /// others into one) or Termination.
  NodeType end = NodeType::Termination;
  /// v_t of the step that created the node (the global minimum for the root).
  Index birth_vertex = kInvalidIndex;
  double fq_min = 0.0;  ///< smallest f over the region's vertices
  double fq_max = 0.0;  ///< largest f over the region's vertices
  Index vertex_count = 0;
  /// Sum over the region's vertices of one third of the area of each incident
  /// triangle.
  double area = 0.0;
  /// Area-weighted Euclidean barycenter of the region's vertices, where the
  /// node is immersed (section 5.2).
  Vec3 barycenter = Vec3::Zero();
  /// The node's part of the topological skeleton (section 5.2, figure 10a):
  /// the Euclidean barycenter (mean position) of its level line, from the
  /// line born at the node's event to the line just before the event that
  /// ends it. Thinned along f (see ReebOptions::skeleton_levels): the line at
  /// its birth, after each step whose f(v_t) enters a new level, and before
  /// its end unless the previous point already shows it. A termination's
  /// last point is the vertex where its line vanished.
  std::vector<Vec3> skeleton;
};

/// The dual Reeb graph and the segmentation it induces.
struct ReebGraph {
  /// Nodes in creation order (node 0 is the root); a node's id is its index.
  /// The new lines of one step get their nodes in the order of their first
  /// vertex in v_t's one-ring (MeshGraph order).
  std::vector<ReebNode> nodes;
  /// (earlier node, later node): the region of the first hands over to the
  /// second at the event ending the first. Sorted, no duplicates.
  std::vector<std::array<Index, 2>> edges;
  /// #V: the node of the level line that absorbed each vertex (the segmentation).
  std::vector<Index> vertex_node;

  Index num_nodes() const { return static_cast<Index>(nodes.size()); }
  Index num_edges() const { return static_cast<Index>(edges.size()); }
  /// Connected components of the graph.
  Index connected_components() const;
  /// First Betti number: #edges - #nodes + #components. Equals the genus of
  /// a closed orientable surface when every handle shows up as a split and
  /// a later merge of level lines.
  Index independent_cycles() const;
  /// Leaves: the nodes whose region ends in a termination (eq. 11), one per
  /// local maximum of f reached by its own level line.
  Index leaf_count() const;
};

/// What a discrete level line is.
enum class LevelLines : std::uint8_t {
  /// A connected curve of the propagation front: the front crosses every
  /// edge between a visited and an unvisited vertex, and two crossings are
  /// on one curve when a triangle joins them (the level set of the
  /// piecewise-linear function that is 0 on visited, 1 on unvisited vertices).
  /// A candidate vertex touched by two curves belongs to both.
  Contour,
  /// Definition 6: a connected set of candidate vertices C(t).
  Paper
};

/// "contour" or "paper".
const char* level_lines_name(LevelLines lines);
/// Inverse of level_lines_name; throws InvalidArgument naming the accepted values.
LevelLines parse_level_lines(const std::string& name);

/// Which terminations of the propagation end a leaf (pit_cancellation.h).
enum class Leaves : std::uint8_t {
  /// Those at a local maximum of f (eq. 11): a termination whose region
  /// holds none, where the front closed around vertices it had passed
  /// above (a pit), is cancelled with the split that made it.
  Maxima,
  /// Every termination of the propagation, pits too.
  Propagation
};

/// "maxima" or "propagation".
const char* leaves_name(Leaves leaves);
/// Inverse of leaves_name; throws InvalidArgument naming the accepted values.
Leaves parse_leaves(const std::string& name);

struct ReebOptions {
  /// The level lines whose evolution the graph records (default: the
  /// contours of the front, exact topology; Paper: Definition 6).
  LevelLines level_lines = LevelLines::Contour;
  /// Which terminations end a leaf (default: those at a maximum of f).
  Leaves leaves = Leaves::Maxima;
  /// false (default): the graph must be connected, as f_q needs; a
  /// propagation that leaves vertices unreached throws InvalidArgument.
  /// true: one root per connected component, each started at the
  /// component's minimum (components in the order of their minima).
  bool all_components = false;
  /// Thinning of the skeleton: the range of f is split into this many equal
  /// levels (default 100), and a level line adds a point to its node's
  /// skeleton only at the first step of each level it absorbs a vertex in
  /// (plus its birth and end). A node spanning a fraction s of the range of f
  /// gets about s * skeleton_levels + 2 points. Must be >= 1.
  Index skeleton_levels = 100;
};

/// The dual Reeb graph of f by discrete level-line propagation from the
/// global minimum of f, vertices compared by (value, vertex id). The level
/// lines (options.level_lines) are kept up to date incrementally: lines
/// meeting at v_t are merged by relabelling the smaller one, and a line can
/// only split where v_t left it, which breadth-first searches started from
/// the arcs around v_t settle in time proportional to all but the largest
/// piece. O(n log n) in practice. Gives exactly the graph of
/// reference_reeb_graph (reeb_reference.h).
/// \pre mesh, graph and f describe the same non-empty vertex set and f is
///      finite; throws InvalidArgument otherwise.
ReebGraph build_reeb_graph(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                           const ReebOptions& options = {});

}  // namespace reebkit

// The bookkeeping both Reeb graph builders share (reeb_graph.h for the fast
// one, reeb_reference.h for the paper's O(n^2) one): turning the level-line
// changes of each propagation step into nodes and edges of the dual Reeb graph
// (Tierny et al. 2006, Definitions 7-9), and the region attributes of section
// 5.2 once every vertex is labeled. The builders only have to say, at each
// step, which lines changed into which.
#pragma once

#include "reebkit/reeb/reeb_graph.h"

#include <array>
#include <cstdint>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace reebkit {

/// Where a vertex stands in the propagation.
enum class VertexState : std::uint8_t { Unvisited, Candidate, Visited };

/// The candidate set C(t) as a binary heap keyed by (f, vertex id): the
/// propagation absorbs its smallest vertex next.
using CandidateQueue =
    std::priority_queue<std::pair<double, Index>, std::vector<std::pair<double, Index>>, std::greater<>>;

/// Throws InvalidArgument (message starting with `who`) unless `mesh`,
/// `graph` and `f` describe the same non-empty vertex set, f is finite and
/// options.skeleton_levels >= 1.
void check_reeb_inputs(const char* who, const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                       const ReebOptions& options);

/// The vertex of smallest (f, id).
Index global_minimum(const std::vector<double>& f);

/// How the level lines touched by one step changed. The other lines are
/// unchanged and keep their nodes.
struct LineChange {
  /// Nodes of the old lines that changed: the line of v_t first, then the
  /// lines merged into it through v_t's new candidate neighbours.
  std::vector<Index> old_nodes;
  /// Number of new lines (those holding a neighbour of v_t), in the order of
  /// their first vertex in v_t's one-ring.
  Index new_lines = 0;
  /// (index into old_nodes, index of a new line): the new line holds vertices
  /// of the old one, or (for old line 0) of v_t's neighbourhood.
  std::vector<std::array<Index, 2>> links;
  /// Skeleton points: the barycenter (mean position) of each old line before
  /// the step, in the order of old_nodes, and of each new line after it.
  std::vector<Vec3> old_centers;
  std::vector<Vec3> new_centers;
  /// The independent cycles the step closes when known, else -1. A
  /// degenerate saddle (v_t's visited neighbours in m > 2 arcs around it) is
  /// m - 1 simple saddles at once, each a split or a merge, and only the
  /// count of merges tells how many cycles it closes: an old line that
  /// splits and merges again at v_t continues as one line but closes a cycle.
  Index cycles = -1;

  void clear() {
    old_nodes.clear();
    new_lines = 0;
    links.clear();
    old_centers.clear();
    new_centers.clear();
    cycles = -1;
  }
};

/// Records the dual Reeb graph and its skeleton while the level lines evolve.
class DualGraphRecorder {
 public:
  /// Keeps references to `mesh` and `f`, which must outlive the recorder.
  DualGraphRecorder(const Mesh& mesh, const std::vector<double>& f, const ReebOptions& options);

  /// Creates the root node of a propagation starting at `minimum`, its
  /// skeleton starting at the minimum.
  Index start_root(Index minimum);

  /// Labels v_t with the node of the line that absorbed it.
  void absorb(Index v, Index node) { graph_.vertex_node[static_cast<std::size_t>(v)] = node; }

  /// Applies the change of step v_t and returns the node of each new line in
  /// `new_nodes`. One old line becoming one new line and closing no cycle is
  /// no event: the line keeps its node. No new line is a termination (eq.
  /// 11). Otherwise every old node ends and every new line starts a node
  /// linked from its old ones: a bifurcation (eq. 9) when one old line feeds
  /// it, a junction (eq. 10) when several do. When those links would close
  /// another number of cycles than change.cycles (a degenerate saddle), the
  /// step is unfolded instead: the old nodes join in one node at v_t without
  /// vertices, then each cycle is one split into two such nodes and their
  /// merge, and the last feeds every new line. Skeletons: an ending node gets
  /// its line's last position, a new node starts at its line's, a node of an
  /// unfolded saddle is the mean of the new lines' positions, and a line that
  /// is no event adds a point when f(v) enters a new level
  /// (ReebOptions::skeleton_levels).
  void step(Index v, const LineChange& change, std::vector<Index>& new_nodes);

  /// Step v_t that is no event for the line of `node` (one old line becoming
  /// one new line, closing no cycle): the line keeps its node, and its
  /// skeleton gets center() (the line after the step) when f(v) enters a
  /// new level; center is called only then.
  template <typename Center>
  void continue_line(Index v, Index node, Center&& center) {
    const Index level = level_of(v);
    const auto n = static_cast<std::size_t>(node);
    if (level > last_level_[n])
      sample(node, center(), level);
    else
      line_shown_[n] = 0;
  }

  /// The finished graph: node attributes from the segmentation, edges sorted.
  /// \pre every vertex has been absorbed.
  ReebGraph finish();

 private:
  Index add_node(NodeType type, Index birth_vertex);
  /// Adds the edge from `from` to `to` and updates how `from` ends.
  void link(Index from, Index to);
  /// The nodes of a degenerate saddle at v (see step), ending in `new_nodes`.
  void unfold(Index v, Index level, const LineChange& change, std::vector<Index>& new_nodes);
  /// The level of f(v) among ReebOptions::skeleton_levels equal parts of the range of f.
  Index level_of(Index v) const;
  /// Appends a skeleton point to `node`: its line as it is now.
  void sample(Index node, const Vec3& center, Index level);

  const Mesh& mesh_;
  const std::vector<double>& f_;
  Index levels_;
  double f_min_ = 0.0;
  double level_scale_ = 0.0;  // levels per unit of f (0 when f is constant)
  ReebGraph graph_;
  std::vector<Index> parents_;  // per new line of the current step
  // Per node: level of its last skeleton point, and whether that point still
  // shows the line (it has not changed since).
  std::vector<Index> last_level_;
  std::vector<std::uint8_t> line_shown_;
};

}  // namespace reebkit

// Level lines as the connected curves of the propagation front
// (LevelLines::Contour, reeb_graph.h): the front is the level set, between 0
// and 1, of the piecewise-linear function that is 0 on the visited vertices
// and 1 on the others. It crosses the triangles with both visited and
// unvisited corners (the front triangles), one segment each, and two front
// triangles are on one curve when they share an edge the front crosses. A
// line is a set of front triangles; a candidate vertex touched by two curves
// (where Definition 6 would see one line) belongs to both.
//
// Absorbing v_t changes only the triangles around v_t, so only the lines
// through them change: FrontStar describes a step from v_t's triangles for
// both builders, the incremental ContourLevelLines (build_reeb_graph) and
// the per-step rebuild of reeb_reference.cpp.
#pragma once

#include "reebkit/core/mesh.h"
#include "reebkit/mesh/mesh_graph.h"
#include "reebkit/reeb/dual_graph_recorder.h"
#include "reebkit/reeb/level_line_lists.h"
#include "reebkit/reeb/line_split.h"

#include <algorithm>
#include <array>
#include <vector>

namespace reebkit {

/// The triangles around each vertex (CSR): those of v are
/// triangle[offset[v] .. offset[v+1]), in increasing order.
struct VertexTriangles {
  std::vector<Index> offset;    ///< #V + 1
  std::vector<Index> triangle;  ///< 3 #F
};

VertexTriangles vertex_triangles(const Mesh& mesh);

/// True when one corner of triangle t is visited and another is not.
bool on_front(const Mesh& mesh, const std::vector<VertexState>& state, Index t);

/// Calls visit(u) for every front triangle u that shares with front triangle
/// t an edge the front crosses (every such triangle, at a non-manifold edge).
template <typename Visit>
void for_each_front_neighbour(const Mesh& mesh, const VertexTriangles& around, const std::vector<VertexState>& state,
                              Index t, Visit&& visit) {
  const auto visited = [&state](Index v) { return state[static_cast<std::size_t>(v)] == VertexState::Visited; };
  for (int k = 0; k < 3; ++k) {
    const Index p = mesh.triangles(t, k);
    const Index q = mesh.triangles(t, (k + 1) % 3);
    if (visited(p) == visited(q)) continue;
    for (Index i = around.offset[static_cast<std::size_t>(p)]; i < around.offset[static_cast<std::size_t>(p) + 1];
         ++i) {
      const Index u = around.triangle[static_cast<std::size_t>(i)];
      if (u != t && (mesh.triangles(u, 0) == q || mesh.triangles(u, 1) == q || mesh.triangles(u, 2) == q)) visit(u);
    }
  }
}

/// One propagation step seen from the triangles around v_t: which of them
/// are on the front before and after v_t is visited, and in which lines.
/// A builder calls, in order: collect (v_t still unvisited), sets old_line of
/// the entries on the front before, settle_old; visits v_t and updates its
/// lines; then sets new_line of the entries on the front after, settle_new.
class FrontStar {
 public:
  struct Entry {
    Index triangle = kInvalidIndex;
    bool before = false;  ///< on the front before v_t is visited
    bool after = false;   ///< on the front after
    Index old_line = kInvalidIndex;
    Index new_line = kInvalidIndex;
  };

  /// The triangles around v (unvisited yet), whether each is on the front
  /// before and after v is visited, and the Euler characteristic of the part
  /// of v's star that visiting v adds to the visited region.
  void collect(const Mesh& mesh, const MeshGraph& graph, const VertexTriangles& around,
               const std::vector<VertexState>& state, Index v);

  std::vector<Entry>& entries() { return entries_; }

  /// True when the step is no event whatever the lines: v's ring is closed
  /// and its visited neighbours form one arc (so one line enters v's
  /// triangles and one leaves them, the same).
  bool regular() const { return closed_ring_ && euler_drop_ == 0; }

  /// The old lines: those of the entries on the front, in entry order, or
  /// `root_line` alone when there are none (v is where a propagation starts).
  /// Appends their nodes and centers to `change`.
  template <typename NodeOf, typename CenterOf>
  void settle_old(Index root_line, LineChange& change, NodeOf&& node_of, CenterOf&& center_of) {
    old_lines_.clear();
    for (const Entry& e : entries_)
      if (e.before && index_of(old_lines_, e.old_line) == kInvalidIndex) old_lines_.push_back(e.old_line);
    if (old_lines_.empty()) old_lines_.push_back(root_line);
    for (const Index line : old_lines_) {
      change.old_nodes.push_back(node_of(line));
      change.old_centers.push_back(center_of(line));
    }
  }
  const std::vector<Index>& old_lines() const { return old_lines_; }

  /// One entry per arc of front triangles around v (after): triangles that
  /// share an edge from v to an unvisited vertex are on one arc.
  const std::vector<Index>& arc_triangles(const Mesh& mesh, const std::vector<VertexState>& state);

  /// The new lines (those of the entries on the front after, in entry
  /// order), the links from the old lines (an old line feeds the new lines
  /// its triangles around v are in; one that feeds none ends there; a new
  /// line no old line feeds is fed by the first old line) and the cycles
  /// the step closes when v's ring is closed.
  template <typename CenterOf>
  void settle_new(LineChange& change, CenterOf&& center_of) {
    new_lines_.clear();
    for (const Entry& e : entries_)
      if (e.after && index_of(new_lines_, e.new_line) == kInvalidIndex) new_lines_.push_back(e.new_line);
    change.new_lines = static_cast<Index>(new_lines_.size());
    for (const Index line : new_lines_) change.new_centers.push_back(center_of(line));
    const bool start = entries_before() == 0;
    for (const Entry& e : entries_)
      if (e.before && e.after) add_link(change, index_of(old_lines_, e.old_line), index_of(new_lines_, e.new_line));
    // A new line no old line feeds (a fan of v that was off the front) is fed
    // by the first old line.
    for (Index n = 0; n < change.new_lines; ++n)
      if (std::none_of(change.links.begin(), change.links.end(),
                       [n](const std::array<Index, 2>& l) { return l[1] == n; }))
        add_link(change, 0, n);
    // Visiting v changes the Euler characteristic of the visited region by
    // 1 - (edges) + (triangles) of the star part it adds, the number of
    // front curves by new - old; on an orientable surface every simple
    // saddle changes one of the two, and merges close cycles (the region's
    // genus is (2 - chi - curves) / 2).
    if (closed_ring_ && !start) {
      const Index twice = euler_drop_ + static_cast<Index>(old_lines_.size()) - change.new_lines;
      if (twice >= 0 && twice % 2 == 0) change.cycles = twice / 2;
    }
  }
  const std::vector<Index>& new_lines() const { return new_lines_; }

 private:
  static Index index_of(const std::vector<Index>& lines, Index line) {
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i] == line) return static_cast<Index>(i);
    return kInvalidIndex;
  }
  static void add_link(LineChange& change, Index old_index, Index new_index) {
    const std::array<Index, 2> link = {old_index, new_index};
    if (std::find(change.links.begin(), change.links.end(), link) == change.links.end()) change.links.push_back(link);
  }
  Index entries_before() const;

  Index v_ = kInvalidIndex;
  std::vector<Entry> entries_;
  std::vector<Index> old_lines_;
  std::vector<Index> new_lines_;
  std::vector<Index> arcs_;
  std::vector<Index> arc_parent_;
  bool closed_ring_ = false;
  Index euler_drop_ = 0;  ///< minus the change of the Euler characteristic
};

/// The level lines of LevelLines::Contour, kept up to date as the
/// propagation absorbs one vertex after the other: a line is a list of front
/// triangles (level_line_lists.h), its points the unvisited corners of its
/// triangles (a candidate vertex counts once per front triangle of the line
/// it is a corner of).
class ContourLevelLines {
 public:
  ContourLevelLines(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                    DualGraphRecorder& recorder);

  /// Propagates from `minimum` over its whole connected component.
  void propagate_from(Index minimum);

  bool visited(Index v) const { return state_[static_cast<std::size_t>(v)] == VertexState::Visited; }
  Index visited_count() const { return visited_count_; }

 private:
  static std::size_t at(Index i) { return static_cast<std::size_t>(i); }
  /// Front triangle t joins `line`, or leaves its line, with its unvisited corners.
  void attach(Index line, Index t);
  void detach(Index t);
  void absorb(Index v);
  /// Visits v: its triangles leave the front or join it in `line` (every old
  /// line through v merged), its unvisited neighbours are queued.
  void visit(Index v, Index line);

  const Mesh& mesh_;
  const MeshGraph& graph_;
  const std::vector<double>& f_;
  DualGraphRecorder& recorder_;
  VertexTriangles around_;
  CandidateQueue queue_;
  std::vector<VertexState> state_;  // Candidate: queued
  Index visited_count_ = 0;
  Index root_line_ = kInvalidIndex;
  LevelLineLists lines_;  // over the triangles
  // Buffers of one step.
  FrontStar star_;
  LineChange change_;
  std::vector<Index> new_nodes_;
  LineSplitter splitter_;
};

}  // namespace reebkit

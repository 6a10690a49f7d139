#include "reebkit/reeb/reeb_graph.h"

#include "reebkit/core/error.h"
#include "reebkit/core/named_values.h"
#include "reebkit/features/critical_points.h"
#include "reebkit/reeb/contour_lines.h"
#include "reebkit/reeb/dual_graph_recorder.h"
#include "reebkit/reeb/level_line_lists.h"
#include "reebkit/reeb/line_split.h"
#include "reebkit/reeb/pit_cancellation.h"

#include <algorithm>
#include <numeric>

namespace reebkit {

const char* node_type_name(NodeType type) {
  switch (type) {
    case NodeType::Root: return "root";
    case NodeType::Bifurcation: return "bifurcation";
    case NodeType::Junction: return "junction";
    case NodeType::Termination: return "termination";
  }
  return "unknown";
}

namespace {
constexpr NamedValues<LevelLines, 2> kLevelLinesNames{"level lines",
                                                      {{{LevelLines::Contour, "contour"},
                                                        {LevelLines::Paper, "paper"}}}};
constexpr NamedValues<Leaves, 2> kLeavesNames{"leaves",
                                              {{{Leaves::Maxima, "maxima"}, {Leaves::Propagation, "propagation"}}}};
}  // namespace

const char* level_lines_name(LevelLines lines) { return kLevelLinesNames.name(lines); }

LevelLines parse_level_lines(const std::string& name) { return kLevelLinesNames.parse(name); }

const char* leaves_name(Leaves leaves) { return kLeavesNames.name(leaves); }

Leaves parse_leaves(const std::string& name) { return kLeavesNames.parse(name); }

Index ReebGraph::connected_components() const {
  std::vector<Index> parent(nodes.size());
  std::iota(parent.begin(), parent.end(), Index{0});
  const auto find = [&parent](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  Index components = num_nodes();
  for (const auto& [a, b] : edges) {
    const Index ra = find(a);
    const Index rb = find(b);
    if (ra != rb) {
      parent[ra] = rb;
      --components;
    }
  }
  return components;
}

Index ReebGraph::independent_cycles() const { return num_edges() - num_nodes() + connected_components(); }

Index ReebGraph::leaf_count() const {
  return static_cast<Index>(
      std::count_if(nodes.begin(), nodes.end(), [](const ReebNode& n) { return n.end == NodeType::Termination; }));
}

namespace {

/// The level lines of C(t) (LevelLines::Paper), kept up to date as the
/// propagation absorbs one vertex after the other: a line is a list of
/// candidate vertices (level_line_lists.h), its points its vertices.
class IncrementalLevelLines {
 public:
  IncrementalLevelLines(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                        DualGraphRecorder& recorder)
      : graph_(graph),
        f_(f),
        recorder_(recorder),
        state_(f.size(), VertexState::Unvisited),
        lines_(mesh, static_cast<Index>(f.size())) {}

  /// Propagates from `minimum` over its whole connected component.
  void propagate_from(Index minimum) {
    // C starts as the minimum alone: one line, the root's.
    enter(minimum, lines_.new_line(recorder_.start_root(minimum)));
    while (!queue_.empty()) {
      const Index v = queue_.top().second;
      queue_.pop();
      absorb(v);
    }
  }

  bool visited(Index v) const { return state_[at(v)] == VertexState::Visited; }
  Index visited_count() const { return visited_count_; }

 private:
  static std::size_t at(Index i) { return static_cast<std::size_t>(i); }

  bool candidate(Index v) const { return state_[at(v)] == VertexState::Candidate; }

  /// Candidate v joins `line`, or leaves its line.
  void attach(Index line, Index v) {
    lines_.link(line, v);
    lines_.add_point(line, v, +1);
  }
  void detach(Index v) {
    lines_.add_point(lines_.line_of(v), v, -1);
    lines_.unlink(v);
  }

  /// v joins C(t) in `line`.
  void enter(Index v, Index line) {
    state_[at(v)] = VertexState::Candidate;
    attach(line, v);
    queue_.emplace(f_[at(v)], v);
  }

  /// The index of `line` among the new lines of the step (slot_ grows with the line ids).
  Index& slot(Index line) {
    if (slot_.size() <= at(line)) slot_.resize(at(line) + 1, kInvalidIndex);
    return slot_[at(line)];
  }

  /// Step t: v_t leaves C, its unvisited neighbours enter it.
  void absorb(Index v) {
    Index line = lines_.line_of(v);
    const Index node = lines_.node(line);
    recorder_.absorb(v, node);
    change_.clear();
    change_.old_nodes.push_back(node);
    change_.old_centers.push_back(lines_.center(line));
    detach(v);
    state_[at(v)] = VertexState::Visited;
    ++visited_count_;
    merged_from_.clear();

    // The new candidates join v's line; every other line they touch merges
    // into it (remembering one of its vertices to find where it ends up).
    entered_.clear();
    const Index begin = graph_.offset[at(v)];
    const Index end = graph_.offset[at(v) + 1];
    for (Index i = begin; i < end; ++i) {
      const Index w = graph_.neighbor[at(i)];
      if (state_[at(w)] != VertexState::Unvisited) continue;
      enter(w, line);
      entered_.push_back(w);
    }
    for (const Index w : entered_) {
      for (Index i = graph_.offset[at(w)]; i < graph_.offset[at(w) + 1]; ++i) {
        const Index u = graph_.neighbor[at(i)];
        if (!candidate(u) || lines_.line_of(u) == line) continue;
        change_.old_nodes.push_back(lines_.node(lines_.line_of(u)));
        change_.old_centers.push_back(lines_.center(lines_.line_of(u)));
        merged_from_.push_back(u);
        line = lines_.merge(line, lines_.line_of(u));
        lines_.set_node(line, node);
      }
    }

    split_at(v, line);

    // The new lines are those holding a neighbour of v, in one-ring order.
    new_lines_.clear();
    for (Index i = begin; i < end; ++i) {
      const Index w = graph_.neighbor[at(i)];
      if (!candidate(w)) continue;
      const Index l = lines_.line_of(w);
      if (slot(l) != kInvalidIndex) continue;
      slot(l) = static_cast<Index>(new_lines_.size());
      change_.links.push_back({0, slot(l)});
      change_.new_centers.push_back(lines_.center(l));
      new_lines_.push_back(l);
    }
    change_.new_lines = static_cast<Index>(new_lines_.size());
    for (std::size_t k = 0; k < merged_from_.size(); ++k)
      change_.links.push_back({static_cast<Index>(k + 1), slot(lines_.line_of(merged_from_[k]))});
    recorder_.step(v, change_, new_nodes_);
    for (std::size_t k = 0; k < new_lines_.size(); ++k) {
      lines_.set_node(new_lines_[k], new_nodes_[k]);
      slot(new_lines_[k]) = kInvalidIndex;
    }
    if (new_lines_.empty()) lines_.free_line(line);  // termination: the line is empty
  }

  /// Splits `line`, which v just left, into its connected components. Each
  /// component holds a neighbour of v, and neighbours consecutive around v
  /// (sharing a triangle with it) stay connected: one search per arc of
  /// candidate neighbours around v (line_split.h).
  void split_at(Index v, Index line) {
    seeds_.clear();
    const Index begin = graph_.offset[at(v)];
    const Index end = graph_.offset[at(v) + 1];
    const auto candidate_at = [&](Index i) { return candidate(graph_.neighbor[at(i)]); };
    bool any = false;
    for (Index i = begin; i < end; ++i) {
      if (!candidate_at(i)) continue;
      any = true;
      // The slot before i around v; link_next[end - 1] is set for closed rings only.
      const Index p = i > begin ? i - 1 : end - 1;
      if (p == i || !candidate_at(p) || graph_.link_next[at(p)] == 0) seeds_.push_back(graph_.neighbor[at(i)]);
    }
    if (any && seeds_.empty()) seeds_.push_back(graph_.neighbor[at(begin)]);  // the whole ring is one arc
    const auto& pieces = splitter_.split(
        seeds_, [this](Index u) -> Index& { return lines_.search(u); },
        [this](Index u, auto&& visit) {
          for (Index i = graph_.offset[at(u)]; i < graph_.offset[at(u) + 1]; ++i) {
            const Index w = graph_.neighbor[at(i)];
            if (candidate(w)) visit(w);
          }
        });
    for (const std::vector<Index>& piece : pieces) {
      const Index moved = lines_.new_line(lines_.node(line));
      for (const Index u : piece) {
        detach(u);
        attach(moved, u);
      }
    }
  }

  const MeshGraph& graph_;
  const std::vector<double>& f_;
  DualGraphRecorder& recorder_;
  CandidateQueue queue_;
  std::vector<VertexState> state_;
  Index visited_count_ = 0;
  LevelLineLists lines_;
  std::vector<Index> slot_;  // per line id: index among the new lines of the current step, else kInvalidIndex
  // Buffers of one step.
  LineChange change_;
  std::vector<Index> new_nodes_;
  std::vector<Index> entered_;
  std::vector<Index> merged_from_;
  std::vector<Index> new_lines_;
  std::vector<Index> seeds_;
  LineSplitter splitter_;
};

}  // namespace

namespace {

/// Propagates with `Lines` (IncrementalLevelLines or ContourLevelLines) from
/// the global minimum, then from the next unvisited minimum of each further
/// component when options.all_components allows.
template <typename Lines>
ReebGraph propagate(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                    const ReebOptions& options) {
  DualGraphRecorder recorder(mesh, f, options);
  Lines lines(mesh, graph, f, recorder);
  lines.propagate_from(global_minimum(f));
  if (lines.visited_count() < mesh.num_vertices()) {
    if (!options.all_components)
      throw InvalidArgument("build_reeb_graph: the mesh graph is not connected (see ReebOptions::all_components)");
    // The next root is the smallest unvisited vertex by (f, id).
    std::vector<Index> order(f.size());
    std::iota(order.begin(), order.end(), Index{0});
    std::sort(order.begin(), order.end(), [&f](Index a, Index b) { return sos_less(f, a, b); });
    for (const Index v : order)
      if (!lines.visited(v)) lines.propagate_from(v);
  }
  return recorder.finish();
}

}  // namespace

ReebGraph build_reeb_graph(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                           const ReebOptions& options) {
  check_reeb_inputs("build_reeb_graph", mesh, graph, f, options);
  ReebGraph reeb = options.level_lines == LevelLines::Paper ? propagate<IncrementalLevelLines>(mesh, graph, f, options)
                                                            : propagate<ContourLevelLines>(mesh, graph, f, options);
  return options.leaves == Leaves::Maxima ? cancel_pits(std::move(reeb), graph, f) : reeb;
}

}  // namespace reebkit

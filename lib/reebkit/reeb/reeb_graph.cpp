#include "reebkit/reeb/reeb_graph.h"

#include "reebkit/core/error.h"
#include "reebkit/features/critical_points.h"
#include "reebkit/reeb/contour_lines.h"
#include "reebkit/reeb/dual_graph_recorder.h"
#include "reebkit/reeb/line_split.h"

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

const char* level_lines_name(LevelLines lines) {
  switch (lines) {
    case LevelLines::Contour: return "contour";
    case LevelLines::Paper: return "paper";
  }
  throw InvalidArgument("level_lines_name: unknown definition " + std::to_string(static_cast<int>(lines)));
}

LevelLines parse_level_lines(const std::string& name) {
  for (const LevelLines lines : {LevelLines::Contour, LevelLines::Paper})
    if (name == level_lines_name(lines)) return lines;
  throw InvalidArgument("unknown level lines '" + name + "' (expected contour or paper)");
}

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

/// The level lines of C(t), kept up to date as the propagation absorbs one
/// vertex after the other. A line is a doubly-linked list of its vertices
/// threaded through one flat array of per-vertex records, which also hold the
/// vertex's line id; line ids are recycled. Each line also keeps the sum of
/// its vertices' positions (relative to the center of the mesh's bounding
/// box, to keep the sums small) for its skeleton point.
class IncrementalLevelLines {
 public:
  IncrementalLevelLines(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                        DualGraphRecorder& recorder)
      : mesh_(mesh),
        graph_(graph),
        f_(f),
        recorder_(recorder),
        origin_(0.5 * (mesh.vertices.colwise().minCoeff() + mesh.vertices.colwise().maxCoeff()).transpose()),
        vertex_(f.size()) {}

  /// Propagates from `minimum` over its whole connected component.
  void propagate_from(Index minimum) {
    // C starts as the minimum alone: one line, the root's.
    enter(minimum, new_line(recorder_.start_root(minimum)));
    while (!queue_.empty()) {
      const Index v = queue_.top().second;
      queue_.pop();
      absorb(v);
    }
  }

  bool visited(Index v) const { return vertex_[at(v)].state == VertexState::Visited; }
  Index visited_count() const { return visited_count_; }

 private:
  static std::size_t at(Index i) { return static_cast<std::size_t>(i); }

  Index new_line(Index node) {
    Index line;
    if (free_lines_.empty()) {
      line = static_cast<Index>(head_.size());
      head_.push_back(kInvalidIndex);
      size_.push_back(0);
      sum_.push_back(Vec3::Zero());
      node_.push_back(node);
      slot_.push_back(kInvalidIndex);
    } else {
      line = free_lines_.back();
      free_lines_.pop_back();
      sum_[at(line)].setZero();  // drop the rounding left by its previous vertices
      node_[at(line)] = node;
    }
    return line;
  }

  Vec3 position(Index v) const { return mesh_.vertices.row(v).transpose() - origin_; }

  /// The barycenter of the line's vertices.
  Vec3 center(Index line) const { return origin_ + sum_[at(line)] / size_[at(line)]; }

  void link(Index line, Index v) {
    vertex_[at(v)].line = line;
    vertex_[at(v)].prev = kInvalidIndex;
    vertex_[at(v)].next = head_[at(line)];
    if (head_[at(line)] != kInvalidIndex) vertex_[at(head_[at(line)])].prev = v;
    head_[at(line)] = v;
    ++size_[at(line)];
    sum_[at(line)] += position(v);
  }

  void unlink(Index line, Index v) {
    const Index p = vertex_[at(v)].prev;
    const Index n = vertex_[at(v)].next;
    (p == kInvalidIndex ? head_[at(line)] : vertex_[at(p)].next) = n;
    if (n != kInvalidIndex) vertex_[at(n)].prev = p;
    --size_[at(line)];
    sum_[at(line)] -= position(v);
  }

  /// v joins C(t) in `line`.
  void enter(Index v, Index line) {
    vertex_[at(v)].state = VertexState::Candidate;
    link(line, v);
    queue_.emplace(f_[at(v)], v);
  }

  /// Merges lines a and b by relabelling the smaller; returns the survivor.
  Index merge(Index a, Index b) {
    if (size_[at(a)] < size_[at(b)]) std::swap(a, b);
    Index tail = kInvalidIndex;
    for (Index u = head_[at(b)]; u != kInvalidIndex; u = vertex_[at(u)].next) {
      vertex_[at(u)].line = a;
      tail = u;
    }
    vertex_[at(tail)].next = head_[at(a)];
    vertex_[at(head_[at(a)])].prev = tail;
    head_[at(a)] = head_[at(b)];
    size_[at(a)] += size_[at(b)];
    sum_[at(a)] += sum_[at(b)];
    head_[at(b)] = kInvalidIndex;
    size_[at(b)] = 0;
    free_lines_.push_back(b);
    return a;
  }

  /// Step t: v_t leaves C, its unvisited neighbours enter it.
  void absorb(Index v) {
    Index line = vertex_[at(v)].line;
    const Index node = node_[at(line)];
    recorder_.absorb(v, node);
    change_.clear();
    change_.old_nodes.push_back(node);
    change_.old_centers.push_back(center(line));
    unlink(line, v);
    vertex_[at(v)].state = VertexState::Visited;
    ++visited_count_;
    merged_from_.clear();

    // The new candidates join v's line; every other line they touch merges
    // into it (remembering one of its vertices to find where it ends up).
    entered_.clear();
    const Index begin = graph_.offset[at(v)];
    const Index end = graph_.offset[at(v) + 1];
    for (Index i = begin; i < end; ++i) {
      const Index w = graph_.neighbor[at(i)];
      if (vertex_[at(w)].state != VertexState::Unvisited) continue;
      enter(w, line);
      entered_.push_back(w);
    }
    for (const Index w : entered_) {
      for (Index i = graph_.offset[at(w)]; i < graph_.offset[at(w) + 1]; ++i) {
        const Index u = graph_.neighbor[at(i)];
        if (vertex_[at(u)].state != VertexState::Candidate || vertex_[at(u)].line == line) continue;
        change_.old_nodes.push_back(node_[at(vertex_[at(u)].line)]);
        change_.old_centers.push_back(center(vertex_[at(u)].line));
        merged_from_.push_back(u);
        line = merge(line, vertex_[at(u)].line);
        node_[at(line)] = node;
      }
    }

    split_at(v, line);

    // The new lines are those holding a neighbour of v, in one-ring order.
    new_lines_.clear();
    for (Index i = begin; i < end; ++i) {
      const Index w = graph_.neighbor[at(i)];
      if (vertex_[at(w)].state != VertexState::Candidate) continue;
      const Index l = vertex_[at(w)].line;
      if (slot_[at(l)] != kInvalidIndex) continue;
      slot_[at(l)] = static_cast<Index>(new_lines_.size());
      change_.links.push_back({0, slot_[at(l)]});
      change_.new_centers.push_back(center(l));
      new_lines_.push_back(l);
    }
    change_.new_lines = static_cast<Index>(new_lines_.size());
    for (std::size_t k = 0; k < merged_from_.size(); ++k)
      change_.links.push_back({static_cast<Index>(k + 1), slot_[at(vertex_[at(merged_from_[k])].line)]});
    recorder_.step(v, change_, new_nodes_);
    for (std::size_t k = 0; k < new_lines_.size(); ++k) {
      node_[at(new_lines_[k])] = new_nodes_[k];
      slot_[at(new_lines_[k])] = kInvalidIndex;
    }
    if (new_lines_.empty()) free_lines_.push_back(line);  // termination: the line is empty
  }

  /// Splits `line`, which v just left, into its connected components. Each
  /// component holds a neighbour of v, and neighbours consecutive around v
  /// (sharing a triangle with it) stay connected: one search per arc of
  /// candidate neighbours around v (line_split.h).
  void split_at(Index v, Index line) {
    seeds_.clear();
    const Index begin = graph_.offset[at(v)];
    const Index end = graph_.offset[at(v) + 1];
    const auto candidate = [&](Index i) { return vertex_[at(graph_.neighbor[at(i)])].state == VertexState::Candidate; };
    bool any = false;
    for (Index i = begin; i < end; ++i) {
      if (!candidate(i)) continue;
      any = true;
      // The slot before i around v; link_next[end - 1] is set for closed rings only.
      const Index p = i > begin ? i - 1 : end - 1;
      if (p == i || !candidate(p) || graph_.link_next[at(p)] == 0) seeds_.push_back(graph_.neighbor[at(i)]);
    }
    if (any && seeds_.empty()) seeds_.push_back(graph_.neighbor[at(begin)]);  // the whole ring is one arc
    const auto& pieces = splitter_.split(
        seeds_, [this](Index u) -> Index& { return vertex_[at(u)].search; },
        [this](Index u, auto&& visit) {
          for (Index i = graph_.offset[at(u)]; i < graph_.offset[at(u) + 1]; ++i) {
            const Index w = graph_.neighbor[at(i)];
            if (vertex_[at(w)].state == VertexState::Candidate) visit(w);
          }
        });
    for (const std::vector<Index>& piece : pieces) {
      const Index moved = new_line(node_[at(line)]);
      for (const Index u : piece) {
        unlink(line, u);
        link(moved, u);
      }
    }
  }

  const Mesh& mesh_;
  const MeshGraph& graph_;
  const std::vector<double>& f_;
  DualGraphRecorder& recorder_;
  Vec3 origin_;
  CandidateQueue queue_;
  Index visited_count_ = 0;
  // Per vertex, together as they are used together.
  struct Vertex {
    VertexState state = VertexState::Unvisited;
    Index line = kInvalidIndex;  // of a candidate
    Index next = kInvalidIndex;  // the line's vertex list
    Index prev = kInvalidIndex;
    Index search = -1;  // id of the last split search that reached the vertex
  };
  std::vector<Vertex> vertex_;
  // Per line id.
  std::vector<Index> head_;
  std::vector<Index> size_;
  std::vector<Vec3> sum_;  // of position()
  std::vector<Index> node_;
  std::vector<Index> slot_;  // index among the new lines of the current step, else kInvalidIndex
  std::vector<Index> free_lines_;
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
  return options.level_lines == LevelLines::Paper ? propagate<IncrementalLevelLines>(mesh, graph, f, options)
                                                  : propagate<ContourLevelLines>(mesh, graph, f, options);
}

}  // namespace reebkit

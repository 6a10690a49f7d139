#include "reebkit/reeb/contour_lines.h"

#include <algorithm>
#include <stdexcept>

namespace reebkit {

VertexTriangles vertex_triangles(const Mesh& mesh) {
  VertexTriangles out;
  out.offset.assign(static_cast<std::size_t>(mesh.num_vertices()) + 1, 0);
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) ++out.offset[static_cast<std::size_t>(mesh.triangles(t, k)) + 1];
  for (std::size_t v = 1; v < out.offset.size(); ++v) out.offset[v] += out.offset[v - 1];
  out.triangle.resize(static_cast<std::size_t>(out.offset.back()));
  std::vector<Index> fill(out.offset.begin(), out.offset.end() - 1);
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) out.triangle[static_cast<std::size_t>(fill[static_cast<std::size_t>(mesh.triangles(t, k))]++)] = t;
  return out;
}

bool on_front(const Mesh& mesh, const std::vector<VertexState>& state, Index t) {
  int visited = 0;
  for (int k = 0; k < 3; ++k) visited += state[static_cast<std::size_t>(mesh.triangles(t, k))] == VertexState::Visited;
  return visited == 1 || visited == 2;
}

void FrontStar::collect(const Mesh& mesh, const MeshGraph& graph, const VertexTriangles& around,
                        const std::vector<VertexState>& state, Index v) {
  v_ = v;
  entries_.clear();
  const auto visited = [&state](Index u) { return state[static_cast<std::size_t>(u)] == VertexState::Visited; };
  Index lower_triangles = 0, lower_corners = 0;
  for (Index i = around.offset[static_cast<std::size_t>(v)]; i < around.offset[static_cast<std::size_t>(v) + 1]; ++i) {
    Entry e;
    e.triangle = around.triangle[static_cast<std::size_t>(i)];
    int others_visited = 0;
    for (int k = 0; k < 3; ++k) {
      const Index u = mesh.triangles(e.triangle, k);
      others_visited += u != v && visited(u);
    }
    e.before = others_visited > 0;
    e.after = others_visited < 2;  // visiting v changes no other corner
    lower_triangles += others_visited == 2;
    lower_corners += others_visited;
    entries_.push_back(e);
  }
  // On a closed ring every neighbour is a corner of two triangles around v.
  closed_ring_ = graph.ring[static_cast<std::size_t>(v)] == RingKind::Closed;
  euler_drop_ = lower_corners / 2 - lower_triangles - 1;
}

const std::vector<Index>& FrontStar::arc_triangles(const Mesh& mesh, const std::vector<VertexState>& state) {
  arcs_.clear();
  // A closed ring whose visited neighbours form one arc (m - 1 = 0) has one
  // arc of unvisited ones, or none.
  if (closed_ring_ && euler_drop_ <= 0) {
    for (const Entry& e : entries_)
      if (e.after) {
        arcs_.push_back(e.triangle);
        break;
      }
    return arcs_;
  }
  // Union-find over the entries: two front triangles around v that share an
  // unvisited corner share the edge from v to it.
  const auto n = entries_.size();
  arc_parent_.resize(n);
  for (std::size_t i = 0; i < n; ++i) arc_parent_[i] = static_cast<Index>(i);
  const auto find = [this](Index x) {
    while (arc_parent_[static_cast<std::size_t>(x)] != x)
      x = arc_parent_[static_cast<std::size_t>(x)] =
          arc_parent_[static_cast<std::size_t>(arc_parent_[static_cast<std::size_t>(x)])];
    return x;
  };
  const auto unvisited_corner = [&](std::size_t i, Index w) {
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(entries_[i].triangle, k) == w) return true;
    return false;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!entries_[i].after) continue;
    for (int k = 0; k < 3; ++k) {
      const Index w = mesh.triangles(entries_[i].triangle, k);
      if (w == v_ || state[static_cast<std::size_t>(w)] == VertexState::Visited) continue;
      for (std::size_t j = i + 1; j < n; ++j)
        if (entries_[j].after && unvisited_corner(j, w)) arc_parent_[static_cast<std::size_t>(find(static_cast<Index>(j)))] = find(static_cast<Index>(i));
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (entries_[i].after && find(static_cast<Index>(i)) == static_cast<Index>(i)) arcs_.push_back(entries_[i].triangle);
  return arcs_;
}

Index FrontStar::entries_before() const {
  return static_cast<Index>(std::count_if(entries_.begin(), entries_.end(), [](const Entry& e) { return e.before; }));
}

ContourLevelLines::ContourLevelLines(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                                     DualGraphRecorder& recorder)
    : mesh_(mesh),
      graph_(graph),
      f_(f),
      recorder_(recorder),
      around_(vertex_triangles(mesh)),
      origin_(0.5 * (mesh.vertices.colwise().minCoeff() + mesh.vertices.colwise().maxCoeff()).transpose()),
      state_(f.size(), VertexState::Unvisited),
      triangle_(static_cast<std::size_t>(mesh.num_triangles())) {}

void ContourLevelLines::propagate_from(Index minimum) {
  // The propagation starts with one line, the root's, holding no triangle.
  root_line_ = new_line(recorder_.start_root(minimum));
  state_[at(minimum)] = VertexState::Candidate;
  queue_.emplace(f_[at(minimum)], minimum);
  while (!queue_.empty()) {
    const Index v = queue_.top().second;
    queue_.pop();
    absorb(v);
  }
}

Index ContourLevelLines::new_line(Index node) {
  Index line;
  if (free_lines_.empty()) {
    line = static_cast<Index>(head_.size());
    head_.push_back(kInvalidIndex);
    size_.push_back(0);
    sum_.push_back(Vec3::Zero());
    weight_.push_back(0);
    node_.push_back(node);
  } else {
    line = free_lines_.back();
    free_lines_.pop_back();
    sum_[at(line)].setZero();  // drop the rounding left by its previous triangles
    weight_[at(line)] = 0;
    node_[at(line)] = node;
  }
  return line;
}

void ContourLevelLines::link(Index line, Index t) {
  Triangle& r = triangle_[at(t)];
  r.line = line;
  r.prev = kInvalidIndex;
  r.next = head_[at(line)];
  if (head_[at(line)] != kInvalidIndex) triangle_[at(head_[at(line)])].prev = t;
  head_[at(line)] = t;
  ++size_[at(line)];
  for (int k = 0; k < 3; ++k) {
    const Index u = mesh_.triangles(t, k);
    if (state_[at(u)] == VertexState::Visited) continue;
    sum_[at(line)] += position(u);
    ++weight_[at(line)];
  }
}

void ContourLevelLines::unlink(Index line, Index t) {
  Triangle& r = triangle_[at(t)];
  (r.prev == kInvalidIndex ? head_[at(line)] : triangle_[at(r.prev)].next) = r.next;
  if (r.next != kInvalidIndex) triangle_[at(r.next)].prev = r.prev;
  r.line = kInvalidIndex;
  --size_[at(line)];
  for (int k = 0; k < 3; ++k) {
    const Index u = mesh_.triangles(t, k);
    if (state_[at(u)] == VertexState::Visited) continue;
    sum_[at(line)] -= position(u);
    --weight_[at(line)];
  }
}

Index ContourLevelLines::merge(Index a, Index b) {
  if (size_[at(a)] < size_[at(b)]) std::swap(a, b);
  if (size_[at(b)] > 0) {
    Index tail = kInvalidIndex;
    for (Index t = head_[at(b)]; t != kInvalidIndex; t = triangle_[at(t)].next) {
      triangle_[at(t)].line = a;
      tail = t;
    }
    triangle_[at(tail)].next = head_[at(a)];
    if (head_[at(a)] != kInvalidIndex) triangle_[at(head_[at(a)])].prev = tail;
    head_[at(a)] = head_[at(b)];
  }
  size_[at(a)] += size_[at(b)];
  sum_[at(a)] += sum_[at(b)];
  weight_[at(a)] += weight_[at(b)];
  head_[at(b)] = kInvalidIndex;
  size_[at(b)] = 0;
  free_lines_.push_back(b);
  return a;
}

void ContourLevelLines::visit(Index v, Index line) {
  // v leaves the front: its triangles on it lose v as an unvisited corner.
  for (const FrontStar::Entry& e : star_.entries()) {
    if (!e.before) continue;
    sum_[at(line)] -= position(v);
    --weight_[at(line)];
  }
  state_[at(v)] = VertexState::Visited;
  ++visited_count_;
  for (const FrontStar::Entry& e : star_.entries()) {
    if (e.before && !e.after) unlink(line, e.triangle);
    if (!e.before && e.after) link(line, e.triangle);
  }
  for (Index i = graph_.offset[at(v)]; i < graph_.offset[at(v) + 1]; ++i) {
    const Index w = graph_.neighbor[at(i)];
    if (state_[at(w)] != VertexState::Unvisited) continue;
    state_[at(w)] = VertexState::Candidate;
    queue_.emplace(f_[at(w)], w);
  }
}

void ContourLevelLines::absorb(Index v) {
  star_.collect(mesh_, graph_, around_, state_, v);
  for (FrontStar::Entry& e : star_.entries())
    if (e.before) e.old_line = triangle_[at(e.triangle)].line;
  if (star_.regular()) {  // one line through v, the same after: no event
    const auto& entries = star_.entries();
    const Index line = std::find_if(entries.begin(), entries.end(), [](const FrontStar::Entry& e) { return e.before; })->old_line;
    recorder_.absorb(v, node_[at(line)]);
    visit(v, line);
    recorder_.continue_line(v, node_[at(line)], [this, line] { return center(line); });
    return;
  }
  change_.clear();
  star_.settle_old(
      root_line_, change_, [this](Index line) { return node_[at(line)]; },
      [this, v](Index line) { return weight_[at(line)] > 0 ? center(line) : Vec3(mesh_.vertices.row(v)); });
  recorder_.absorb(v, change_.old_nodes[0]);
  // Every line through v becomes one, ...
  const std::vector<Index>& old_lines = star_.old_lines();
  Index line = old_lines[0];
  for (std::size_t k = 1; k < old_lines.size(); ++k) line = merge(line, old_lines[k]);
  root_line_ = kInvalidIndex;
  // ... which holds v's triangles still or newly on the front ...
  visit(v, line);
  // ... and splits into its connected curves, one per arc around v at most.
  const auto& pieces = splitter_.split(
      star_.arc_triangles(mesh_, state_), [this](Index t) -> Index& { return triangle_[at(t)].search; },
      [this](Index t, auto&& visit_triangle) { for_each_front_neighbour(mesh_, around_, state_, t, visit_triangle); });
  for (const std::vector<Index>& piece : pieces) {
    const Index moved = new_line(node_[at(line)]);
    for (const Index t : piece) {
      unlink(line, t);
      link(moved, t);
    }
  }

  for (FrontStar::Entry& e : star_.entries())
    if (e.after) e.new_line = triangle_[at(e.triangle)].line;
  star_.settle_new(change_, [this](Index l) { return center(l); });
  recorder_.step(v, change_, new_nodes_);
  const std::vector<Index>& new_lines = star_.new_lines();
  for (std::size_t k = 0; k < new_lines.size(); ++k) node_[at(new_lines[k])] = new_nodes_[k];
  if (new_lines.empty()) {  // termination: the line vanished with v
    if (size_[at(line)] != 0) throw std::logic_error("ContourLevelLines: a level line outlived its last front triangle");
    free_lines_.push_back(line);
  }
}

}  // namespace reebkit

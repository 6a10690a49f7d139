#include "reebkit/reeb/contour_lines.h"

#include "reebkit/mesh/mesh_topology.h"

#include <algorithm>
#include <stdexcept>

namespace reebkit {

VertexTriangles vertex_triangles(const Mesh& mesh) {
  VertexCorners corners = corners_by_vertex(mesh.triangles, mesh.num_vertices());
  VertexTriangles out{std::move(corners.start), std::move(corners.corner)};
  for (Index& t : out.triangle) t /= 3;  // corner 3 t + k -> triangle t
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
        if (entries_[j].after && unvisited_corner(j, w))
          arc_parent_[static_cast<std::size_t>(find(static_cast<Index>(j)))] = find(static_cast<Index>(i));
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (entries_[i].after && find(static_cast<Index>(i)) == static_cast<Index>(i))
      arcs_.push_back(entries_[i].triangle);
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
      state_(f.size(), VertexState::Unvisited),
      lines_(mesh, mesh.num_triangles()) {}

void ContourLevelLines::propagate_from(Index minimum) {
  // The propagation starts with one line, the root's, holding no triangle.
  root_line_ = lines_.new_line(recorder_.start_root(minimum));
  state_[at(minimum)] = VertexState::Candidate;
  queue_.emplace(f_[at(minimum)], minimum);
  while (!queue_.empty()) {
    const Index v = queue_.top().second;
    queue_.pop();
    absorb(v);
  }
}

void ContourLevelLines::attach(Index line, Index t) {
  lines_.link(line, t);
  for (int k = 0; k < 3; ++k) {
    const Index u = mesh_.triangles(t, k);
    if (state_[at(u)] != VertexState::Visited) lines_.add_point(line, u, +1);
  }
}

void ContourLevelLines::detach(Index t) {
  for (int k = 0; k < 3; ++k) {
    const Index u = mesh_.triangles(t, k);
    if (state_[at(u)] != VertexState::Visited) lines_.add_point(lines_.line_of(t), u, -1);
  }
  lines_.unlink(t);
}

void ContourLevelLines::visit(Index v, Index line) {
  // v leaves the front: its triangles on it lose v as an unvisited corner.
  for (const FrontStar::Entry& e : star_.entries())
    if (e.before) lines_.add_point(line, v, -1);
  state_[at(v)] = VertexState::Visited;
  ++visited_count_;
  for (const FrontStar::Entry& e : star_.entries()) {
    if (e.before && !e.after) detach(e.triangle);
    if (!e.before && e.after) attach(line, e.triangle);
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
    if (e.before) e.old_line = lines_.line_of(e.triangle);
  if (star_.regular()) {  // one line through v, the same after: no event
    const auto& entries = star_.entries();
    const Index line =
        std::find_if(entries.begin(), entries.end(), [](const FrontStar::Entry& e) { return e.before; })->old_line;
    recorder_.absorb(v, lines_.node(line));
    visit(v, line);
    recorder_.continue_line(v, lines_.node(line), [this, line] { return lines_.center(line); });
    return;
  }
  change_.clear();
  star_.settle_old(
      root_line_, change_, [this](Index line) { return lines_.node(line); },
      [this, v](Index line) { return lines_.points(line) > 0 ? lines_.center(line) : Vec3(mesh_.vertices.row(v)); });
  recorder_.absorb(v, change_.old_nodes[0]);
  // Every line through v becomes one, ...
  const std::vector<Index>& old_lines = star_.old_lines();
  Index line = old_lines[0];
  for (std::size_t k = 1; k < old_lines.size(); ++k) line = lines_.merge(line, old_lines[k]);
  root_line_ = kInvalidIndex;
  // ... which holds v's triangles still or newly on the front ...
  visit(v, line);
  // ... and splits into its connected curves, one per arc around v at most.
  const auto& pieces = splitter_.split(
      star_.arc_triangles(mesh_, state_), [this](Index t) -> Index& { return lines_.search(t); },
      [this](Index t, auto&& visit_triangle) { for_each_front_neighbour(mesh_, around_, state_, t, visit_triangle); });
  for (const std::vector<Index>& piece : pieces) {
    const Index moved = lines_.new_line(lines_.node(line));
    for (const Index t : piece) {
      detach(t);
      attach(moved, t);
    }
  }

  for (FrontStar::Entry& e : star_.entries())
    if (e.after) e.new_line = lines_.line_of(e.triangle);
  star_.settle_new(change_, [this](Index l) { return lines_.center(l); });
  recorder_.step(v, change_, new_nodes_);
  const std::vector<Index>& new_lines = star_.new_lines();
  for (std::size_t k = 0; k < new_lines.size(); ++k) lines_.set_node(new_lines[k], new_nodes_[k]);
  if (new_lines.empty()) {  // termination: the line vanished with v
    if (lines_.size(line) != 0)
      throw std::logic_error("ContourLevelLines: a level line outlived its last front triangle");
    lines_.free_line(line);
  }
}

}  // namespace reebkit

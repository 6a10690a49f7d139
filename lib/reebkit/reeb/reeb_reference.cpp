#include "reebkit/reeb/reeb_reference.h"

#include "reebkit/core/error.h"
#include "reebkit/reeb/contour_lines.h"
#include "reebkit/reeb/dual_graph_recorder.h"
#include "reebkit/reeb/pit_cancellation.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>

namespace reebkit {
namespace {

/// The discrete level lines of Definition 6: the connected components of
/// C(t), found by breadth-first search over the candidate vertices.
struct CandidateLines {
  std::vector<Index> line;   ///< #V, line of each candidate vertex (kInvalidIndex elsewhere)
  std::vector<Index> size;   ///< vertices per line
  std::vector<Vec3> center;  ///< barycenter of each line's vertices (section 5.2)
};

void find_level_lines(const Mesh& mesh, const MeshGraph& graph, const std::vector<VertexState>& state,
                      const std::vector<Index>& candidates, CandidateLines& lines) {
  for (const Index v : candidates) lines.line[static_cast<std::size_t>(v)] = kInvalidIndex;
  lines.size.clear();
  lines.center.clear();
  std::vector<Index> queue;
  for (const Index seed : candidates) {
    if (lines.line[static_cast<std::size_t>(seed)] != kInvalidIndex) continue;
    const Index id = static_cast<Index>(lines.size.size());
    lines.line[static_cast<std::size_t>(seed)] = id;
    queue.assign(1, seed);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const Index u = queue[head];
      for (Index i = graph.offset[u]; i < graph.offset[u + 1]; ++i) {
        const Index w = graph.neighbor[static_cast<std::size_t>(i)];
        if (state[static_cast<std::size_t>(w)] != VertexState::Candidate ||
            lines.line[static_cast<std::size_t>(w)] != kInvalidIndex)
          continue;
        lines.line[static_cast<std::size_t>(w)] = id;
        queue.push_back(w);
      }
    }
    lines.size.push_back(static_cast<Index>(queue.size()));
    Vec3 sum = Vec3::Zero();
    for (const Index u : queue) sum += mesh.vertices.row(u);
    lines.center.push_back(sum / static_cast<double>(queue.size()));
  }
}

/// The level lines of LevelLines::Contour from scratch: the connected sets
/// of front triangles (union-find), each named by its smallest triangle;
/// kInvalidIndex for a triangle off the front.
std::vector<Index> front_curves(const Mesh& mesh, const VertexTriangles& around,
                                const std::vector<VertexState>& state) {
  std::vector<Index> parent(static_cast<std::size_t>(mesh.num_triangles()));
  std::iota(parent.begin(), parent.end(), Index{0});
  const auto find = [&parent](Index x) {
    while (parent[static_cast<std::size_t>(x)] != x)
      x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    return x;
  };
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    if (!on_front(mesh, state, t)) continue;
    for_each_front_neighbour(mesh, around, state, t, [&](Index u) {
      const Index a = find(t), b = find(u);
      parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    });
  }
  std::vector<Index> line(parent.size(), kInvalidIndex);
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    if (on_front(mesh, state, t)) line[static_cast<std::size_t>(t)] = find(t);
  return line;
}

/// The mean position of the unvisited corners of the line's triangles.
Vec3 front_center(const Mesh& mesh, const std::vector<VertexState>& state, const std::vector<Index>& line, Index id) {
  Vec3 sum = Vec3::Zero();
  Index count = 0;
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    if (line[static_cast<std::size_t>(t)] != id) continue;
    for (int k = 0; k < 3; ++k) {
      const Index u = mesh.triangles(t, k);
      if (state[static_cast<std::size_t>(u)] == VertexState::Visited) continue;
      sum += mesh.vertices.row(u);
      ++count;
    }
  }
  return sum / static_cast<double>(count);
}

ReebGraph contour_reference(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                            const ReebOptions& options) {
  const auto n = static_cast<std::size_t>(mesh.num_vertices());
  const VertexTriangles around = vertex_triangles(mesh);
  std::vector<VertexState> state(n, VertexState::Unvisited);
  CandidateQueue queue;
  DualGraphRecorder recorder(mesh, f, options);
  const Index minimum = global_minimum(f);
  state[static_cast<std::size_t>(minimum)] = VertexState::Candidate;
  queue.emplace(f[static_cast<std::size_t>(minimum)], minimum);
  // The propagation starts with one line, the root's, holding no triangle.
  const Index root_line = -2;
  std::map<Index, Index> node = {{root_line, recorder.start_root(minimum)}};
  std::vector<Index> line(static_cast<std::size_t>(mesh.num_triangles()), kInvalidIndex);
  FrontStar star;
  LineChange change;
  std::vector<Index> new_nodes;
  Index visited = 0;
  while (!queue.empty()) {
    const Index v = queue.top().second;
    queue.pop();
    star.collect(mesh, graph, around, state, v);
    for (FrontStar::Entry& e : star.entries())
      if (e.before) e.old_line = line[static_cast<std::size_t>(e.triangle)];
    change.clear();
    star.settle_old(
        root_line, change, [&](Index id) { return node.at(id); },
        [&](Index id) { return id == root_line ? Vec3(mesh.vertices.row(v)) : front_center(mesh, state, line, id); });
    recorder.absorb(v, change.old_nodes[0]);
    state[static_cast<std::size_t>(v)] = VertexState::Visited;
    ++visited;
    for (Index i = graph.offset[v]; i < graph.offset[v + 1]; ++i) {
      const Index w = graph.neighbor[static_cast<std::size_t>(i)];
      if (state[static_cast<std::size_t>(w)] != VertexState::Unvisited) continue;
      state[static_cast<std::size_t>(w)] = VertexState::Candidate;
      queue.emplace(f[static_cast<std::size_t>(w)], w);
    }
    const std::vector<Index> next = front_curves(mesh, around, state);
    for (FrontStar::Entry& e : star.entries())
      if (e.after) e.new_line = next[static_cast<std::size_t>(e.triangle)];
    star.settle_new(change, [&](Index id) { return front_center(mesh, state, next, id); });
    recorder.step(v, change, new_nodes);

    // A line away from v keeps its triangles, its name and its node.
    std::map<Index, Index> next_node;
    for (std::size_t k = 0; k < new_nodes.size(); ++k) next_node[star.new_lines()[k]] = new_nodes[k];
    for (std::size_t t = 0; t < next.size(); ++t) {
      if (next[t] == kInvalidIndex || next_node.count(next[t]) > 0) continue;
      if (line[t] != next[t]) throw std::logic_error("reference_reeb_graph: a level line changed away from v_t");
      next_node[next[t]] = node.at(line[t]);
    }
    node = std::move(next_node);
    line = next;
  }
  if (visited != mesh.num_vertices()) throw InvalidArgument("reference_reeb_graph: the mesh graph is not connected");
  return recorder.finish();
}

/// Definition 6 as the paper states it: every line of C(t) rebuilt at each step.
ReebGraph paper_reference(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                          const ReebOptions& options) {
  const auto n = static_cast<std::size_t>(mesh.num_vertices());
  std::vector<VertexState> state(n, VertexState::Unvisited);
  std::vector<bool> entered(n, false);  // joined C at the current step
  std::vector<Index> candidates;
  CandidateQueue queue;
  DualGraphRecorder recorder(mesh, f, options);

  // C starts as the global minimum alone: one line, the root's.
  const Index minimum = global_minimum(f);
  state[static_cast<std::size_t>(minimum)] = VertexState::Candidate;
  candidates.push_back(minimum);
  queue.emplace(f[static_cast<std::size_t>(minimum)], minimum);
  CandidateLines old_lines{std::vector<Index>(n, kInvalidIndex), {1}, {mesh.vertices.row(minimum)}};
  old_lines.line[static_cast<std::size_t>(minimum)] = 0;
  std::vector<Index> old_node = {recorder.start_root(minimum)};
  CandidateLines lines{std::vector<Index>(n, kInvalidIndex), {}, {}};

  LineChange change;
  std::vector<Index> changed;  // new lines of the event, in one-ring order
  std::vector<Index> new_nodes;
  Index visited = 0;
  while (!queue.empty()) {
    const Index v = queue.top().second;
    queue.pop();
    const Index v_line = old_lines.line[static_cast<std::size_t>(v)];
    recorder.absorb(v, old_node[static_cast<std::size_t>(v_line)]);
    state[static_cast<std::size_t>(v)] = VertexState::Visited;
    ++visited;
    candidates.erase(std::find(candidates.begin(), candidates.end(), v));
    const Index begin = graph.offset[v];
    const Index end = graph.offset[v + 1];
    for (Index i = begin; i < end; ++i) {
      const Index w = graph.neighbor[static_cast<std::size_t>(i)];
      if (state[static_cast<std::size_t>(w)] != VertexState::Unvisited) continue;
      state[static_cast<std::size_t>(w)] = VertexState::Candidate;
      entered[static_cast<std::size_t>(w)] = true;
      candidates.push_back(w);
      queue.emplace(f[static_cast<std::size_t>(w)], w);
    }
    find_level_lines(mesh, graph, state, candidates, lines);

    // Each new line's old lines: those it shares vertices with, and v's line
    // when it holds a neighbour of v.
    std::vector<std::vector<Index>> sources(lines.size.size());
    for (const Index u : candidates)
      if (!entered[static_cast<std::size_t>(u)])
        sources[static_cast<std::size_t>(lines.line[static_cast<std::size_t>(u)])].push_back(
            old_lines.line[static_cast<std::size_t>(u)]);
    changed.clear();
    for (Index i = begin; i < end; ++i) {
      const Index w = graph.neighbor[static_cast<std::size_t>(i)];
      if (state[static_cast<std::size_t>(w)] != VertexState::Candidate) continue;
      const Index line = lines.line[static_cast<std::size_t>(w)];
      sources[static_cast<std::size_t>(line)].push_back(v_line);
      if (std::find(changed.begin(), changed.end(), line) == changed.end()) changed.push_back(line);
    }
    for (auto& s : sources) {
      std::sort(s.begin(), s.end());
      s.erase(std::unique(s.begin(), s.end()), s.end());
    }

    // A new line equal to an old one keeps its node; every other new line
    // must hold a neighbour of v.
    std::vector<Index> node(lines.size.size(), kInvalidIndex);
    for (std::size_t line = 0; line < node.size(); ++line) {
      const std::vector<Index>& s = sources[line];
      if (s.size() == 1 && s[0] != v_line && lines.size[line] == old_lines.size[static_cast<std::size_t>(s[0])])
        node[line] = old_node[static_cast<std::size_t>(s[0])];
      else if (std::find(changed.begin(), changed.end(), static_cast<Index>(line)) == changed.end())
        throw std::logic_error("reference_reeb_graph: a level line changed away from v_t");
    }

    change.clear();
    change.old_nodes.push_back(old_node[static_cast<std::size_t>(v_line)]);
    change.old_centers.push_back(old_lines.center[static_cast<std::size_t>(v_line)]);
    std::vector<Index> old_index = {v_line};  // old line of each entry of change.old_nodes
    change.new_lines = static_cast<Index>(changed.size());
    for (std::size_t k = 0; k < changed.size(); ++k) {
      change.new_centers.push_back(lines.center[static_cast<std::size_t>(changed[k])]);
      for (const Index old : sources[static_cast<std::size_t>(changed[k])]) {
        auto at = std::find(old_index.begin(), old_index.end(), old);
        if (at == old_index.end()) {
          old_index.push_back(old);
          change.old_nodes.push_back(old_node[static_cast<std::size_t>(old)]);
          change.old_centers.push_back(old_lines.center[static_cast<std::size_t>(old)]);
          at = old_index.end() - 1;
        }
        change.links.push_back({static_cast<Index>(at - old_index.begin()), static_cast<Index>(k)});
      }
    }
    recorder.step(v, change, new_nodes);
    for (std::size_t k = 0; k < changed.size(); ++k) node[static_cast<std::size_t>(changed[k])] = new_nodes[k];

    for (const Index u : candidates) entered[static_cast<std::size_t>(u)] = false;
    std::swap(old_lines, lines);
    old_node = std::move(node);
  }
  if (visited != mesh.num_vertices()) throw InvalidArgument("reference_reeb_graph: the mesh graph is not connected");
  return recorder.finish();
}

}  // namespace

ReebGraph reference_reeb_graph(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                               const ReebOptions& options) {
  check_reeb_inputs("reference_reeb_graph", mesh, graph, f, options);
  ReebGraph reeb = options.level_lines == LevelLines::Paper ? paper_reference(mesh, graph, f, options)
                                                            : contour_reference(mesh, graph, f, options);
  return options.leaves == Leaves::Maxima ? cancel_pits(std::move(reeb), graph, f) : reeb;
}

}  // namespace reebkit

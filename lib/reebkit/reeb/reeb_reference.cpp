#include "reebkit/reeb/reeb_reference.h"

#include "reebkit/core/error.h"
#include "reebkit/reeb/dual_graph_recorder.h"

#include <algorithm>
#include <stdexcept>

namespace reebkit {
namespace {

/// The discrete level lines of Definition 6: the connected components of
/// C(t), found by breadth-first search over the candidate vertices.
struct LevelLines {
  std::vector<Index> line;    ///< #V, line of each candidate vertex (kInvalidIndex elsewhere)
  std::vector<Index> size;    ///< vertices per line
  std::vector<Vec3> center;   ///< barycenter of each line's vertices (section 5.2)
};

void find_level_lines(const Mesh& mesh, const MeshGraph& graph, const std::vector<VertexState>& state,
                      const std::vector<Index>& candidates, LevelLines& lines) {
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

}  // namespace

ReebGraph reference_reeb_graph(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                               const ReebOptions& options) {
  check_reeb_inputs("reference_reeb_graph", mesh, graph, f, options);
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
  LevelLines old_lines{std::vector<Index>(n, kInvalidIndex), {1}, {mesh.vertices.row(minimum)}};
  old_lines.line[static_cast<std::size_t>(minimum)] = 0;
  std::vector<Index> old_node = {recorder.start_root(minimum)};
  LevelLines lines{std::vector<Index>(n, kInvalidIndex), {}, {}};

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

}  // namespace reebkit

// The genus oracle: on a closed orientable surface of genus g, a Reeb graph
// has exactly g independent cycles. Checked on the CGAL meshes, with every
// failure listed and explained by comparing the level lines of Definition 6
// (connected sets of candidate vertices) with the fronts of the same
// propagation (the connected curves between visited and unvisited vertices,
// the level sets of the piecewise-linear function "step of absorption", whose
// Reeb graph has exactly g cycles).
#include "reebkit/reeb/reeb_graph.h"

#include "reeb/reeb_test_util.h"
#include "reebkit/reeb/dual_graph_recorder.h"
#include "reebkit/mesh/load_mesh.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <regex>
#include <set>

namespace reebkit::test {
namespace {

/// The order in which the propagation absorbs the vertices: always the
/// smallest (f, id) among the unvisited neighbours of visited vertices.
std::vector<Index> propagation_order(const MeshGraph& graph, const std::vector<double>& f) {
  std::vector<bool> reached(f.size(), false);
  CandidateQueue queue;
  const Index start = global_minimum(f);
  queue.emplace(f[static_cast<std::size_t>(start)], start);
  reached[static_cast<std::size_t>(start)] = true;
  std::vector<Index> order;
  while (!queue.empty()) {
    const Index v = queue.top().second;
    queue.pop();
    order.push_back(v);
    for (Index i = graph.offset[v]; i < graph.offset[v + 1]; ++i) {
      const Index w = graph.neighbor[static_cast<std::size_t>(i)];
      if (reached[static_cast<std::size_t>(w)]) continue;
      reached[static_cast<std::size_t>(w)] = true;
      queue.emplace(f[static_cast<std::size_t>(w)], w);
    }
  }
  return order;
}

/// Fronts of the propagation through vertex v's star: the connected
/// components (joined across triangles) of the edges between a visited and
/// an unvisited vertex that end at v.
class Fronts {
 public:
  Fronts(const Mesh& mesh, const MeshGraph& graph)
      : mesh_(mesh), graph_(graph), visited_(static_cast<std::size_t>(graph.num_vertices()), false) {
    for (Index t = 0; t < mesh.num_triangles(); ++t)
      for (int k = 0; k < 3; ++k)
        triangle_edges_.push_back(edge_id(mesh.triangles(t, k), mesh.triangles(t, (k + 1) % 3)));
  }

  bool visited(Index v) const { return visited_[static_cast<std::size_t>(v)]; }
  void visit(Index v) { visited_[static_cast<std::size_t>(v)] = true; }

  /// Number of fronts through v, from scratch: O(#F).
  Index through(Index v) {
    parent_.resize(static_cast<std::size_t>(graph_.num_half_edges()));
    std::iota(parent_.begin(), parent_.end(), Index{0});
    for (Index t = 0; t < mesh_.num_triangles(); ++t) {
      Index front[3];
      int count = 0;
      for (int k = 0; k < 3; ++k)
        if (visited(mesh_.triangles(t, k)) != visited(mesh_.triangles(t, (k + 1) % 3)))
          front[count++] = triangle_edges_[static_cast<std::size_t>(3 * t + k)];
      if (count == 2) parent_[static_cast<std::size_t>(find(front[0]))] = find(front[1]);
    }
    std::set<Index> fronts;
    for (Index i = graph_.offset[v]; i < graph_.offset[v + 1]; ++i) {
      const Index u = graph_.neighbor[static_cast<std::size_t>(i)];
      if (visited(u) != visited(v)) fronts.insert(find(edge_id(u, v)));
    }
    return static_cast<Index>(fronts.size());
  }

 private:
  /// Undirected edge id: the slot of the larger endpoint in the smaller one's ring.
  Index edge_id(Index a, Index b) const {
    if (a > b) std::swap(a, b);
    Index i = graph_.offset[a];
    while (graph_.neighbor[static_cast<std::size_t>(i)] != b) ++i;
    return i;
  }
  Index find(Index x) {
    while (parent_[static_cast<std::size_t>(x)] != x)
      x = parent_[static_cast<std::size_t>(x)] =
          parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(x)])];
    return x;
  }

  const Mesh& mesh_;
  const MeshGraph& graph_;
  std::vector<bool> visited_;
  std::vector<Index> triangle_edges_;
  std::vector<Index> parent_;
};

/// Independent cycles of the Reeb graph of the fronts.
struct FrontCycles {
  Index unfolded = 0;  ///< degenerate saddles unfolded: the genus
  Index folded = 0;    ///< each saddle one event, as the level lines count them
};

/// Counts the cycles the fronts close. At a saddle v_t whose visited neighbours form k arcs
/// around it, k - 1 simple saddles turn the a fronts through v_t into b, so
/// (k - 1 + a - b) / 2 of them are merges, each closing one cycle. (Left
/// folded, a saddle where fronts touch themselves more than once loses
/// cycles, exactly like the level lines do.) Equals the genus of a closed
/// orientable surface.
FrontCycles front_cycles(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f) {
  Fronts fronts(mesh, graph);
  FrontCycles cycles;
  for (const Index v : propagation_order(graph, f)) {
    const Index begin = graph.offset[v];
    const Index end = graph.offset[v + 1];
    Index arcs = 0;
    Index lower = 0;
    for (Index i = begin; i < end; ++i) {
      if (!fronts.visited(graph.neighbor[static_cast<std::size_t>(i)])) continue;
      ++lower;
      const Index p = i > begin ? i - 1 : end - 1;
      if (!fronts.visited(graph.neighbor[static_cast<std::size_t>(p)]) ||
          graph.link_next[static_cast<std::size_t>(p)] == 0)
        ++arcs;
    }
    if (arcs < 2 || lower == end - begin) {  // regular, minimum or maximum
      fronts.visit(v);
      continue;
    }
    const Index before = fronts.through(v);
    fronts.visit(v);
    const Index after = fronts.through(v);
    cycles.folded += before - 1;
    cycles.unfolded += (arcs - 1 + before - after) / 2;
  }
  return cycles;
}

struct ManifestMesh {
  std::string file;
  int genus = 0;
};

/// The closed, manifold, one-piece triangle meshes of the CGAL manifest.
std::vector<ManifestMesh> closed_triangle_meshes(const std::filesystem::path& dir) {
  std::ifstream manifest(dir / "manifest.jsonl");
  const std::regex row(
      R"re("file": "([^"]+)".*"nontri": 0,.*"comps": 1,.*"genus": (\d+)\.0,.*"closed": true, "manifold": true)re");
  std::vector<ManifestMesh> meshes;
  for (std::string line; std::getline(manifest, line);) {
    std::smatch m;
    if (std::regex_search(line, m, row)) meshes.push_back({m[1].str(), std::stoi(m[2].str())});
  }
  return meshes;
}

// The level-line cycles of the meshes where they fall short of the genus
// while the fronts of the same propagation have it. Definition 6 joins fronts
// into one level line as soon as candidate vertices of theirs are adjacent:
// when the two fronts around a handle stay that close from the split to the
// merge (thin walls, handles and tunnels a few edges across: pipe, joint,
// the pinion gears, the 133 tunnels of cheese), the line never splits and the
// cycle is lost. A degenerate saddle where fronts touch themselves more than
// once also counts as one event (one cycle of cheese). Cheese has 73 with the
// default feature points, 70 with every local extremum as one
// (FeatureOptions::min_persistence = 0).
const std::map<std::string, Index> kLostCycles = {{"cheese.off", 73}, {"couplingdown.off", 7}, {"femur.off", 1},
                                                  {"joint.off", 0},   {"pinion.off", 0},       {"pinion_small.off", 0},
                                                  {"pipe.off", 0},    {"turbine.off", 7}};

TEST(ReebGenusOracle, CyclesEqualTheGenusOfEveryClosedCgalMesh) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  const std::vector<ManifestMesh> meshes = closed_triangle_meshes(dir);
  EXPECT_EQ(meshes.size(), 70u);
  Index passed = 0;
  std::ostringstream failures;
  for (const ManifestMesh& entry : meshes) {
    SCOPED_TRACE(entry.file);
    const ReebInput in = reeb_input(load_mesh(dir / entry.file).components[0]);
    const ReebGraph g = build_reeb_graph(in.mesh, in.graph, in.fq);
    const FrontCycles fronts = front_cycles(in.mesh, in.graph, in.fq);
    EXPECT_EQ(fronts.unfolded, entry.genus) << "the propagation itself misses the topology";
    const auto known = kLostCycles.find(entry.file);
    if (g.independent_cycles() == entry.genus) {
      ++passed;
      EXPECT_EQ(known, kLostCycles.end()) << "now passes: remove it from kLostCycles";
      continue;
    }
    failures << "  " << entry.file << " (" << in.mesh.num_vertices() << " vertices): genus " << entry.genus
             << ", level-line cycles " << g.independent_cycles() << "; front cycles " << fronts.unfolded << ", "
             << fronts.folded << " with each degenerate saddle one event, so " << fronts.folded - g.independent_cycles()
             << " lost to fronts joined into one level line and " << fronts.unfolded - fronts.folded
             << " to degenerate saddles (" << summary(g) << ")\n";
    ASSERT_NE(known, kLostCycles.end()) << "unexpected failure: " << summary(g);
    EXPECT_EQ(g.independent_cycles(), known->second);
  }
  std::cout << passed << " of " << meshes.size() << " closed CGAL meshes have as many cycles as their genus; "
            << meshes.size() - static_cast<std::size_t>(passed) << " lose some:\n"
            << failures.str();
}

}  // namespace
}  // namespace reebkit::test

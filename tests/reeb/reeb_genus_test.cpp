// The genus oracle: on a closed orientable surface of genus g, the Reeb graph
// of any function has exactly g independent cycles. With the contour level
// lines (LevelLines::Contour, the default) every merge of two curves of the
// front closes a cycle and degenerate saddles are unfolded, so the count is
// exact on every closed mesh and for any f; Definition 6 as the paper states
// it (LevelLines::Paper) loses the handles where two curves of the front
// stay within one edge of each other, and the cycles a degenerate saddle
// closes. Checked on the CGAL meshes, on plates of genus 1 to 8 generated in
// code, and on random functions.
#include "reebkit/reeb/reeb_graph.h"

#include "reeb/reeb_test_util.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shapes.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <numeric>
#include <random>
#include <regex>

namespace reebkit::test {
namespace {

ReebOptions with_lines(LevelLines lines) {
  ReebOptions options;
  options.level_lines = lines;
  return options;
}

/// Nodes without vertices: those of the degenerate saddles the recorder
/// unfolded (and lines that merged before absorbing a vertex).
Index empty_nodes(const ReebGraph& g) {
  return static_cast<Index>(
      std::count_if(g.nodes.begin(), g.nodes.end(), [](const ReebNode& n) { return n.vertex_count == 0; }));
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

TEST(ReebGenusOracle, CyclesEqualTheGenusOfEveryClosedCgalMesh) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  const std::vector<ManifestMesh> meshes = closed_triangle_meshes(dir);
  ASSERT_EQ(meshes.size(), 70u);
  int largest_genus = 0;
  std::ostringstream paper;
  for (const ManifestMesh& entry : meshes) {
    SCOPED_TRACE(entry.file);
    const ReebInput in = reeb_input(load_mesh(dir / entry.file).components[0]);
    const ReebGraph g = build_reeb_graph(in.mesh, in.graph, in.fq);
    EXPECT_EQ(g.independent_cycles(), entry.genus) << summary(g);
    largest_genus = std::max(largest_genus, entry.genus);
    const ReebGraph p = build_reeb_graph(in.mesh, in.graph, in.fq, with_lines(LevelLines::Paper));
    if (p.independent_cycles() != entry.genus)
      paper << "  " << entry.file << ": genus " << entry.genus << ", paper level lines " << p.independent_cycles()
            << " cycles\n";
  }
  EXPECT_GE(largest_genus, 50) << "the set should hold a mesh of high genus (cheese)";
  std::cout << "70 of 70 closed CGAL meshes have as many cycles as their genus; with Definition 6:\n" << paper.str();
}

TEST(ReebGenusOracle, HoledPlatesOfGenusOneToEight) {
  for (int genus = 1; genus <= 8; ++genus) {
    SCOPED_TRACE("genus " + std::to_string(genus));
    const ReebInput in = reeb_input(make_holed_plate(genus, 3));
    const MeshTopology topology = analyze_topology(in.mesh);
    ASSERT_TRUE(topology.manifold);
    ASSERT_EQ(topology.genus, genus);
    EXPECT_EQ(build_reeb_graph(in.mesh, in.graph, in.fq).independent_cycles(), genus);
    for (const int axis : {0, 1, 2})
      EXPECT_EQ(build_reeb_graph(in.mesh, in.graph, height(in.mesh, axis)).independent_cycles(), genus)
          << "height along axis " << axis;
    for (unsigned seed = 1; seed <= 3; ++seed)
      EXPECT_EQ(build_reeb_graph(in.mesh, in.graph, random_ranks(in.mesh.num_vertices(), seed)).independent_cycles(),
                genus)
          << "seed " << seed;
  }
}

// Random functions make degenerate saddles everywhere: a vertex whose
// visited neighbours form m > 2 arcs is m - 1 simple saddles, and a line that
// splits and merges again at it continues as one line but closes a cycle.
// The contour lines count every one; Definition 6 does not.
TEST(ReebGenusOracle, RandomFunctionsUnfoldDegenerateSaddles) {
  const std::vector<std::pair<Mesh, int>> surfaces = {{make_icosphere(3), 0},
                                                      {make_torus(30, 12), 1},
                                                      {make_holed_plate(2, 2), 2},
                                                      {make_holed_plate(5, 2), 5}};
  Index unfolded = 0, paper_wrong = 0;
  for (const auto& [mesh, genus] : surfaces) {
    const MeshGraph graph = build_mesh_graph(mesh);
    for (unsigned seed = 1; seed <= 10; ++seed) {
      SCOPED_TRACE("genus " + std::to_string(genus) + ", seed " + std::to_string(seed));
      const std::vector<double> f = random_ranks(mesh.num_vertices(), seed);
      const ReebGraph g = build_reeb_graph(mesh, graph, f);
      expect_consistent(g, mesh, f);
      EXPECT_EQ(g.independent_cycles(), genus) << summary(g);
      unfolded += empty_nodes(g);
      paper_wrong += build_reeb_graph(mesh, graph, f, with_lines(LevelLines::Paper)).independent_cycles() != genus;
    }
  }
  EXPECT_GT(unfolded, 0) << "no degenerate saddle was unfolded: the test lost its point";
  EXPECT_GT(paper_wrong, 0) << "Definition 6 got every random function right: the test lost its point";
}

// A monkey saddle made by hand: on an icosphere, a vertex c of degree 6
// whose neighbours alternate low and high, everything else lower still
// (a height function towards c). The
// propagation reaches c once the rest and the three low neighbours are
// visited: its visited neighbours form m = 3 arcs, the one line around the
// unvisited c and its three high neighbours splits into three, one around
// each, and each vanishes at its vertex: the root, a bifurcation into three
// nodes of one vertex each, three leaves, no cycle.
TEST(ReebGenusOracle, MonkeySaddleSplitsOneLineIntoThree) {
  const Mesh mesh = make_icosphere(1);
  const MeshGraph graph = build_mesh_graph(mesh);
  Index c = 0;
  while (graph.degree(c) != 6) ++c;
  ASSERT_EQ(graph.ring[static_cast<std::size_t>(c)], RingKind::Closed);
  std::vector<double> f(static_cast<std::size_t>(mesh.num_vertices()));
  // Below 0.05 elsewhere: the height towards c, whose only maximum is c.
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    f[static_cast<std::size_t>(v)] = 0.025 * (1.0 + mesh.vertices.row(v).dot(mesh.vertices.row(c)));
  f[static_cast<std::size_t>(c)] = 0.5;
  std::vector<Index> high;
  for (int k = 0; k < 6; ++k) {
    const Index n = graph.neighbor[static_cast<std::size_t>(graph.offset[static_cast<std::size_t>(c)] + k)];
    f[static_cast<std::size_t>(n)] = k % 2 == 0 ? 0.1 + 0.1 * k : 0.7 + 0.1 * k;
    if (k % 2 == 1) high.push_back(n);
  }
  for (const LevelLines lines : {LevelLines::Contour, LevelLines::Paper}) {
    SCOPED_TRACE(level_lines_name(lines));
    const ReebGraph g = build_reeb_graph(mesh, graph, f, with_lines(lines));
    expect_consistent(g, mesh, f);
    ASSERT_EQ(g.num_nodes(), 4) << summary(g);
    EXPECT_EQ(g.nodes[0].end, NodeType::Bifurcation);
    EXPECT_EQ(g.vertex_node[static_cast<std::size_t>(c)], 0);
    EXPECT_EQ(g.edges, (std::vector<std::array<Index, 2>>{{0, 1}, {0, 2}, {0, 3}}));
    for (const Index n : high) {
      const ReebNode& leaf = g.nodes[static_cast<std::size_t>(g.vertex_node[static_cast<std::size_t>(n)])];
      EXPECT_EQ(leaf.end, NodeType::Termination);
      EXPECT_EQ(leaf.vertex_count, 1);
    }
  }
}

// Two cubes sharing one corner c (a non-manifold vertex whose ring is two
// fans). f rises along x (less a little of y and z), so c = (1, 1, 1) is
// reached while cube a still has unvisited vertices at x = 1: the one curve of the front in cube a goes on,
// and a second one starts around c in cube b. The curves of two fans never
// join (they share no edge): a bifurcation at c, two leaves, no cycle.
TEST(ReebGenusOracle, NonManifoldVertexStartsALineInTheOtherFan) {
  const Mesh cube = make_cube();
  Mesh mesh = disjoint_union(cube, cube);
  mesh.vertices.bottomRows(8).rowwise() += Eigen::RowVector3d(1, 1, 1);
  // b's corner (0,0,0), vertex 8, becomes a's corner (1,1,1), vertex 7, and
  // b's last vertex takes its place.
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (mesh.triangles(t, k) == 8) mesh.triangles(t, k) = 7;
      if (mesh.triangles(t, k) == 15) mesh.triangles(t, k) = 8;
    }
  }
  mesh.vertices.row(8) = mesh.vertices.row(15);
  mesh.vertices.conservativeResize(15, 3);
  const MeshGraph graph = build_mesh_graph(mesh);
  ASSERT_EQ(graph.ring[7], RingKind::Irregular);
  std::vector<double> f(15);
  for (Index v = 0; v < 15; ++v)
    f[static_cast<std::size_t>(v)] = mesh.vertices(v, 0) - 1e-3 * mesh.vertices(v, 1) - 1e-6 * mesh.vertices(v, 2);
  for (const LevelLines lines : {LevelLines::Contour, LevelLines::Paper}) {
    SCOPED_TRACE(level_lines_name(lines));
    const ReebGraph g = build_reeb_graph(mesh, graph, f, with_lines(lines));
    expect_consistent(g, mesh, f);
    EXPECT_EQ(g.independent_cycles(), 0);
    const Index c = g.vertex_node[7];
    EXPECT_EQ(g.nodes[static_cast<std::size_t>(c)].end, NodeType::Bifurcation) << summary(g);
    Index children = 0;
    for (const auto& [a, b] : g.edges) children += a == c;
    EXPECT_EQ(children, 2) << summary(g);
    EXPECT_EQ(g.leaf_count(), 2) << summary(g);
  }
}

}  // namespace
}  // namespace reebkit::test

// Oracles for the Reeb graph on all 400 SHREC 2007 Watertight meshes
// (../shared/datasets): every mesh is closed, manifold and one piece, with
// its genus in manifest.jsonl. With the default contour level lines, every
// one has exactly genus-many cycles.
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/pipeline/analyze_mesh.h"
#include "support/test_support.h"

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace reebkit {
namespace {

std::map<std::string, int> manifest_genus(const std::filesystem::path& dir) {
  std::ifstream in(dir / "manifest.jsonl");
  const std::regex file(R"re("file": "([^"]+)")re"), genus(R"re("genus": ([0-9]+))re");
  std::map<std::string, int> out;
  std::string line;
  std::smatch f, g;
  while (std::getline(in, line))
    if (std::regex_search(line, f, file) && std::regex_search(line, g, genus)) out[f[1]] = std::stoi(g[1]);
  return out;
}

TEST(ReebShrec, CyclesEqualGenusAndLeavesEndAtFeaturePoints) {
  REEBKIT_REQUIRE_DATASET(dir, "shrec07_watertight");
  const auto genus = manifest_genus(dir);
  ASSERT_EQ(genus.size(), 400u);
  // Leaves with no feature point: the feature points are the only local
  // maxima of f_q, but the propagation floods from the global minimum, and
  // where it enters a basin of f_q (around a local minimum) from above, the
  // front can close around a vertex of the basin's rim that is no maximum
  // of f_q: a pocket of 1-2 vertices (measured: 284 twice, 287, 290 twice).
  // Each is checked to be such a vertex: a neighbour of higher f_q was
  // absorbed before it.
  const std::size_t max_pocket_vertices = 2;
  const int max_pockets = 5;

  int pockets = 0;
  std::ostringstream failures;
  for (const auto& [file, g] : genus) {
    const MeshAnalysis a = analyze_mesh(load_mesh(dir / file).components.front());
    const int cycles = a.reeb.independent_cycles();
    if (cycles != g) failures << file << " (genus " << g << ", " << cycles << " cycles) ";
    std::vector<bool> holds_feature(a.reeb.nodes.size(), false);
    for (const Index v : a.features.vertices) {
      const Index node = a.reeb.vertex_node[static_cast<std::size_t>(v)];
      holds_feature[static_cast<std::size_t>(node)] = true;
      EXPECT_EQ(a.reeb.nodes[static_cast<std::size_t>(node)].end, NodeType::Termination)
          << file << ": feature point " << v << " is not in a leaf region";
    }
    for (std::size_t n = 0; n < a.reeb.nodes.size(); ++n) {
      const ReebNode& node = a.reeb.nodes[n];
      if (node.end != NodeType::Termination || holds_feature[n]) continue;
      ++pockets;
      std::cout << "[ pocket ] " << file << " leaf " << n << ", " << node.vertex_count << " vertices\n";
      EXPECT_LE(static_cast<std::size_t>(node.vertex_count), max_pocket_vertices)
          << file << ": leaf " << n << " without a feature point has " << node.vertex_count << " vertices";
      // Its last vertex (the largest f_q) has a neighbour of higher f_q in
      // another region: not a maximum of f_q, only of the flood's order.
      Index last = kInvalidIndex;
      for (Index v = 0; v < a.mesh.num_vertices(); ++v)
        if (a.reeb.vertex_node[static_cast<std::size_t>(v)] == static_cast<Index>(n) &&
            (last == kInvalidIndex ||
             a.fq.value[static_cast<std::size_t>(v)] > a.fq.value[static_cast<std::size_t>(last)]))
          last = v;
      bool higher_outside = false;
      for (Index i = a.graph.offset[static_cast<std::size_t>(last)];
           i < a.graph.offset[static_cast<std::size_t>(last) + 1]; ++i) {
        const Index w = a.graph.neighbor[static_cast<std::size_t>(i)];
        higher_outside |= a.fq.value[static_cast<std::size_t>(w)] > a.fq.value[static_cast<std::size_t>(last)] &&
                          a.reeb.vertex_node[static_cast<std::size_t>(w)] != static_cast<Index>(n);
      }
      EXPECT_TRUE(higher_outside) << file << ": leaf " << n << " ends at a maximum of f_q that is no feature point";
    }
  }
  EXPECT_EQ(failures.str(), "") << "meshes whose cycle count differs from their genus";
  EXPECT_LE(pockets, max_pockets);
}

}  // namespace
}  // namespace reebkit

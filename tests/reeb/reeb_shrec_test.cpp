// Oracles for the Reeb graph on all 400 SHREC 2007 Watertight meshes
// (../shared/datasets): every mesh is closed, manifold and one piece, with
// its genus in manifest.jsonl.
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
  // Measured exceptions, all genus 1 with 0 cycles: the two level lines
  // around the handle stay within one edge of each other from split to merge,
  // so Definition 6 (connected sets of candidate vertices) sees one line and
  // no cycle forms. Any other mesh must have exactly genus-many cycles.
  // (133.off lost its cycle too with every local extremum as a feature
  // point, FeatureOptions::min_persistence = 0.)
  const std::set<std::string> lost_cycle = {"5.off", "163.off"};
  // Leaves with no feature point: pockets of 1-2 vertices that the
  // propagation front closes around (measured: 284 twice, 287, 290 twice;
  // 3, 258, 284 twice with min_persistence = 0).
  const std::size_t max_pocket_vertices = 2;
  const int max_pockets = 5;

  int pockets = 0;
  std::ostringstream failures;
  for (const auto& [file, g] : genus) {
    const MeshAnalysis a = analyze_mesh(load_mesh(dir / file).components.front());
    const int cycles = a.reeb.independent_cycles();
    if (lost_cycle.count(file)) {
      EXPECT_LT(cycles, g) << file << " is listed as losing a cycle but now has " << cycles << " for genus " << g;
    } else if (cycles != g) {
      failures << file << " (genus " << g << ", " << cycles << " cycles) ";
    }
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
    }
  }
  EXPECT_EQ(failures.str(), "") << "meshes whose cycle count differs from their genus";
  EXPECT_LE(pockets, max_pockets);
}

}  // namespace
}  // namespace reebkit

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

TEST(ReebShrec, CyclesEqualGenusAndEveryLeafHoldsAFeaturePoint) {
  REEBKIT_REQUIRE_DATASET(dir, "shrec07_watertight");
  const auto genus = manifest_genus(dir);
  ASSERT_EQ(genus.size(), 400u);
  // The feature points are the only local maxima of f_q, and a leaf is a
  // termination at one of them: the pits where the propagation closed around
  // a vertex it had passed above (with Leaves::Propagation, 5 leaves of 1 or 2
  // vertices on 284, 287 and 290) are cancelled (pit_cancellation.h).
  std::ostringstream failures, pits;
  AnalysisOptions options;  // the defaults, but for the attributes' spectra, which this test does not read
  options.prepare_attributes = false;
  for (const auto& [file, g] : genus) {
    const MeshAnalysis a = analyze_mesh(load_mesh(dir / file).components.front(), options);
    const int cycles = a.reeb.independent_cycles();
    if (cycles != g) failures << file << " (genus " << g << ", " << cycles << " cycles) ";
    std::vector<bool> holds_feature(a.reeb.nodes.size(), false);
    for (const Index v : a.features.vertices) {
      const Index node = a.reeb.vertex_node[static_cast<std::size_t>(v)];
      holds_feature[static_cast<std::size_t>(node)] = true;
      EXPECT_EQ(a.reeb.nodes[static_cast<std::size_t>(node)].end, NodeType::Termination)
          << file << ": feature point " << v << " is not in a leaf region";
    }
    for (std::size_t n = 0; n < a.reeb.nodes.size(); ++n)
      if (a.reeb.nodes[n].end == NodeType::Termination && !holds_feature[n]) pits << file << " leaf " << n << "; ";
  }
  EXPECT_EQ(failures.str(), "") << "meshes whose cycle count differs from their genus";
  EXPECT_EQ(pits.str(), "") << "leaves without a feature point";
}

}  // namespace
}  // namespace reebkit

// End to end: the `reeb` binary indexes the embedded collection (datasets/),
// `reeb info` reports it and `reeb export` prints a graph as `reeb graph` does.
#include "io/io_test_util.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/store/collection_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace reebkit::test {
namespace {

/// The lines of a graph JSON file without the ones that differ between
/// `reeb graph` and `reeb export` by design: the mesh path and the timings.
std::vector<std::string> comparable_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  bool in_timings = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("\"timings_ms\"") != std::string::npos) in_timings = true;
    if (!in_timings && line.find("\"mesh\":") == std::string::npos) out.push_back(line);
    if (in_timings && line.find('}') != std::string::npos) in_timings = false;
  }
  return out;
}

TEST(ReebIndexCli, IndexInfoExportOnTheEmbeddedCollection) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path datasets = embedded_dataset_dir();
  const std::size_t meshes = list_mesh_inputs({datasets.string()}).size();
  ASSERT_GT(meshes, 0u);

  const auto [indexed, index_out] =
      run_command(reeb + " index " + shell_quoted(datasets) + " -o " + shell_quoted(dir / "c.h5") +
                  " --threads 2 2>&1");
  ASSERT_EQ(indexed, 0) << index_out;
  EXPECT_NE(index_out.find(std::to_string(meshes) + " meshes: " + std::to_string(meshes) + " ok, 0 failed"),
            std::string::npos)
      << index_out;

  const auto [info_status, info] = run_command(reeb + " info " + shell_quoted(dir / "c.h5"));
  ASSERT_EQ(info_status, 0) << info;
  EXPECT_NE(info.find(std::to_string(meshes) + " meshes: " + std::to_string(meshes) + " ok, 0 failed"),
            std::string::npos)
      << info;
  EXPECT_NE(info.find("layout " + std::to_string(kCollectionLayoutVersion)), std::string::npos) << info;
  EXPECT_NE(info.find("command: reeb index"), std::string::npos) << info;
  std::string analysis = "analysis options:";
  for (const NamedOption& option : named_analysis_options(AnalysisOptions{}))
    analysis += " " + option.name + "=" + option_text(option.value);
  EXPECT_NE(info.find(analysis + "\n"), std::string::npos) << info;

  // The same document from the collection and from the mesh (timings and path aside).
  const auto [exported, export_out] =
      run_command(reeb + " export " + shell_quoted(dir / "c.h5") + " elk.off --json -o " +
                  shell_quoted(dir / "export.json") + " 2>&1");
  ASSERT_EQ(exported, 0) << export_out;
  const auto [graphed, graph_out] =
      run_command(reeb + " graph " + shell_quoted(datasets / "elk.off") + " -o " + shell_quoted(dir / "graph.json"));
  ASSERT_EQ(graphed, 0) << graph_out;
  const std::vector<std::string> a = comparable_lines(dir / "export.json");
  EXPECT_GT(a.size(), 100u);
  EXPECT_EQ(a, comparable_lines(dir / "graph.json"));

  const auto [missing, missing_out] =
      run_command(reeb + " export " + shell_quoted(dir / "c.h5") + " nothing.off --json 2>&1");
  EXPECT_EQ(missing, 1);
  EXPECT_NE(missing_out.find("no mesh named 'nothing.off'"), std::string::npos) << missing_out;

  // --resume on an unchanged folder computes nothing.
  const auto [resumed, resume_out] =
      run_command(reeb + " index " + shell_quoted(datasets) + " -o " + shell_quoted(dir / "c.h5") + " --resume 2>&1");
  ASSERT_EQ(resumed, 0) << resume_out;
  EXPECT_NE(resume_out.find("0 ok, 0 failed, " + std::to_string(meshes) + " already indexed"), std::string::npos)
      << resume_out;
}

}  // namespace
}  // namespace reebkit::test

// End to end: `reeb features` and `reeb graph` with --geodesic.
#include "io/io_test_util.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace reebkit::test {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ReebFeaturesCli, GeodesicMethodIsAnOption) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path cow = embedded_dataset_dir() / "cow.off";
  for (const std::string method : {"dijkstra", "fmm"}) {
    const auto [status, out] = run_command(reeb + " features " + shell_quoted(cow) + " --geodesic " + method + " -o " +
                                           shell_quoted(dir / "f.json") + " 2>&1");
    ASSERT_EQ(status, 0) << out;
    // Hooves, horns, ears, tail, muzzle (default --min-persistence 0.01: the teats persist less).
    EXPECT_NE(out.find("10 feature points"), std::string::npos) << method << ": " << out;
    EXPECT_NE(read_text(dir / "f.json").find("\"geodesic\": \"" + method + "\""), std::string::npos) << method;
  }
  const auto [graphed, graph_out] = run_command(reeb + " graph " + shell_quoted(embedded_dataset_dir() / "eight.off") +
                                                " -o " + shell_quoted(dir / "g.json") + " --geodesic fmm 2>&1");
  ASSERT_EQ(graphed, 0) << graph_out;
  EXPECT_NE(graph_out.find("2 cycles"), std::string::npos) << graph_out;  // genus 2

  const auto [bad, bad_out] = run_command(reeb + " features " + shell_quoted(cow) + " --geodesic heat 2>&1");
  EXPECT_EQ(bad, 1);
  EXPECT_NE(bad_out.find("unknown geodesic method 'heat' (expected dijkstra or fmm)"), std::string::npos) << bad_out;
}

TEST(ReebFeaturesCli, MinPersistenceIsAnOption) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path cow = embedded_dataset_dir() / "cow.off";
  // 5 % of the diameter keeps only the cow's long extremities; 0.01, the
  // default, 10; 0, the paper's rule, 14 (the teats too).
  const auto [status, out] = run_command(reeb + " features " + shell_quoted(cow) + " --min-persistence 0.05 -o " +
                                         shell_quoted(dir / "f.json") + " 2>&1");
  ASSERT_EQ(status, 0) << out;
  EXPECT_NE(out.find("6 feature points"), std::string::npos) << out;
  EXPECT_NE(read_text(dir / "f.json").find("\"min_persistence\": 0.05"), std::string::npos);
  const auto [plain, plain_out] = run_command(reeb + " features " + shell_quoted(cow) + " -o " +
                                              shell_quoted(dir / "g.json") + " 2>&1");
  ASSERT_EQ(plain, 0) << plain_out;
  EXPECT_NE(plain_out.find("10 feature points"), std::string::npos) << plain_out;
  EXPECT_NE(read_text(dir / "g.json").find("\"min_persistence\": 0.01"), std::string::npos);
  const auto [paper, paper_out] =
      run_command(reeb + " features " + shell_quoted(cow) + " --min-persistence 0 -o " + shell_quoted(dir / "p.json") + " 2>&1");
  ASSERT_EQ(paper, 0) << paper_out;
  EXPECT_NE(paper_out.find("14 feature points"), std::string::npos) << paper_out;
  EXPECT_NE(read_text(dir / "p.json").find("\"min_persistence\": 0,"), std::string::npos);

  const auto [graphed, graph_out] = run_command(reeb + " graph " + shell_quoted(embedded_dataset_dir() / "eight.off") +
                                                " -o " + shell_quoted(dir / "g.json") + " --min-persistence 0.02 2>&1");
  ASSERT_EQ(graphed, 0) << graph_out;
  EXPECT_NE(graph_out.find("2 cycles"), std::string::npos) << graph_out;  // genus 2

  // reeb index records it with the collection's analysis options.
  const auto [indexed, index_out] = run_command(reeb + " index " + shell_quoted(cow) + " -o " +
                                                shell_quoted(dir / "c.h5") + " --threads 1 --min-persistence 0.02 2>&1");
  ASSERT_EQ(indexed, 0) << index_out;
  const auto [info_status, info] = run_command(reeb + " info " + shell_quoted(dir / "c.h5"));
  ASSERT_EQ(info_status, 0) << info;
  EXPECT_NE(info.find("\"min_persistence\": 0.02"), std::string::npos) << info;

  const auto [bad, bad_out] = run_command(reeb + " features " + shell_quoted(cow) + " --min-persistence -1 2>&1");
  EXPECT_EQ(bad, 1);
  EXPECT_NE(bad_out.find("min_persistence must lie in [0, 1]"), std::string::npos) << bad_out;
}

}  // namespace
}  // namespace reebkit::test

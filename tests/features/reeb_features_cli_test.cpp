// End to end: `reeb features` and `reeb graph` with --geodesic.
#include "io/io_test_util.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
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
    const auto [status, out] =
        run_command(reeb + " features " + shell_quoted(cow) + " --geodesic " + method +
                    " --epsilon 0.05 --min-persistence 0.01 -o " + shell_quoted(dir / "f.json") + " 2>&1");
    ASSERT_EQ(status, 0) << out;
    // At the scale of a toe: hooves, horns, ears, tail, muzzle (the teats persist less than 0.01).
    EXPECT_NE(out.find("10 feature points"), std::string::npos) << method << ": " << out;
    EXPECT_NE(read_text(dir / "f.json").find("\"geodesic\": \"" + method + "\""), std::string::npos) << method;
  }
  const auto [graphed, graph_out] = run_command(reeb + " graph " + shell_quoted(embedded_dataset_dir() / "eight.off") +
                                                " -o " + shell_quoted(dir / "g.json") + " --geodesic fmm 2>&1");
  ASSERT_EQ(graphed, 0) << graph_out;
  EXPECT_NE(graph_out.find("2 cycles"), std::string::npos) << graph_out;  // genus 2
  // Where the time goes: every step of the analysis, then the attributes.
  EXPECT_NE(graph_out.find(" ms; the spectra's surface and its spectrum "), std::string::npos) << graph_out;
  EXPECT_NE(graph_out.find("g.json (attributes and JSON "), std::string::npos) << graph_out;

  const auto [bad, bad_out] = run_command(reeb + " features " + shell_quoted(cow) + " --geodesic heat 2>&1");
  EXPECT_EQ(bad, 1);
  EXPECT_NE(bad_out.find("unknown geodesic method 'heat' (expected dijkstra or fmm)"), std::string::npos) << bad_out;
}

TEST(ReebFeaturesCli, MinPersistenceIsAnOption) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path cow = embedded_dataset_dir() / "cow.off";
  // 5 % of the diameter keeps only the cow's long extremities; 0.03, the
  // default, 9; 0, 10; the paper's rule (0 at epsilon 0.05), 14 (the teats too).
  const auto [status, out] = run_command(reeb + " features " + shell_quoted(cow) + " --min-persistence 0.05 -o " +
                                         shell_quoted(dir / "f.json") + " 2>&1");
  ASSERT_EQ(status, 0) << out;
  EXPECT_NE(out.find("6 feature points"), std::string::npos) << out;
  EXPECT_NE(read_text(dir / "f.json").find("\"min_persistence\": 0.05"), std::string::npos);
  const auto [plain, plain_out] =
      run_command(reeb + " features " + shell_quoted(cow) + " -o " + shell_quoted(dir / "g.json") + " 2>&1");
  ASSERT_EQ(plain, 0) << plain_out;
  EXPECT_NE(plain_out.find("9 feature points"), std::string::npos) << plain_out;
  EXPECT_NE(read_text(dir / "g.json").find("\"min_persistence\": 0.03"), std::string::npos);
  const auto [all, all_out] = run_command(reeb + " features " + shell_quoted(cow) + " --min-persistence 0 -o " +
                                          shell_quoted(dir / "a.json") + " 2>&1");
  ASSERT_EQ(all, 0) << all_out;
  EXPECT_NE(all_out.find("10 feature points"), std::string::npos) << all_out;
  const auto [paper, paper_out] =
      run_command(reeb + " features " + shell_quoted(cow) + " --epsilon 0.05 --min-persistence 0 -o " +
                  shell_quoted(dir / "p.json") + " 2>&1");
  ASSERT_EQ(paper, 0) << paper_out;
  EXPECT_NE(paper_out.find("14 feature points"), std::string::npos) << paper_out;
  EXPECT_NE(read_text(dir / "p.json").find("\"min_persistence\": 0,"), std::string::npos);

  const auto [graphed, graph_out] = run_command(reeb + " graph " + shell_quoted(embedded_dataset_dir() / "eight.off") +
                                                " -o " + shell_quoted(dir / "g.json") + " --min-persistence 0.02 2>&1");
  ASSERT_EQ(graphed, 0) << graph_out;
  EXPECT_NE(graph_out.find("2 cycles"), std::string::npos) << graph_out;  // genus 2
  // Where the time goes: every step of the analysis, then the attributes.
  EXPECT_NE(graph_out.find(" ms; the spectra's surface and its spectrum "), std::string::npos) << graph_out;
  EXPECT_NE(graph_out.find("g.json (attributes and JSON "), std::string::npos) << graph_out;

  // reeb index records it with the collection's analysis options.
  const auto [indexed, index_out] =
      run_command(reeb + " index " + shell_quoted(cow) + " -o " + shell_quoted(dir / "c.h5") +
                  " --threads 1 --min-persistence 0.02 2>&1");
  ASSERT_EQ(indexed, 0) << index_out;
  const auto [info_status, info] = run_command(reeb + " info " + shell_quoted(dir / "c.h5"));
  ASSERT_EQ(info_status, 0) << info;
  EXPECT_NE(info.find("\"min_persistence\": 0.02"), std::string::npos) << info;

  const auto [bad, bad_out] = run_command(reeb + " features " + shell_quoted(cow) + " --min-persistence -1 2>&1");
  EXPECT_EQ(bad, 1);
  EXPECT_NE(bad_out.find("analysis option min_persistence: -1 is out of its range [0, 1]"), std::string::npos)
      << bad_out;
}

TEST(ReebFeaturesCli, OutputsAreCheckedBeforeWorkAndWrittenWholeOrNotAtAll) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  std::filesystem::copy_file(embedded_dataset_dir() / "elk.off", dir / "elk.off");
  const std::string mesh = read_text(dir / "elk.off");

  // An output that is the input, or in a missing folder: refused before the mesh is read.
  for (const std::string command : {"graph", "features"}) {
    const auto [status, out] = run_command(reeb + " " + command + " " + shell_quoted(dir / "elk.off") + " -o " +
                                           shell_quoted(dir / "elk.off") + " 2>&1");
    EXPECT_EQ(status, 1) << out;
    EXPECT_TRUE(contains(out, {(dir / "elk.off").string() + ": is an input of this command"})) << out;
    EXPECT_EQ(out.find("read and cleaned"), std::string::npos) << out;
  }
  EXPECT_EQ(read_text(dir / "elk.off"), mesh);
  // So is an analysis option out of its range.
  const auto [range, range_out] = run_command(reeb + " graph " + shell_quoted(dir / "elk.off") + " -o " +
                                              shell_quoted(dir / "g.json") + " --epsilon 5 2>&1");
  EXPECT_EQ(range, 1) << range_out;
  EXPECT_TRUE(contains(range_out, {"reeb graph: error: analysis option epsilon: 5 is out of its range (0, 1]"}))
      << range_out;
  EXPECT_EQ(range_out.find("read and cleaned"), std::string::npos) << range_out;
  const auto [missing, missing_out] =
      run_command(reeb + " graph " + shell_quoted(dir / "elk.off") + " -o " + shell_quoted(dir / "g.json") + " --ply " +
                  shell_quoted(dir / "no" / "s.ply") + " 2>&1");
  EXPECT_EQ(missing, 1) << missing_out;
  EXPECT_TRUE(contains(missing_out, {"s.ply: cannot write it: the folder", "does not exist"})) << missing_out;
  EXPECT_EQ(missing_out.find("read and cleaned"), std::string::npos) << missing_out;
  // Two outputs on one file (one would be lost), a folder that is a file:
  // refused before the mesh is read, each named.
  const std::string json = (dir / "a.json").string();
  for (const auto& [outputs, message] :
       std::vector<std::pair<std::string, std::string>>{{"-o " + shell_quoted(json) + " --ply " + shell_quoted(json),
                                                         json + ": is also the output " + json},
                                                        {"-o " + shell_quoted(dir / "x" / ".." / "a.json") + " --obj " +
                                                             shell_quoted(json),
                                                         json + ": is also the output"},
                                                        {"-o " + shell_quoted(dir / "elk.off" / "x.json"),
                                                         "x.json: cannot write it: " + (dir / "elk.off").string() +
                                                             " is a file, not a folder"}}) {
    std::filesystem::create_directories(dir / "x");
    const auto [status, out] = run_command(reeb + " graph " + shell_quoted(dir / "elk.off") + " " + outputs + " 2>&1");
    EXPECT_EQ(status, 1) << outputs << "\n" << out;
    EXPECT_TRUE(contains(out, {message})) << out;
    EXPECT_EQ(out.find("read and cleaned"), std::string::npos) << out;
    std::filesystem::remove(dir / "x");
  }

  // A write that fails (a file size limit, as a full disk): exit 1 naming the
  // file and the reason, the previous file untouched, no partial file.
  // Before: "wrote f.json", exit 0 and an empty file.
  std::ofstream(dir / "f.json") << "previous\n";
  for (const std::string command : {"features", "graph"}) {
    const auto [status, out] =
        run_command(with_file_size_limit(reeb + " " + command + " " + shell_quoted(dir / "elk.off") + " -o " +
                                             shell_quoted(dir / "f.json"),
                                         100) +
                    " 2>&1");
    EXPECT_EQ(status, 1) << out;
    EXPECT_TRUE(contains(out, {(dir / "f.json").string() + ": write error: File too large"})) << out;
    EXPECT_EQ(out.find("wrote"), std::string::npos) << out;
    EXPECT_EQ(read_text(dir / "f.json"), "previous\n");
    EXPECT_EQ(files_in(dir / ""), (std::vector<std::string>{"elk.off", "f.json"}));
  }

  // Standard output that cannot be written: exit 1 (before: 0).
  const auto [full, full_out] = run_command(reeb + " features " + shell_quoted(dir / "elk.off") + " 2>&1 >/dev/full");
  EXPECT_EQ(full, 1) << full_out;
  EXPECT_TRUE(contains(full_out, {"reeb features: error: standard output: write failed: No space left on device"}))
      << full_out;
  // A device is written to, never replaced (reeb runs as root in CI).
  const auto [null, null_out] = run_command(reeb + " features " + shell_quoted(dir / "elk.off") + " -o /dev/null 2>&1");
  EXPECT_EQ(null, 0) << null_out;
  EXPECT_FALSE(std::filesystem::is_regular_file("/dev/null"));
}

}  // namespace
}  // namespace reebkit::test

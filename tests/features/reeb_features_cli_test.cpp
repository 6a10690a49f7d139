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
    EXPECT_NE(out.find("14 feature points"), std::string::npos) << method << ": " << out;  // hooves, horns, ears, ...
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

}  // namespace
}  // namespace reebkit::test

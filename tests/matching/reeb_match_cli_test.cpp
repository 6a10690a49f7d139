// `reeb match` end to end on two embedded meshes: the printed distance is the
// library's on the indexed entries whether a mesh is named in a collection or
// given as a file, the OBJ holds both graphs and one line per matched pair,
// and a mesh against itself is at distance 0 with nothing deleted.
#include "io/io_test_util.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/matching/graph_matching.h"
#include "reebkit/store/collection_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace reebkit::test {
namespace {

double printed_distance(const std::string& out) {
  const auto at = out.find("distance ");
  if (at == std::string::npos) return -1.0;
  return std::stod(out.substr(at + 9));
}

TEST(ReebMatchCli, DistanceCorrespondenceAndObj) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  std::filesystem::create_directories(dir / "in");
  for (const char* name : {"cactus.off", "eight.off"})
    std::filesystem::copy_file(embedded_dataset_dir() / name, dir / "in" / name);
  const auto [indexed, index_out] =
      run_command(reeb + " index " + shell_quoted(dir / "in") + " -o " + shell_quoted(dir / "c.h5") + " 2>&1");
  ASSERT_EQ(indexed, 0) << index_out;

  const CollectionReader reader(dir / "c.h5");
  const GraphRecord cactus = reader.entry(*reader.find("cactus.off"));
  const GraphRecord eight = reader.entry(*reader.find("eight.off"));
  const GraphMatch expected = match_graphs(cactus, eight);
  ASSERT_GT(expected.distance, 0.0);

  const std::string collection = (dir / "c.h5").string();
  const auto [status, out] =
      run_command(reeb + " match " + shell_quoted(collection + ":cactus.off") + " " +
                  shell_quoted(dir / "in" / "eight.off") + " --obj " + shell_quoted(dir / "m.obj") + " 2>&1");
  ASSERT_EQ(status, 0) << out;
  EXPECT_NEAR(printed_distance(out), expected.distance, 1e-5 * expected.distance) << out;

  int vertices = 0, lines = 0;
  std::ifstream obj(dir / "m.obj");
  for (std::string line; std::getline(obj, line);) {
    vertices += line.rfind("v ", 0) == 0;
    lines += line.rfind("l ", 0) == 0;
  }
  int matched = 0;
  for (const std::int32_t j : expected.correspondence) matched += j >= 0;
  EXPECT_EQ(vertices, cactus.num_nodes() + eight.num_nodes());
  EXPECT_EQ(lines, cactus.num_edges() + eight.num_edges() + matched);

  const auto [self_status, self] = run_command(reeb + " match " + shell_quoted(collection + ":eight.off") + " " +
                                               shell_quoted(collection + ":eight.off"));
  ASSERT_EQ(self_status, 0) << self;
  EXPECT_NEAR(printed_distance(self), 0.0, 1e-12) << self;
  EXPECT_EQ(self.find("deleted"), std::string::npos) << self;
  EXPECT_EQ(self.find("inserted"), std::string::npos) << self;

  const auto [missing, missing_out] = run_command(reeb + " match " + shell_quoted(collection + ":nope.off") + " " +
                                                  shell_quoted(collection + ":eight.off") + " 2>&1");
  EXPECT_EQ(missing, 1);
  EXPECT_NE(missing_out.find("no mesh named 'nope.off'"), std::string::npos) << missing_out;

  // The collection read is an input: --obj on it is refused, the file kept
  // (before: overwritten with OBJ text, exit 0).
  const std::string bytes = read_file_bytes(dir / "c.h5");
  const auto [onto, onto_out] =
      run_command(reeb + " match " + shell_quoted(collection + ":cactus.off") + " " +
                  shell_quoted(dir / "in" / "eight.off") + " --obj " + shell_quoted(collection) + " 2>&1");
  EXPECT_EQ(onto, 1) << onto_out;
  EXPECT_TRUE(contains(onto_out, {collection + ": is an input of this command"})) << onto_out;
  EXPECT_EQ(read_file_bytes(dir / "c.h5"), bytes);
}

}  // namespace
}  // namespace reebkit::test

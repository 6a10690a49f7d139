// End to end: the `reeb` binary indexes the embedded collection (datasets/),
// `reeb distances` writes the matrices the library computes (rows in .cla
// order) and `reeb query` lists what query_collection ranks, for a mesh of
// the collection and for a mesh file analysed on the fly.
#include "io/io_test_util.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/retrieval/all_pairs.h"
#include "reebkit/retrieval/query.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace reebkit::test {
namespace {

/// The values of `"name": "..."` in a JSON text, in order.
std::vector<std::string> json_names(const std::string& text) {
  std::vector<std::string> out;
  const std::string key = "\"name\": \"";
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1)) {
    const std::size_t begin = at + key.size();
    out.push_back(text.substr(begin, text.find('"', begin) - begin));
  }
  return out;
}

TEST(ReebRetrievalCli, DistancesAndQueryOnTheEmbeddedCollection) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path datasets = embedded_dataset_dir();
  const std::string collection_file = shell_quoted(dir / "c.h5");
  const auto [indexed, index_out] =
      run_command(reeb + " index " + shell_quoted(datasets) + " -o " + collection_file + " --threads 2 2>&1");
  ASSERT_EQ(indexed, 0) << index_out;
  const CollectionReader collection(dir / "c.h5");
  ASSERT_EQ(collection.size(), 8);

  // Two classes listing the meshes in another order than the collection's.
  std::ofstream(dir / "c.cla") << "PSB 1\n2 8\n\nround 0 4\nhelmet\nbunny\ncow\nanchor\n\n"
                                  "limbs 0 4\nhand\nelk\neight\ncactus\n";
  const auto [computed, distances_out] =
      run_command(reeb + " distances " + collection_file + " -o " + shell_quoted(dir / "d.matrix") + " --cla " +
          shell_quoted(dir / "c.cla") + " --ascii " + shell_quoted(dir / "d.txt") + " --threads 2 2>&1");
  ASSERT_EQ(computed, 0) << distances_out;
  const PairwiseDistances want =
      all_pairs_distances(collection, matrix_rows(collection, read_psb_classes(dir / "c.cla")));
  EXPECT_EQ(want.names.front(), "helmet.off");
  EXPECT_EQ(want.names.back(), "cactus.off");
  const DistanceMatrix binary = read_psb_matrix(dir / "d.matrix");
  const DistanceMatrix ascii = read_shrec_matrix(dir / "d.txt");
  ASSERT_EQ(binary.rows(), 8);
  EXPECT_EQ(std::filesystem::file_size(dir / "d.matrix"), 4u * 8 * 8);
  EXPECT_TRUE(binary == ascii);
  for (Eigen::Index i = 0; i < 8; ++i)
    for (Eigen::Index j = 0; j < 8; ++j) EXPECT_EQ(binary(i, j), static_cast<float>(want(i, j))) << i << " " << j;

  // A mesh of the collection, by name.
  QueryOptions options;
  options.k = 4;
  const auto index = collection.find("elk.off");
  ASSERT_TRUE(index);
  std::vector<std::string> ranked;
  for (const QueryResult& r : query_collection(collection, collection.entry(*index), options))
    ranked.push_back(r.name);
  EXPECT_EQ(ranked.front(), "elk.off");  // d(G, G) = 0
  const auto [by_name, by_name_out] = run_command(reeb + " query " + collection_file + " elk.off -k 4 --json");
  ASSERT_EQ(by_name, 0) << by_name_out;
  EXPECT_EQ(json_names(by_name_out), ranked) << by_name_out;
  EXPECT_NE(by_name_out.find("\"query_in_collection\": true"), std::string::npos) << by_name_out;

  // The same mesh as a file: analysed as reeb index does, hence the same graph and ranking.
  const auto [by_file, by_file_out] =
      run_command(reeb + " query " + collection_file + " " + shell_quoted(datasets / "elk.off") + " -k 4 --json");
  ASSERT_EQ(by_file, 0) << by_file_out;
  EXPECT_EQ(json_names(by_file_out), ranked) << by_file_out;
  EXPECT_NE(by_file_out.find("\"query_in_collection\": false"), std::string::npos) << by_file_out;

  // The text listing: a header, then one line per result with its name.
  const auto [text, text_out] = run_command(reeb + " query " + collection_file + " elk.off -k 2");
  ASSERT_EQ(text, 0) << text_out;
  EXPECT_EQ(text_out.rfind("rank\tdistance\tclass\tname\n1\t", 0), 0u) << text_out;
  EXPECT_NE(text_out.find("\telk.off\n2\t"), std::string::npos) << text_out;

  // A class file naming a mesh the collection lacks.
  std::ofstream(dir / "bad.cla") << "PSB 1\n1 2\nround 0 2\nhelmet\nsphere\n";
  const auto [bad, bad_out] = run_command(reeb + " distances " + collection_file + " -o " +
                                          shell_quoted(dir / "x.matrix") + " --cla " + shell_quoted(dir / "bad.cla") +
                                          " 2>&1");
  EXPECT_EQ(bad, 1);
  EXPECT_NE(bad_out.find("model 'sphere' of class 'round' is not in the collection"), std::string::npos) << bad_out;
}

}  // namespace
}  // namespace reebkit::test

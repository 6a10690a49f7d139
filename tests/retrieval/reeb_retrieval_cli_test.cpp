// End to end: the `reeb` binary indexes the embedded collection (datasets/),
// `reeb distances` writes the matrices the library computes (rows in .cla
// order) and `reeb query` lists what query_collection ranks, for a mesh of
// the collection and for a mesh file analysed on the fly.
#include "io/io_test_util.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/retrieval/all_pairs.h"
#include "reebkit/retrieval/query.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace reebkit::test {
namespace {

/// The values of `"key": value` in a JSON text, in order, as written up to
/// the next comma or line end (strings without their quotes).
std::vector<std::string> json_values(const std::string& text, const std::string& key) {
  std::vector<std::string> out;
  const std::string field = "\"" + key + "\": ";
  for (std::size_t at = text.find(field); at != std::string::npos; at = text.find(field, at + 1)) {
    const std::size_t begin = at + field.size();
    std::string value = text.substr(begin, text.find_first_of(",\n", begin) - begin);
    if (value.size() >= 2 && value.front() == '"') value = value.substr(1, value.size() - 2);
    out.push_back(value);
  }
  return out;
}

std::vector<std::string> json_names(const std::string& text) { return json_values(text, "name"); }

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

  // Matching options reach the matcher.
  const auto [weighted, weighted_out] =
      run_command(reeb + " distances " + collection_file + " -o " + shell_quoted(dir / "w.matrix") +
                  " --global-shape-weight 0 --refine-rounds 0 --unmatched-cost 2 2>&1");
  ASSERT_EQ(weighted, 0) << weighted_out;
  AllPairsOptions weights;
  weights.matching.global_shape_weight = 0;
  weights.matching.refine_rounds = 0;
  weights.matching.unmatched_cost = 2;
  const PairwiseDistances weighted_want = all_pairs_distances(collection, matrix_rows(collection), weights);
  const DistanceMatrix weighted_matrix = read_psb_matrix(dir / "w.matrix");
  for (Eigen::Index i = 0; i < 8; ++i)
    for (Eigen::Index j = 0; j < 8; ++j)
      EXPECT_EQ(weighted_matrix(i, j), static_cast<float>(weighted_want(i, j))) << i << " " << j;

  // A mesh of the collection, by name.
  QueryOptions options;
  options.k = 4;
  const auto index = collection.find("elk.off");
  ASSERT_TRUE(index);
  std::vector<std::string> ranked;
  for (const QueryResult& r : query_collection(collection, collection.entry(*index), options)) ranked.push_back(r.name);
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
  const auto [bad, bad_out] =
      run_command(reeb + " distances " + collection_file + " -o " + shell_quoted(dir / "x.matrix") + " --cla " +
                  shell_quoted(dir / "bad.cla") + " 2>&1");
  EXPECT_EQ(bad, 1);
  EXPECT_NE(bad_out.find("model 'sphere' of class 'round' is not in the collection"), std::string::npos) << bad_out;
}

// A collection indexed with other than the default analysis options: a mesh
// file is analysed as the collection was, so a file equal to an indexed mesh
// is at distance 0 from its entry and ranks the collection as querying by
// name does; with the defaults its graph would differ. Resuming the file with
// other options is refused, naming each.
TEST(ReebRetrievalCli, QueryByFileUsesTheCollectionsAnalysisOptions) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path datasets = embedded_dataset_dir();
  const std::string collection_file = shell_quoted(dir / "c.h5");
  const std::string analysis = " --epsilon 0.1 --geodesic dijkstra --min-persistence 0.02";
  const auto [indexed, index_out] = run_command(reeb + " index " + shell_quoted(datasets) + " -o " + collection_file +
                                                analysis + " --threads 2 2>&1");
  ASSERT_EQ(indexed, 0) << index_out;
  const CollectionReader collection(dir / "c.h5");
  const GraphRecord elk = collection.entry(*collection.find("elk.off"));
  EXPECT_GT(match_graphs(analyze_mesh_file(datasets / "elk.off", "elk.off"), elk).distance, 0.0);

  const auto [by_name, by_name_out] = run_command(reeb + " query " + collection_file + " elk.off -k 8 --json");
  ASSERT_EQ(by_name, 0) << by_name_out;
  const auto [by_file, by_file_out] =
      run_command(reeb + " query " + collection_file + " " + shell_quoted(datasets / "elk.off") + " -k 8 --json");
  ASSERT_EQ(by_file, 0) << by_file_out;
  EXPECT_NE(by_file_out.find("\"query_in_collection\": false"), std::string::npos) << by_file_out;
  EXPECT_EQ(json_names(by_file_out), json_names(by_name_out));
  EXPECT_EQ(json_values(by_file_out, "distance"), json_values(by_name_out, "distance"));
  ASSERT_EQ(json_names(by_file_out).size(), 8u);
  EXPECT_EQ(json_names(by_file_out).front(), "elk.off");
  EXPECT_EQ(json_values(by_file_out, "distance").front(), "0");

  // reeb match: a mesh file against an entry is analysed as the collection was.
  const auto [matched, match_out] = run_command(reeb + " match " + shell_quoted((dir / "c.h5").string() + ":elk.off") +
                                                " " + shell_quoted(datasets / "elk.off"));
  ASSERT_EQ(matched, 0) << match_out;
  EXPECT_EQ(match_out.rfind("distance 0\n", 0), 0u) << match_out;
  const auto [overridden, overridden_out] =
      run_command(reeb + " match " + shell_quoted((dir / "c.h5").string() + ":elk.off") + " " +
                  shell_quoted(datasets / "elk.off") + " --epsilon 0.05 2>&1");
  EXPECT_EQ(overridden, 1);
  EXPECT_NE(overridden_out.find("analysed with the analysis options of"), std::string::npos) << overridden_out;

  const auto [resumed, resume_out] = run_command(reeb + " index " + shell_quoted(datasets) + " -o " + collection_file +
                                                 " --resume --epsilon 0.1 --min-persistence 0.03 2>&1");
  EXPECT_EQ(resumed, 1);
  EXPECT_NE(resume_out.find("cannot resume: the file was indexed with other analysis options"), std::string::npos)
      << resume_out;
  EXPECT_NE(resume_out.find("geodesic: dijkstra in the file, fmm now"), std::string::npos) << resume_out;
  EXPECT_NE(resume_out.find("min_persistence: 0.02 in the file, 0.03 now"), std::string::npos) << resume_out;
  EXPECT_EQ(resume_out.find("epsilon:"), std::string::npos) << resume_out;
  const auto [same, same_out] = run_command(reeb + " index " + shell_quoted(datasets) + " -o " + collection_file +
                                            " --resume" + analysis + " 2>&1");
  ASSERT_EQ(same, 0) << same_out;
  EXPECT_NE(same_out.find("0 ok, 0 failed, 8 already indexed"), std::string::npos) << same_out;
}

/// The text of a file with every occurrence of `from` replaced by `to`.
std::string text_with(const std::filesystem::path& path, const std::string& from, const std::string& to) {
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// reeb distances without --cla on a collection indexed with --classes writes
// the rows in the order of that .cla, so that reeb eval given only the .cla
// reports what it reports with the explicit --cla; the order used is printed.
TEST(ReebRetrievalCli, DistancesFollowTheClassFileTheCollectionWasIndexedWith) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path datasets = embedded_dataset_dir(), cla = dir / "c.cla";
  // Classes that interleave with the collection order (anchor, bunny, cactus, ...).
  std::ofstream(cla) << "PSB 1\n2 8\n\nround 0 4\nhelmet\nbunny\ncow\nanchor\n\n"
                        "limbs 0 4\nhand\nelk\neight\ncactus\n";
  const auto run = [&](const std::string& command) {
    const auto [status, out] = run_command(reeb + " " + command + " 2>&1");
    EXPECT_EQ(status, 0) << command << "\n" << out;
    return out;
  };
  run("index " + shell_quoted(datasets) + " -o " + shell_quoted(dir / "c.h5") + " --classes " + shell_quoted(cla) +
      " --threads 2");
  std::filesystem::create_directories(dir / "implicit");
  std::filesystem::create_directories(dir / "explicit");
  const std::string implicit =
      run("distances " + shell_quoted(dir / "c.h5") + " -o " + shell_quoted(dir / "implicit" / "d.matrix"));
  EXPECT_NE(implicit.find("rows in the .cla order of " + cla.string()), std::string::npos) << implicit;
  const std::string explicit_out = run("distances " + shell_quoted(dir / "c.h5") + " -o " +
                                       shell_quoted(dir / "explicit" / "d.matrix") + " --cla " + shell_quoted(cla));
  EXPECT_NE(explicit_out.find("rows in the .cla order of " + cla.string()), std::string::npos) << explicit_out;
  EXPECT_TRUE(read_psb_matrix(dir / "implicit" / "d.matrix") == read_psb_matrix(dir / "explicit" / "d.matrix"));
  for (const char* folder : {"implicit", "explicit"})
    run("eval " + shell_quoted(dir / folder / "d.matrix") + " --cla " + shell_quoted(cla) + " --name reebkit -o " +
        shell_quoted(dir / folder / "report") + " --no-plot");
  const std::string report = text_with(dir / "implicit" / "report" / "report.md", "implicit", "explicit");
  EXPECT_NE(report.find("| reebkit | micro (8 queries) |"), std::string::npos) << report;
  EXPECT_EQ(report, text_with(dir / "explicit" / "report" / "report.md", "implicit", "explicit"));

  // Without classes: collection order, which that .cla would misread.
  run("index " + shell_quoted(datasets) + " -o " + shell_quoted(dir / "plain.h5") + " --threads 2");
  const std::string plain =
      run("distances " + shell_quoted(dir / "plain.h5") + " -o " + shell_quoted(dir / "p.matrix"));
  EXPECT_NE(plain.find("rows in the collection order\n"), std::string::npos) << plain;
  EXPECT_FALSE(read_psb_matrix(dir / "p.matrix") == read_psb_matrix(dir / "explicit" / "d.matrix"));

  // Classes listing models the collection lacks: collection order, and why.
  run("index " + shell_quoted(datasets / "elk.off") + " " + shell_quoted(datasets / "cow.off") + " -o " +
      shell_quoted(dir / "two.h5") + " --classes " + shell_quoted(cla));
  const std::string two = run("distances " + shell_quoted(dir / "two.h5") + " -o " + shell_quoted(dir / "t.matrix"));
  EXPECT_NE(two.find("rows in the collection order (the classes of " + cla.string() +
                     " do not fit the collection: model 'helmet' of class 'round' is not in the collection)"),
            std::string::npos)
      << two;
}

}  // namespace
}  // namespace reebkit::test

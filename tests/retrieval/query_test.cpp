// Query by example: with candidates >= the collection size the ranking is
// brute force (match_graphs against every entry); with fewer it reranks
// exactly the nearest signatures; failed entries never come back.
#include "reebkit/retrieval/query.h"
#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "retrieval/retrieval_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>

namespace reebkit::test {
namespace {

/// Every ok entry matched to the query, by (distance, index), the first k.
std::vector<QueryResult> brute_force(const CollectionReader& collection, const GraphRecord& query, int k) {
  std::vector<QueryResult> all;
  for (std::int64_t i = 0; i < collection.size(); ++i) {
    const GraphRecord e = collection.entry(i);
    if (e.ok) all.push_back({i, e.name, e.class_label, match_graphs(query, e).distance, 0.0});
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const QueryResult& a, const QueryResult& b) { return a.distance < b.distance; });
  all.resize(std::min(all.size(), static_cast<std::size_t>(k)));
  return all;
}

/// The same entries (index, name, class) at the same distances, rank by rank.
void expect_same_ranking(const std::vector<QueryResult>& got, const std::vector<QueryResult>& want,
                         const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t r = 0; r < got.size(); ++r) {
    EXPECT_EQ(got[r].index, want[r].index) << what << " rank " << r;
    EXPECT_EQ(got[r].name, want[r].name);
    EXPECT_EQ(got[r].class_label, want[r].class_label);
    EXPECT_EQ(got[r].distance, want[r].distance);
  }
}

TEST(QueryCollection, WithEveryCandidateTheRankingIsBruteForce) {
  const TempDir dir;
  write_generated_collection(dir / "c.h5");
  const CollectionReader collection(dir / "c.h5");
  const SearchableCollection searchable = load_searchable(collection);
  ASSERT_EQ(searchable.index.size(), collection.size() - 1);  // the failed entry is not indexed
  ASSERT_EQ(searchable.entries.size(), static_cast<std::size_t>(collection.size()));
  for (std::int64_t i = 0; i < collection.size(); ++i) {  // one range read == entry by entry
    const GraphRecord& e = searchable.entries[static_cast<std::size_t>(i)];
    const GraphRecord one = collection.entry(i);
    EXPECT_EQ(e.name, one.name);
    EXPECT_EQ(e.nodes, one.nodes);
    EXPECT_EQ(e.node_attributes, one.node_attributes);
    EXPECT_EQ(e.edges, one.edges);
  }
  for (const GraphRecord& query : generated_entries()) {
    if (!query.ok) continue;
    for (const int k : {1, 5, 100}) {
      QueryOptions options;
      options.k = k;
      options.candidates = static_cast<int>(collection.size());
      expect_same_ranking(query_collection(searchable, query, options), brute_force(collection, query, k), query.name);
    }
  }
}

TEST(QueryCollection, FewCandidatesRerankTheNearestSignatures) {
  const TempDir dir;
  write_generated_collection(dir / "c.h5");
  const CollectionReader collection(dir / "c.h5");
  const SearchableCollection searchable = load_searchable(collection);
  const GraphRecord& query = generated_entries()[3];
  QueryOptions options;
  options.k = 3;
  options.candidates = 4;
  const std::vector<QueryResult> got = query_collection(searchable, query, options);
  ASSERT_EQ(got.size(), 3u);
  std::vector<std::int64_t> nearest;
  for (const SignatureNeighbour& n : searchable.index.nearest(query.signature, 4)) nearest.push_back(n.row);
  for (std::size_t r = 0; r < got.size(); ++r) {
    EXPECT_NE(std::find(nearest.begin(), nearest.end(), got[r].index), nearest.end()) << r;
    EXPECT_EQ(got[r].distance, match_graphs(query, collection.entry(got[r].index)).distance);
    if (r > 0) {
      EXPECT_LE(got[r - 1].distance, got[r].distance);
    }
  }
  // One thread or two: the same ranking.
  options.threads = 1;
  const std::vector<QueryResult> serial = query_collection(searchable, query, options);
  options.threads = 2;
  const std::vector<QueryResult> parallel = query_collection(searchable, query, options);
  ASSERT_EQ(serial.size(), got.size());
  ASSERT_EQ(parallel.size(), got.size());
  for (std::size_t r = 0; r < got.size(); ++r) {
    EXPECT_EQ(serial[r].index, parallel[r].index);
    EXPECT_EQ(serial[r].distance, parallel[r].distance);
  }
  // The one-shot form reads the same collection.
  const std::vector<QueryResult> once = query_collection(collection, query, options);
  ASSERT_EQ(once.size(), got.size());
  for (std::size_t r = 0; r < got.size(); ++r) EXPECT_EQ(once[r].index, got[r].index);
}

/// `e` with its node attributes scaled by 1 + U(-amount, amount) and its
/// signature moved by U(-amount, amount) (clamped to [0, 1]).
GraphRecord jittered(GraphRecord e, double amount, std::mt19937& random) {
  std::uniform_real_distribution<double> u(-amount, amount);
  for (double& a : e.node_attributes) a *= 1.0 + u(random);
  for (double& x : e.signature) x = std::clamp(x + u(random), 0.0, 1.0);
  return e;
}

TEST(QueryCollection, PruningGivesTheRankingOfMatchingEveryCandidate) {
  // The generated entries and 10 jittered copies of each (133 entries, many
  // near-ties); queries: the entries and other jittered copies; every k and
  // number of candidates, 1 and 2 threads: skipping candidates by their
  // lower bound changes nothing in the ranking.
  std::mt19937 random(3);
  const TempDir dir;
  {
    CollectionWriter writer(dir / "c.h5", Provenance{}, false);
    for (const GraphRecord& e : generated_entries()) writer.append(e);
    for (int copy = 0; copy < 10; ++copy)
      for (const GraphRecord& e : generated_entries()) {
        if (!e.ok) continue;
        GraphRecord c = jittered(e, copy < 5 ? 0.02 : 0.2, random);
        c.name += "-copy" + std::to_string(copy);
        writer.append(c);
      }
    writer.close();
  }
  const SearchableCollection searchable = load_searchable(CollectionReader(dir / "c.h5"));
  std::vector<GraphRecord> queries;
  for (const GraphRecord& e : generated_entries()) {
    if (!e.ok) continue;
    queries.push_back(e);
    queries.push_back(jittered(e, 0.05, random));
  }
  int cases = 0, pruned = 0;
  for (const GraphRecord& query : queries)
    for (const int k : {1, 3, 10})
      for (const int candidates : {10, 40, 133})
        for (const int threads : {1, 2}) {
          QueryOptions options;
          options.k = k;
          options.candidates = candidates;
          options.threads = threads;
          options.prune = false;
          const std::vector<QueryResult> want = query_collection(searchable, query, options);
          options.prune = true;
          const std::vector<QueryResult> got = query_collection(searchable, query, options);
          ASSERT_EQ(got.size(), want.size());
          for (std::size_t r = 0; r < got.size(); ++r) {
            EXPECT_EQ(got[r].index, want[r].index) << query.name << " k " << k << " rank " << r;
            EXPECT_EQ(got[r].distance, want[r].distance);
            EXPECT_EQ(got[r].signature_distance, want[r].signature_distance);
            EXPECT_EQ(got[r].name, want[r].name);
          }
          // Not vacuous: mostly some candidate is skipped (its bound is above the k-th distance).
          ++cases;
          for (const SignatureNeighbour& n : searchable.index.nearest(query.signature, candidates))
            if (match_lower_bound(make_matchable_graph(query), searchable.graphs[static_cast<std::size_t>(n.row)]) >
                want.back().distance) {
              ++pruned;
              break;
            }
        }
  EXPECT_GT(pruned, cases / 2) << "of " << cases;
}

TEST(QueryCollection, RejectsBadOptionsAndFailedQueries) {
  const TempDir dir;
  write_generated_collection(dir / "c.h5");
  const CollectionReader collection(dir / "c.h5");
  const GraphRecord& query = generated_entries()[0];
  QueryOptions options;
  options.k = 0;
  EXPECT_THROW(query_collection(collection, query, options), InvalidArgument);
  options.k = 5;
  options.candidates = 0;
  EXPECT_THROW(query_collection(collection, query, options), InvalidArgument);
  options.candidates = 10;
  options.threads = -1;
  EXPECT_THROW(query_collection(collection, query, options), InvalidArgument);
  EXPECT_THROW(query_collection(collection, generated_entries()[6], QueryOptions{}), InvalidArgument);
  const SearchableCollection other{{}, SignatureIndex({0, 0}, 2), {}};
  EXPECT_THROW(query_collection(other, query, QueryOptions{}), InvalidArgument);
  SearchableCollection no_graphs = load_searchable(collection);
  no_graphs.graphs.clear();
  EXPECT_THROW(query_collection(no_graphs, query, QueryOptions{}), InvalidArgument);
}

TEST(QueryFile, ReadsTheCandidatesGraphsAsTheWholeCollectionHasThem) {
  const TempDir dir;
  write_generated_collection(dir / "c.h5");
  const CollectionReader collection(dir / "c.h5");
  EXPECT_FALSE(open_query_file(collection).has_value());  // none written yet
  write_query_file(collection);
  const std::optional<QueryableFile> file = open_query_file(collection);
  ASSERT_TRUE(file.has_value());
  const std::vector<GraphRecord> all = collection.entries(0, collection.size());
  std::vector<std::int64_t> rows = file->index.row_of();
  ASSERT_EQ(rows.size(), all.size() - 1);  // the failed entry has no signature row
  std::reverse(rows.begin(), rows.end());  // any order, an entry twice
  rows.push_back(rows.front());
  const std::vector<GraphRecord> lazy = file->file.graphs(rows);
  ASSERT_EQ(lazy.size(), rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const GraphRecord& e = all[static_cast<std::size_t>(rows[k])];
    EXPECT_TRUE(lazy[k].ok);
    EXPECT_EQ(lazy[k].signature, e.signature) << e.name;
    EXPECT_EQ(lazy[k].nodes, e.nodes) << e.name;
    EXPECT_EQ(lazy[k].node_attributes, e.node_attributes) << e.name;
    EXPECT_EQ(lazy[k].edges, e.edges) << e.name;
  }
  EXPECT_THROW(file->file.graphs({6}), InvalidArgument);  // the failed entry
}

TEST(QueryFile, AQueryOnTheFileGivesTheResultsOfTheLoadedCollection) {
  const TempDir dir;
  write_generated_collection(dir / "c.h5");
  const CollectionReader collection(dir / "c.h5");
  write_query_file(collection);
  const std::optional<QueryableFile> file = open_query_file(collection);
  ASSERT_TRUE(file.has_value());
  const SearchableCollection searchable = load_searchable(collection);
  EXPECT_EQ(file->index.row_of(), searchable.index.row_of());
  for (const GraphRecord& query : generated_entries()) {
    if (!query.ok) continue;
    for (const int candidates : {1, 4, 100})
      for (const int k : {1, 3, 20}) {
        QueryOptions options;
        options.k = k;
        options.candidates = candidates;
        const std::vector<QueryResult> got = query_collection(collection, *file, query, options);
        const std::vector<QueryResult> want = query_collection(searchable, query, options);
        expect_same_ranking(got, want, query.name);
        for (std::size_t r = 0; r < std::min(got.size(), want.size()); ++r)
          EXPECT_EQ(got[r].signature_distance, want[r].signature_distance) << query.name << " rank " << r;
      }
  }
}

TEST(QueryFile, IsIgnoredOnceTheCollectionChanges) {
  const TempDir dir;
  write_generated_collection(dir / "c.h5");
  write_query_file(CollectionReader(dir / "c.h5"));
  {
    CollectionWriter writer(dir / "c.h5", Provenance{}, true);  // resume: one more entry
    GraphRecord extra = generated_entries().front();
    extra.name = "extra";
    writer.append(extra);
    writer.close();
  }
  const CollectionReader grown(dir / "c.h5");
  EXPECT_FALSE(open_query_file(grown).has_value());
  // query_collection then reads the whole collection: the new entry is found
  const std::vector<QueryResult> results = query_collection(grown, generated_entries().front(), {});
  EXPECT_TRUE(std::any_of(results.begin(), results.end(), [](const QueryResult& r) { return r.name == "extra"; }));
}

}  // namespace
}  // namespace reebkit::test

// Query by example: the entries of a collection nearest to a query
// graph. The `candidates` entries whose signatures are nearest to the query's
// (SignatureIndex) are reranked by attribute-based graph matching
// (match_graphs) and the best `k` returned. With candidates >= the number of
// entries the ranking is that of matching the query against every entry.
#pragma once

#include "reebkit/matching/graph_matching.h"
#include "reebkit/retrieval/signature_index.h"
#include "reebkit/store/collection_file.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace reebkit {

struct QueryOptions {
  int k = 10;            ///< results returned; >= 1
  int candidates = 100;  ///< nearest signatures reranked by graph matching (at least k); >= 1
  /// OpenMP threads bounding and matching the candidates; 0 =
  /// omp_get_max_threads(). One by default: a query is short, and on a busy
  /// machine its second thread waits for a core (docs/benchmarks.md, "Query
  /// and all-pairs distances").
  int threads = 1;
  /// Match the candidates by increasing match_lower_bound and skip those
  /// whose bound is above the k-th best distance found so far: the same
  /// ranking with fewer matches. false: match every candidate.
  bool prune = true;
  MatchingOptions matching;  ///< the cost model of match_graphs
};

struct QueryResult {
  std::int64_t index = 0;  ///< of the entry in the collection
  std::string name;
  std::string class_label;          ///< "" when the collection has none
  double distance = 0.0;            ///< match_graphs(query, entry).distance
  double signature_distance = 0.0;  ///< Euclidean distance between the signatures (the pre-filter's)
};

/// A collection held in memory for many queries: its entries, the index of
/// their signatures and their graphs in matchable form.
struct SearchableCollection {
  std::vector<GraphRecord> entries;
  SignatureIndex index;
  /// make_matchable_graph of each entry (an empty graph for a failed entry),
  /// built once instead of once per query and candidate (its memory per
  /// graph: docs/benchmarks.md).
  std::vector<MatchableGraph> graphs;
};

/// Every entry of `collection` (one read), SignatureIndex(signatures,
/// kSignatureLength) and the entries' matchable graphs.
SearchableCollection load_searchable(const CollectionReader& collection);

/// The k entries nearest to `query` by graph matching among the `candidates`
/// nearest by signature, by increasing distance (ties by increasing index).
/// Failed entries are never returned; an entry named like the query is (at
/// distance 0 when it is the same graph). Throws InvalidArgument when the
/// query has no graph, on k < 1, candidates < 1 or threads < 0, or when the
/// index does not cover the entries. The same ranking whatever the number of threads.
std::vector<QueryResult> query_collection(const SearchableCollection& collection, const GraphRecord& query,
                                          const QueryOptions& options = {});

/// A collection queried without reading it whole: the signature index of its
/// query file (store/collection_file.h, QueryFile), the saved tree loaded and
/// the rows mapped, and each candidate's graph read from that file when it is one.
struct QueryableFile {
  QueryFile file;
  SignatureIndex index;
};

/// Builds the signature index of `collection` (a k-d tree) and writes its
/// query file with it (QueryFile::write).
void write_query_file(const CollectionReader& collection);

/// The query file of `collection` with its signature index, or nullopt when
/// there is none for the collection as it is (QueryFile::open).
std::optional<QueryableFile> open_query_file(const CollectionReader& collection);

/// query_collection on the candidates' graphs read from `file`: the same
/// results as on load_searchable(collection).
std::vector<QueryResult> query_collection(const CollectionReader& collection, const QueryableFile& file,
                                          const GraphRecord& query, const QueryOptions& options = {});

/// The same for one query: with the query file when there is one for the
/// collection as it is, otherwise load_searchable, then query_collection.
std::vector<QueryResult> query_collection(const CollectionReader& collection, const GraphRecord& query,
                                          const QueryOptions& options = {});

}  // namespace reebkit

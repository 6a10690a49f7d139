// Query by example (issue 5): the entries of a collection nearest to a query
// graph. The `candidates` entries whose signatures are nearest to the query's
// (SignatureIndex) are reranked by attribute-based graph matching
// (match_graphs) and the best `k` returned. With candidates >= the number of
// entries the ranking is that of matching the query against every entry.
#pragma once

#include "reebkit/matching/graph_matching.h"
#include "reebkit/retrieval/signature_index.h"
#include "reebkit/store/collection_file.h"

#include <cstdint>
#include <string>
#include <vector>

namespace reebkit {

struct QueryOptions {
  int k = 10;             ///< results returned; >= 1
  int candidates = 100;   ///< nearest signatures reranked by graph matching (at least k); >= 1
  /// OpenMP threads bounding and matching the candidates; 0 =
  /// omp_get_max_threads(). One by default: a typical query takes 0.5 ms and
  /// the slowest of bench/retrieval_bench (a 113-node graph) 12 ms on one
  /// thread; with a free core two threads take that to 9 ms, but on a busy
  /// machine a query's second thread waits for a core (median 16 ms with two
  /// threads at load 3 on 2 cores).
  int threads = 1;
  /// Match the candidates by increasing match_lower_bound and skip those
  /// whose bound is above the k-th best distance found so far: the same
  /// ranking with fewer matches. false: match every candidate.
  bool prune = true;
  MatchingOptions matching;  ///< the cost model of match_graphs
};

struct QueryResult {
  std::int64_t index = 0;           ///< of the entry in the collection
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
  /// built once instead of once per query and candidate: 3.6 KB per graph
  /// on SHREC07 as allocated (36 MB for 10,000 graphs of 3 to 113 nodes,
  /// 28 MB of it the node features, 3.5 MB the dense n x n adjacency, kept:
  /// it is the fastest edge test).
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

/// The same for one query: load_searchable, then query_collection.
std::vector<QueryResult> query_collection(const CollectionReader& collection, const GraphRecord& query,
                                          const QueryOptions& options = {});

}  // namespace reebkit

#include "reebkit/retrieval/query.h"

#include "reebkit/core/error.h"

#include <omp.h>

#include <algorithm>
#include <string>

namespace reebkit {

SearchableCollection load_searchable(const CollectionReader& collection) {
  SearchableCollection searchable{collection.entries(0, collection.size()),
                                  SignatureIndex(collection.signatures(), kSignatureLength), {}};
  searchable.graphs.reserve(searchable.entries.size());
  for (const CollectionEntry& e : searchable.entries)
    searchable.graphs.push_back(e.ok ? make_matchable_graph(e) : MatchableGraph{});
  return searchable;
}

std::vector<QueryResult> query_collection(const SearchableCollection& collection, const CollectionEntry& query,
                                          const QueryOptions& options) {
  if (!query.ok) throw InvalidArgument("query '" + query.name + "' has no graph: " + query.error);
  if (options.k < 1 || options.candidates < 1 || options.threads < 0)
    throw InvalidArgument("query: need k >= 1, candidates >= 1 and threads >= 0 (k = " + std::to_string(options.k) +
                          ", candidates = " + std::to_string(options.candidates) +
                          ", threads = " + std::to_string(options.threads) + ")");
  if (collection.index.dimension() != kSignatureLength || collection.graphs.size() != collection.entries.size())
    throw InvalidArgument("query: the signature index or the graphs do not match the collection");
  const MatchableGraph query_graph = make_matchable_graph(query);

  const std::vector<SignatureNeighbour> nearest =
      collection.index.nearest(query.signature, std::max(options.k, options.candidates));
  for (const SignatureNeighbour& n : nearest)
    if (n.row >= static_cast<std::int64_t>(collection.entries.size()))
      throw InvalidArgument("query: the signature index does not match the collection");
  std::vector<QueryResult> ranked(nearest.size());
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const auto count = static_cast<std::int64_t>(nearest.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t c = 0; c < count; ++c) {
    const SignatureNeighbour& n = nearest[static_cast<std::size_t>(c)];
    const auto row = static_cast<std::size_t>(n.row);
    const CollectionEntry& entry = collection.entries[row];
    ranked[static_cast<std::size_t>(c)] = {
        n.row, entry.name, entry.class_label,
        match_graphs(query_graph, collection.graphs[row], options.matching).distance, n.distance};
  }
  std::sort(ranked.begin(), ranked.end(), [](const QueryResult& a, const QueryResult& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.index < b.index;
  });
  if (ranked.size() > static_cast<std::size_t>(options.k)) ranked.resize(static_cast<std::size_t>(options.k));
  return ranked;
}

std::vector<QueryResult> query_collection(const CollectionReader& collection, const CollectionEntry& query,
                                          const QueryOptions& options) {
  return query_collection(load_searchable(collection), query, options);
}

}  // namespace reebkit

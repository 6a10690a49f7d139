#include "reebkit/retrieval/query.h"

#include "reebkit/core/error.h"
#include "reebkit/matching/matching_options.h"

#include <omp.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <queue>
#include <string>

namespace reebkit {

SearchableCollection load_searchable(const CollectionReader& collection) {
  SearchableCollection searchable{collection.entries(0, collection.size()),
                                  SignatureIndex(collection.signatures(), kSignatureLength),
                                  {}};
  searchable.graphs = make_matchable_graphs(searchable.entries);
  return searchable;
}

namespace {

void check_query(const GraphRecord& query, const QueryOptions& options) {
  if (!query.ok) throw InvalidArgument("query '" + query.name + "' has no graph: " + query.error);
  if (options.k < 1 || options.candidates < 1 || options.threads < 0)
    throw InvalidArgument("query: need k >= 1, candidates >= 1 and threads >= 0 (k = " + std::to_string(options.k) +
                          ", candidates = " + std::to_string(options.candidates) +
                          ", threads = " + std::to_string(options.threads) + ")");
  check_matching_options(options.matching);
}

/// The `index` entries nearest to `query` by signature, checked to lie in a
/// collection of `size` entries.
std::vector<SignatureNeighbour> nearest_signatures(const SignatureIndex& index, const GraphRecord& query,
                                                   const QueryOptions& options, std::size_t size) {
  if (index.dimension() != kSignatureLength)
    throw InvalidArgument("query: the signature index does not match the collection");
  std::vector<SignatureNeighbour> nearest = index.nearest(query.signature, std::max(options.k, options.candidates));
  for (const SignatureNeighbour& n : nearest)
    if (n.row >= static_cast<std::int64_t>(size))
      throw InvalidArgument("query: the signature index does not match the collection");
  return nearest;
}

/// The best options.k of the candidates `nearest` (graphs[c] the graph of
/// nearest[c]) by graph matching against `query`, by increasing distance
/// (ties by increasing index); names and classes left empty.
std::vector<QueryResult> rank_candidates(const MatchableGraph& query_graph,
                                         const std::vector<SignatureNeighbour>& nearest,
                                         const std::vector<const MatchableGraph*>& graphs,
                                         const QueryOptions& options) {
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const auto count = static_cast<std::int64_t>(nearest.size());
  const auto graph_of = [&](std::int64_t c) -> const MatchableGraph& { return *graphs[static_cast<std::size_t>(c)]; };
  // Pruning keeps the ranking exact: the k-th best distance among any of
  // the candidates matched so far is >= the k-th best among all of them, and
  // a candidate of the final ranking has bound <= distance <= that, so it is
  // never skipped (ties included: skipping needs bound > threshold).
  std::vector<double> bound(nearest.size(), -std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> order(nearest.size());
  std::iota(order.begin(), order.end(), std::int64_t{0});
  if (options.prune) {
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t c = 0; c < count; ++c)
      bound[static_cast<std::size_t>(c)] = match_lower_bound(query_graph, graph_of(c), options.matching);
    std::sort(order.begin(), order.end(), [&](std::int64_t x, std::int64_t y) {
      const double bx = bound[static_cast<std::size_t>(x)], by = bound[static_cast<std::size_t>(y)];
      return bx != by ? bx < by : x < y;
    });
  }
  std::vector<double> distance(nearest.size());
  std::vector<char> matched(nearest.size(), 0);
  std::priority_queue<double> best;  // the k smallest distances so far, the largest on top
  double kth = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t r = 0; r < count; ++r) {
    const auto c = static_cast<std::size_t>(order[static_cast<std::size_t>(r)]);
    double threshold = 0.0;
#pragma omp critical(reebkit_query_best)
    threshold = kth;
    if (bound[c] > threshold) continue;
    const double d =
        options.prune
            ? match_distance_up_to(query_graph, graph_of(order[static_cast<std::size_t>(r)]), threshold,
                                   options.matching)
            : match_graphs(query_graph, graph_of(order[static_cast<std::size_t>(r)]), options.matching).distance;
    if (d > threshold) continue;  // exact or a lower bound: either way not in the ranking
#pragma omp critical(reebkit_query_best)
    {
      distance[c] = d;
      matched[c] = 1;
      best.push(d);
      if (best.size() > static_cast<std::size_t>(options.k)) best.pop();
      if (best.size() == static_cast<std::size_t>(options.k)) kth = best.top();
    }
  }
  std::vector<QueryResult> ranked;
  for (std::size_t c = 0; c < nearest.size(); ++c)
    if (matched[c]) ranked.push_back({nearest[c].row, "", "", distance[c], nearest[c].distance});
  std::sort(ranked.begin(), ranked.end(), [](const QueryResult& a, const QueryResult& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.index < b.index;
  });
  if (ranked.size() > static_cast<std::size_t>(options.k)) ranked.resize(static_cast<std::size_t>(options.k));
  return ranked;
}

}  // namespace

std::vector<QueryResult> query_collection(const SearchableCollection& collection, const GraphRecord& query,
                                          const QueryOptions& options) {
  check_query(query, options);
  if (collection.graphs.size() != collection.entries.size())
    throw InvalidArgument("query: the signature index or the graphs do not match the collection");
  const std::vector<SignatureNeighbour> nearest =
      nearest_signatures(collection.index, query, options, collection.entries.size());
  std::vector<const MatchableGraph*> graphs;
  for (const SignatureNeighbour& n : nearest) graphs.push_back(&collection.graphs[static_cast<std::size_t>(n.row)]);
  std::vector<QueryResult> ranked = rank_candidates(make_matchable_graph(query), nearest, graphs, options);
  for (QueryResult& r : ranked) {
    const GraphRecord& entry = collection.entries[static_cast<std::size_t>(r.index)];
    r.name = entry.name;
    r.class_label = entry.class_label;
  }
  return ranked;
}

void write_query_file(const CollectionReader& collection) {
  const SignatureIndex index(collection.signatures(), kSignatureLength);
  QueryFile::write(collection, index.rows(), index.row_of(), index.save());
}

std::optional<QueryableFile> open_query_file(const CollectionReader& collection) {
  std::optional<QueryFile> file = QueryFile::open(collection);
  if (!file) return std::nullopt;
  SignatureIndex index(file->rows(), file->row_of(), kSignatureLength, file->saved_index());
  return QueryableFile{std::move(*file), std::move(index)};
}

std::vector<QueryResult> query_collection(const CollectionReader& collection, const QueryableFile& file,
                                          const GraphRecord& query, const QueryOptions& options) {
  check_query(query, options);
  const std::vector<SignatureNeighbour> nearest =
      nearest_signatures(file.index, query, options, static_cast<std::size_t>(collection.size()));
  std::vector<std::int64_t> rows;
  for (const SignatureNeighbour& n : nearest) rows.push_back(n.row);
  const std::vector<MatchableGraph> matchable = make_matchable_graphs(file.file.graphs(rows));
  std::vector<const MatchableGraph*> graphs;
  for (const MatchableGraph& g : matchable) graphs.push_back(&g);
  std::vector<QueryResult> ranked = rank_candidates(make_matchable_graph(query), nearest, graphs, options);
  for (QueryResult& r : ranked) {
    r.name = collection.name(r.index);
    r.class_label = collection.class_label(r.index);
  }
  return ranked;
}

std::vector<QueryResult> query_collection(const CollectionReader& collection, const GraphRecord& query,
                                          const QueryOptions& options) {
  if (const std::optional<QueryableFile> file = open_query_file(collection))
    return query_collection(collection, *file, query, options);
  return query_collection(load_searchable(collection), query, options);
}

}  // namespace reebkit

#include "reebkit/retrieval/all_pairs.h"

#include "reebkit/core/error.h"

#include <omp.h>

#include <unordered_map>

namespace reebkit {

PairwiseDistances all_pairs_distances(const std::vector<GraphRecord>& entries, const AllPairsOptions& options) {
  if (options.threads < 0)
    throw InvalidArgument("all-pairs distances: threads " + std::to_string(options.threads) + " < 0");
  PairwiseDistances out;
  const std::int64_t n = static_cast<std::int64_t>(entries.size());
  for (const GraphRecord& e : entries) out.names.push_back(e.name);
  out.values.assign(static_cast<std::size_t>(n * n), 0.0);
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const std::vector<MatchableGraph> graphs = make_matchable_graphs(entries);  // once, not once per pair
  // Rows get shorter with i (only j > i): a dynamic schedule balances them.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i) {
    const bool a_ok = entries[static_cast<std::size_t>(i)].ok;
    for (std::int64_t j = i + 1; j < n; ++j) {
      const double d = a_ok && entries[static_cast<std::size_t>(j)].ok
                           ? match_graphs(graphs[static_cast<std::size_t>(i)], graphs[static_cast<std::size_t>(j)],
                                          options.matching)
                                 .distance
                           : kFailedEntryDistance;
      out.values[static_cast<std::size_t>(i * n + j)] = d;
      out.values[static_cast<std::size_t>(j * n + i)] = d;
    }
  }
  return out;
}

std::vector<std::int64_t> matrix_rows(const CollectionReader& collection, const std::vector<PsbClass>& classes) {
  std::vector<std::int64_t> rows;
  if (classes.empty()) {
    for (std::int64_t i = 0; i < collection.size(); ++i) rows.push_back(i);
    return rows;
  }
  // class_of with every model as its own class names the model an entry is.
  ClassMap model_of;
  for (const PsbClass& c : classes)
    for (const std::string& m : c.models) model_of.emplace(m, m);
  std::unordered_map<std::string, std::int64_t> entry_of;
  for (std::int64_t i = 0; i < collection.size(); ++i) {
    const std::string model = class_of(model_of, collection.names()[static_cast<std::size_t>(i)]);
    if (model.empty()) continue;
    if (!entry_of.emplace(model, i).second)
      throw Error("model '" + model + "' of the classes is two entries of the collection: '" +
                  collection.names()[static_cast<std::size_t>(entry_of[model])] + "' and '" +
                  collection.names()[static_cast<std::size_t>(i)] + "'");
  }
  for (const PsbClass& c : classes)
    for (const std::string& m : c.models) {
      const auto it = entry_of.find(m);
      if (it == entry_of.end()) throw Error("model '" + m + "' of class '" + c.name + "' is not in the collection");
      rows.push_back(it->second);
    }
  return rows;
}

PairwiseDistances all_pairs_distances(const CollectionReader& collection, const std::vector<std::int64_t>& rows,
                                   const AllPairsOptions& options) {
  std::vector<GraphRecord> all = collection.entries(0, collection.size());
  std::vector<GraphRecord> entries;
  entries.reserve(rows.size());
  for (const std::int64_t r : rows) entries.push_back(all.at(static_cast<std::size_t>(r)));
  return all_pairs_distances(entries, options);
}

}  // namespace reebkit

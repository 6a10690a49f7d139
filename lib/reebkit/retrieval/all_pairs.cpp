#include "reebkit/retrieval/all_pairs.h"

#include "reebkit/core/error.h"
#include "reebkit/matching/matching_options.h"

#include <omp.h>

#include <atomic>
#include <cmath>
#include <sstream>
#include <unordered_map>

namespace reebkit {

namespace {

/// Pairs (i, j > i) in the upper-triangle rows before row `row` of an n x n matrix.
std::int64_t pairs_before(std::int64_t row, std::int64_t n) { return row * (n - 1) - row * (row - 1) / 2; }

}  // namespace

std::vector<std::int64_t> balanced_row_blocks(std::int64_t n, int parts) {
  if (n < 0 || parts < 1)
    throw InvalidArgument("balanced row blocks: " + std::to_string(n) + " rows in " + std::to_string(parts) + " parts");
  const std::int64_t total = pairs_before(n, n);
  std::vector<std::int64_t> first = {0};
  std::int64_t row = 0;
  for (int b = 1; b < parts; ++b) {
    // The boundary whose pair count before it is nearest to b / parts of them all.
    const double target = static_cast<double>(total) * b / parts;
    while (row < n && static_cast<double>(pairs_before(row + 1, n)) <= target) ++row;
    if (row < n &&
        static_cast<double>(pairs_before(row + 1, n)) - target < target - static_cast<double>(pairs_before(row, n)))
      ++row;
    first.push_back(row);
  }
  first.push_back(n);
  return first;
}

std::vector<double> upper_triangle_rows(const std::vector<GraphRecord>& entries, std::int64_t first, std::int64_t last,
                                        const AllPairsOptions& options) {
  if (options.threads < 0)
    throw InvalidArgument("all-pairs distances: threads " + std::to_string(options.threads) + " < 0");
  check_matching_options(options.matching);
  const std::int64_t n = static_cast<std::int64_t>(entries.size());
  if (first < 0 || last < first || last > n)
    throw InvalidArgument("all-pairs distances: rows " + std::to_string(first) + " to " + std::to_string(last) +
                          " of " + std::to_string(n));
  std::vector<double> out(static_cast<std::size_t>(pairs_before(last, n) - pairs_before(first, n)), 0.0);
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const std::vector<MatchableGraph> graphs = make_matchable_graphs(entries);  // once, not once per pair
  const auto pairs = static_cast<std::int64_t>(out.size());
  std::atomic<std::int64_t> matched{0};
  // Rows get shorter with i (only j > i): a dynamic schedule balances them.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t i = first; i < last; ++i) {
    const bool a_ok = entries[static_cast<std::size_t>(i)].ok;
    const std::int64_t row = pairs_before(i, n) - pairs_before(first, n);  // where row i starts in `out`
    for (std::int64_t j = i + 1; j < n; ++j)
      out[static_cast<std::size_t>(row + j - i - 1)] =
          a_ok && entries[static_cast<std::size_t>(j)].ok
              ? match_graphs(graphs[static_cast<std::size_t>(i)], graphs[static_cast<std::size_t>(j)], options.matching)
                    .distance
              : kFailedEntryDistance;
    const std::int64_t so_far = matched.fetch_add(n - 1 - i) + (n - 1 - i);
    if (options.progress && omp_get_thread_num() == 0) options.progress(so_far, pairs);
  }
  if (options.progress) options.progress(pairs, pairs);
  return out;
}

PairwiseDistances matrix_from_upper_triangle(std::vector<std::string> names, const std::vector<double>& upper) {
  PairwiseDistances out;
  out.names = std::move(names);
  const std::int64_t n = out.size();
  if (static_cast<std::int64_t>(upper.size()) != pairs_before(n, n))
    throw InvalidArgument("all-pairs distances: " + std::to_string(upper.size()) +
                          " values for the upper triangle of " + std::to_string(n) + " rows");
  out.values.assign(static_cast<std::size_t>(n * n), 0.0);
  std::size_t k = 0;
  for (std::int64_t i = 0; i < n; ++i)
    for (std::int64_t j = i + 1; j < n; ++j, ++k) {
      out.values[static_cast<std::size_t>(i * n + j)] = upper[k];
      out.values[static_cast<std::size_t>(j * n + i)] = upper[k];
    }
  return out;
}

PairwiseDistances all_pairs_distances(const std::vector<GraphRecord>& entries, const AllPairsOptions& options) {
  std::vector<std::string> names;
  for (const GraphRecord& e : entries) names.push_back(e.name);
  return matrix_from_upper_triangle(std::move(names),
                                    upper_triangle_rows(entries, 0, static_cast<std::int64_t>(entries.size()),
                                                        options));
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

std::string failed_rows_warning(const CollectionReader& collection, const std::vector<std::int64_t>& rows) {
  std::vector<std::string> failed;
  for (const std::int64_t row : rows)
    if (std::isnan(collection.signatures()[static_cast<std::size_t>(row) * kSignatureLength]))
      failed.push_back(collection.names()[static_cast<std::size_t>(row)]);
  if (failed.empty()) return "";
  std::ostringstream text;
  text << failed.size() << " of " << rows.size()
       << " entries failed when indexed (reeb info lists why); their rows and columns hold the largest float, "
       << static_cast<float>(kFailedEntryDistance) << ", 0 on the diagonal, so that they rank last:";
  for (std::size_t k = 0; k < failed.size() && k < 10; ++k) text << " " << failed[k];
  if (failed.size() > 10) text << " ...";
  return text.str();
}

std::vector<GraphRecord> matrix_entries(const CollectionReader& collection, const std::vector<std::int64_t>& rows) {
  std::vector<GraphRecord> all = collection.entries(0, collection.size());
  std::vector<GraphRecord> entries;
  entries.reserve(rows.size());
  for (const std::int64_t r : rows) entries.push_back(all.at(static_cast<std::size_t>(r)));
  return entries;
}

PairwiseDistances all_pairs_distances(const CollectionReader& collection, const std::vector<std::int64_t>& rows,
                                      const AllPairsOptions& options) {
  return all_pairs_distances(matrix_entries(collection, rows), options);
}

}  // namespace reebkit

// All-pairs distances of a collection (`reeb distances`): the
// N x N matrix of graph-matching distances that retrieval evaluation (PSB
// measures, precision-recall) reads. Only the pairs i < j are matched, in
// parallel (OpenMP, dynamic schedule), and mirrored: match_graphs is
// symmetric by contract.
#pragma once

#include "reebkit/io/psb_classes.h"
#include "reebkit/matching/graph_matching.h"
#include "reebkit/store/collection_file.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace reebkit {

/// Distance between a failed entry (no graph) and any other entry: the
/// largest float, so that failed entries rank last and the matrix still
/// fits the float32 PSB format.
inline constexpr double kFailedEntryDistance = static_cast<double>(std::numeric_limits<float>::max());

struct AllPairsOptions {
  int threads = 0;           ///< OpenMP threads; 0 = omp_get_max_threads()
  MatchingOptions matching;  ///< the cost model of match_graphs
  /// Called with the pairs matched so far and the pairs to match, from the
  /// calling thread only: after each row it matched, and once at the end.
  /// Empty: silent.
  std::function<void(std::int64_t matched, std::int64_t pairs)> progress;
};

struct PairwiseDistances {
  std::vector<std::string> names;  ///< of the rows (and columns), in matrix order
  std::vector<double> values;      ///< names.size() x names.size(), row-major
  std::int64_t size() const { return static_cast<std::int64_t>(names.size()); }
  double operator()(std::int64_t i, std::int64_t j) const { return values[static_cast<std::size_t>(i * size() + j)]; }
};

/// match_graphs(entries[i], entries[j]).distance for every pair, in the
/// order of `entries`: zero diagonal, symmetric, kFailedEntryDistance
/// between a failed entry and any other. The same matrix whatever the
/// number of threads. Throws InvalidArgument on threads < 0.
PairwiseDistances all_pairs_distances(const std::vector<GraphRecord>& entries, const AllPairsOptions& options = {});

/// Row i of the upper triangle of an n x n matrix holds the pairs (i, j),
/// j in (i, n): n - 1 - i of them. Splits rows [0, n) into `parts`
/// consecutive blocks holding about n (n - 1) / (2 parts) pairs each (equal
/// row counts would not balance them): block b is rows [first[b],
/// first[b + 1]); first has parts + 1 elements, first[0] = 0, first[parts]
/// = n. Throws InvalidArgument on n < 0 or parts < 1.
std::vector<std::int64_t> balanced_row_blocks(std::int64_t n, int parts);

/// The distances of the upper-triangle rows [first, last) of the matrix of
/// `entries` (all_pairs_distances), row after row: (first, first + 1),
/// (first, first + 2), ..., (first, n - 1), (first + 1, first + 2), ...
/// Each pair is computed as all_pairs_distances computes it, so blocks
/// computed apart (by the processes of an MPI job) assemble into the same
/// matrix bit for bit (matrix_from_upper_triangle). Throws InvalidArgument
/// on threads < 0 or rows out of range.
std::vector<double> upper_triangle_rows(const std::vector<GraphRecord>& entries, std::int64_t first, std::int64_t last,
                                        const AllPairsOptions& options = {});

/// The symmetric matrix, zero diagonal, of the whole upper triangle
/// `upper` (rows [0, names.size()) as upper_triangle_rows orders them).
PairwiseDistances matrix_from_upper_triangle(std::vector<std::string> names, const std::vector<double>& upper);

/// The rows of the matrix of a collection: every entry in collection order,
/// or, given the classes of a .cla file, one row per model of the file in
/// its order (the entry found as class_of finds it: by name, by name
/// without extension, by file name without extension). Throws Error naming
/// the model when a model of the file has no entry, or two models the same.
std::vector<std::int64_t> matrix_rows(const CollectionReader& collection, const std::vector<PsbClass>& classes = {});

/// What `reeb distances` and Python's Collection.distances warn of when some
/// of `rows` are failed entries (a NaN signature): how many, what their rows
/// and columns hold, the first names. "" when none failed.
std::string failed_rows_warning(const CollectionReader& collection, const std::vector<std::int64_t>& rows);

/// The entries `rows` of `collection` (read once), in the order of `rows`.
std::vector<GraphRecord> matrix_entries(const CollectionReader& collection, const std::vector<std::int64_t>& rows);

/// The entries `rows` of `collection` (read once) and their all-pairs
/// distances, rows and columns in the order of `rows`.
PairwiseDistances all_pairs_distances(const CollectionReader& collection, const std::vector<std::int64_t>& rows,
                                      const AllPairsOptions& options = {});

}  // namespace reebkit

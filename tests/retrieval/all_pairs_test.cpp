// All-pairs distances: every entry is match_graphs of its pair, zero
// diagonal, symmetric, failed entries at kFailedEntryDistance, the same
// matrix with 1 and 2 threads; rows in .cla order.
#include "reebkit/retrieval/all_pairs.h"
#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "retrieval/retrieval_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <thread>
#include <utility>
#include <vector>

namespace reebkit::test {
namespace {

TEST(AllPairs, SymmetricZeroDiagonalEqualToMatchingAndSerialEqualsParallel) {
  const std::vector<GraphRecord>& entries = generated_entries();
  AllPairsOptions serial;
  serial.threads = 1;
  AllPairsOptions parallel;
  parallel.threads = 2;
  const PairwiseDistances a = all_pairs_distances(entries, serial);
  const PairwiseDistances b = all_pairs_distances(entries, parallel);
  const std::int64_t n = static_cast<std::int64_t>(entries.size());
  ASSERT_EQ(a.size(), n);
  EXPECT_EQ(a.values, b.values);  // bit for bit
  for (std::int64_t i = 0; i < n; ++i) {
    const GraphRecord& ei = entries[static_cast<std::size_t>(i)];
    EXPECT_EQ(a.names[static_cast<std::size_t>(i)], ei.name);
    EXPECT_EQ(a(i, i), 0.0);
    for (std::int64_t j = 0; j < n; ++j) {
      const GraphRecord& ej = entries[static_cast<std::size_t>(j)];
      EXPECT_EQ(a(i, j), a(j, i));
      if (i == j) continue;
      if (!ei.ok || !ej.ok) {
        EXPECT_EQ(a(i, j), kFailedEntryDistance);
      } else if (i < j) {
        EXPECT_EQ(a(i, j), match_graphs(ei, ej).distance);
      }
    }
  }
  AllPairsOptions negative;
  negative.threads = -1;
  EXPECT_THROW(all_pairs_distances(entries, negative), InvalidArgument);
}

// reeb distances' progress: the counts the calling thread reports never go
// down, end at the number of pairs, and the matrix is the one without it.
TEST(AllPairs, ProgressComesFromTheCallingThreadAndEndsAtEveryPair) {
  const std::vector<GraphRecord>& entries = generated_entries();
  const auto n = static_cast<std::int64_t>(entries.size());
  AllPairsOptions options;
  options.threads = 2;
  std::vector<std::pair<std::int64_t, std::int64_t>> calls;
  bool other_thread = false;
  const std::thread::id caller = std::this_thread::get_id();
  options.progress = [&](std::int64_t matched, std::int64_t pairs) {
    other_thread = other_thread || std::this_thread::get_id() != caller;
    calls.emplace_back(matched, pairs);
  };
  const PairwiseDistances with = all_pairs_distances(entries, options);
  EXPECT_FALSE(other_thread);
  // At least the call at the end (the other thread may take every row of a loaded machine).
  ASSERT_GE(calls.size(), 1u);
  for (std::size_t k = 0; k < calls.size(); ++k) {
    EXPECT_EQ(calls[k].second, n * (n - 1) / 2);
    EXPECT_GE(calls[k].first, 0);
    if (k > 0) {
      EXPECT_GE(calls[k].first, calls[k - 1].first);
    }
  }
  EXPECT_EQ(calls.back().first, n * (n - 1) / 2);
  options.progress = nullptr;
  EXPECT_EQ(with.values, all_pairs_distances(entries, options).values);
}

TEST(AllPairs, BalancedRowBlocksSplitThePairsEvenlyAndAssembleIntoTheSameMatrix) {
  // Every split covers the rows once, in order, with about equal pair counts.
  for (const std::int64_t n : {0, 1, 2, 5, 48, 400, 1001})
    for (const int parts : {1, 2, 3, 7, 64}) {
      SCOPED_TRACE(std::to_string(n) + " rows, " + std::to_string(parts) + " parts");
      const std::vector<std::int64_t> first = balanced_row_blocks(n, parts);
      ASSERT_EQ(first.size(), static_cast<std::size_t>(parts) + 1);
      EXPECT_EQ(first.front(), 0);
      EXPECT_EQ(first.back(), n);
      EXPECT_TRUE(std::is_sorted(first.begin(), first.end()));
      const double share = static_cast<double>(n) * static_cast<double>(n - 1) / 2 / parts;
      for (int b = 0; b < parts; ++b) {
        std::int64_t pairs = 0;
        for (std::int64_t i = first[static_cast<std::size_t>(b)]; i < first[static_cast<std::size_t>(b) + 1]; ++i)
          pairs += n - 1 - i;
        EXPECT_LE(std::abs(static_cast<double>(pairs) - share), static_cast<double>(n)) << "block " << b;
      }
    }
  // 400 rows in 2: the first block is the 117 longest rows (39,897 of the
  // 79,800 pairs), not 200 rows.
  EXPECT_EQ(balanced_row_blocks(400, 2)[1], 117);
  EXPECT_THROW(balanced_row_blocks(10, 0), InvalidArgument);

  // Blocks computed apart assemble into the matrix all_pairs_distances gives, bit for bit.
  const std::vector<GraphRecord>& entries = generated_entries();
  const auto n = static_cast<std::int64_t>(entries.size());
  const PairwiseDistances whole = all_pairs_distances(entries);
  const std::vector<std::int64_t> first = balanced_row_blocks(n, 3);
  std::vector<double> upper;
  for (std::size_t b = 0; b < 3; ++b) {
    const std::vector<double> block = upper_triangle_rows(entries, first[b], first[b + 1]);
    upper.insert(upper.end(), block.begin(), block.end());
  }
  EXPECT_EQ(matrix_from_upper_triangle(whole.names, upper).values, whole.values);
  EXPECT_EQ(upper_triangle_rows(entries, 2, 3).front(), whole(2, 3));
  EXPECT_THROW(upper_triangle_rows(entries, 2, n + 1), InvalidArgument);
  EXPECT_THROW(matrix_from_upper_triangle(whole.names, {1.0}), InvalidArgument);
}

void write_text(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(AllPairs, RowsInClaOrder) {
  const TempDir dir;
  write_generated_collection(dir / "c.h5");
  const CollectionReader collection(dir / "c.h5");
  EXPECT_EQ(matrix_rows(collection), (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));

  write_text(dir / "c.cla", "PSB 1\n2 3\n\ntorus 0 2\ntorus-b\ntorus-a\n\nstar 0 1\narms3-a\n");
  const std::vector<std::int64_t> rows = matrix_rows(collection, read_psb_classes(dir / "c.cla"));
  EXPECT_EQ(rows, (std::vector<std::int64_t>{12, 11, 2}));
  const PairwiseDistances d = all_pairs_distances(collection, rows);
  EXPECT_EQ(d.names, (std::vector<std::string>{"torus-b", "torus-a", "arms3-a"}));
  const PairwiseDistances all = all_pairs_distances(generated_entries());
  for (std::int64_t i = 0; i < 3; ++i)
    for (std::int64_t j = 0; j < 3; ++j)
      EXPECT_EQ(d(i, j), all(rows[static_cast<std::size_t>(i)], rows[static_cast<std::size_t>(j)]));

  write_text(dir / "missing.cla", "PSB 1\n1 2\nstar 0 2\narms3-a\narms9-a\n");
  try {
    matrix_rows(collection, read_psb_classes(dir / "missing.cla"));
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'arms9-a'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace reebkit::test

// The signature index returns the exact nearest neighbours: the same rows,
// distances and order as a brute-force scan sorted by (distance, row).
#include "reebkit/retrieval/signature_index.h"
#include "reebkit/core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace reebkit::test {
namespace {

constexpr int kDim = 32;

/// Brute force: every row without NaN, by (distance, row), the first `count`.
std::vector<SignatureNeighbour> brute_force(const std::vector<double>& rows, const std::vector<double>& q,
                                            std::int64_t count) {
  std::vector<SignatureNeighbour> all;
  for (std::size_t r = 0; r < rows.size() / kDim; ++r) {
    double s = 0;
    bool nan = false;
    for (int c = 0; c < kDim; ++c) {
      const double v = rows[r * kDim + static_cast<std::size_t>(c)];
      nan = nan || std::isnan(v);
      s += (v - q[static_cast<std::size_t>(c)]) * (v - q[static_cast<std::size_t>(c)]);
    }
    if (!nan) all.push_back({static_cast<std::int64_t>(r), std::sqrt(s)});
  }
  std::sort(all.begin(), all.end(), [](const SignatureNeighbour& a, const SignatureNeighbour& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.row < b.row;
  });
  all.resize(std::min<std::size_t>(all.size(), static_cast<std::size_t>(std::max<std::int64_t>(count, 0))));
  return all;
}

/// 300 random signatures in [0,1], every 7th a NaN row (a failed entry), and
/// rows 10..14 copies of row 3 (ties at every distance).
std::vector<double> signatures() {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> rows(300 * kDim);
  for (double& v : rows) v = u(rng);
  for (std::size_t r = 0; r < 300; r += 7) rows[r * kDim + 5] = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t r = 10; r < 15; ++r)
    std::copy_n(rows.begin() + 3 * kDim, kDim, rows.begin() + static_cast<std::ptrdiff_t>(r * kDim));
  return rows;
}

void expect_same(const std::vector<SignatureNeighbour>& got, const std::vector<SignatureNeighbour>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].row, want[i].row) << "rank " << i;
    EXPECT_NEAR(got[i].distance, want[i].distance, 1e-12) << "rank " << i;
  }
}

TEST(SignatureIndex, ExactNearestNeighboursForBothKinds) {
  const std::vector<double> rows = signatures();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const SignatureIndexKind kind : {SignatureIndexKind::Linear, SignatureIndexKind::KdTreeSingle}) {
    SignatureIndexOptions options;
    options.kind = kind;
    const SignatureIndex index(rows, kDim, options);
    EXPECT_EQ(index.size(), 300 - 42);  // rows 0, 7, ..., 294 hold a NaN but 14 (a copy of 3)
    EXPECT_EQ(index.dimension(), kDim);
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<double> q(kDim);
      for (double& v : q) v = u(rng);
      for (const std::int64_t k : {1, 5, 37, 257, 1000}) expect_same(index.nearest(q, k), brute_force(rows, q, k));
    }
    // A query equal to the tied rows: row 3 and its copies first, at 0, by row.
    const std::vector<double> q(rows.begin() + 3 * kDim, rows.begin() + 4 * kDim);
    const std::vector<SignatureNeighbour> tied = index.nearest(q, 4);
    ASSERT_EQ(tied.size(), 4u);
    EXPECT_EQ(tied[0].row, 3);
    EXPECT_EQ(tied[1].row, 10);
    EXPECT_EQ(tied[2].row, 11);
    EXPECT_EQ(tied[3].row, 12);
    for (const auto& n : tied) EXPECT_EQ(n.distance, 0.0);
    EXPECT_TRUE(index.nearest(q, 0).empty());
  }
}

TEST(SignatureIndex, ASavedKdTreeLoadsAndFindsTheSameNeighbours) {
  const std::vector<double> rows = signatures();
  const SignatureIndex built(rows, kDim);
  const std::vector<char> saved = built.save();
  const std::shared_ptr<const double> packed(built.rows(), [](const double*) {});  // owned by `built`
  const SignatureIndex loaded(packed, built.row_of(), kDim, saved);
  EXPECT_EQ(loaded.size(), built.size());
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> q(kDim);
    for (double& v : q) v = u(rng);
    for (const std::int64_t k : {1, 10, 100}) expect_same(loaded.nearest(q, k), brute_force(rows, q, k));
  }
  EXPECT_THROW(SignatureIndex(packed, {0, 1}, kDim, saved), InvalidArgument);  // sizes disagree
  std::vector<char> damaged(saved.begin(), saved.begin() + 8);
  EXPECT_THROW(SignatureIndex(packed, built.row_of(), kDim, damaged), InvalidArgument);
  SignatureIndexOptions linear;
  linear.kind = SignatureIndexKind::Linear;
  EXPECT_THROW(SignatureIndex(rows, kDim, linear).save(), InvalidArgument);
}

TEST(SignatureIndex, TiesBeyondTheKthAreChosenByRow) {
  // 40 rows at the same distance from the query, in an order FLANN's tree
  // shuffles: the first 5 by row, whichever kind of index.
  std::vector<double> rows;
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < kDim; ++c) rows.push_back(c == r % kDim ? 1.0 : 0.0);
  const std::vector<double> q(kDim, 0.0);
  for (const SignatureIndexKind kind : {SignatureIndexKind::Linear, SignatureIndexKind::KdTreeSingle}) {
    SignatureIndexOptions options;
    options.kind = kind;
    options.leaf_max_size = 2;
    expect_same(SignatureIndex(rows, kDim, options).nearest(q, 5), brute_force(rows, q, 5));
  }
}

TEST(SignatureIndex, RejectsBadInput) {
  EXPECT_THROW(SignatureIndex({1, 2, 3}, 2), InvalidArgument);
  EXPECT_THROW(SignatureIndex({}, 0), InvalidArgument);
  const SignatureIndex index({0, 0, 1, 1}, 2);
  EXPECT_THROW(index.nearest({0, 0, 0}, 1), InvalidArgument);
  EXPECT_THROW(index.nearest({0, std::numeric_limits<double>::quiet_NaN()}, 1), InvalidArgument);
  const SignatureIndex empty({std::numeric_limits<double>::quiet_NaN(), 0}, 2);
  EXPECT_EQ(empty.size(), 0);
  EXPECT_TRUE(empty.nearest({0, 0}, 3).empty());
}

}  // namespace
}  // namespace reebkit::test

// Edge consistency: the definition on a hand-checked pair, and the row form
// equal to it, number for number, on random graphs with repeated edges and
// self-loops under random partial correspondences.
#include "reebkit/matching/edge_consistency.h"

#include "reebkit/attributes/graph_attributes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace reebkit {
namespace {

/// The matchable graph of `n` nodes (zero attributes) and the given edges.
MatchableGraph graph(int n, const std::vector<std::int32_t>& edges) {
  GraphRecord e;
  e.ok = true;
  e.nodes.assign(static_cast<std::size_t>(n) * kNodeColumnCount, 0);
  e.node_attributes.assign(static_cast<std::size_t>(n) * kNodeAttributeCount, 0.0);
  e.signature.assign(kSignatureLength, 0.0);
  e.edges = edges;
  return make_matchable_graph(e);
}

TEST(EdgeConsistency, HandCheckedPathAgainstStar) {
  // A: the path 0-1-2; B: the star 1-0-2; nodes matched to their namesakes.
  const MatchableGraph a = graph(3, {0, 1, 1, 2}), b = graph(3, {0, 1, 0, 2});
  const std::vector<std::int32_t> identity = {0, 1, 2};
  // 1: A's neighbours 0, 2 -> 2 is not B's neighbour of 1; B's neighbour 0 is fine: 1 of 3.
  EXPECT_DOUBLE_EQ(edge_inconsistency(a, b, 1, 1, identity, identity), 1.0 / 3);
  // 0: A's neighbour 1 is fine; B's neighbours 1, 2 -> 2 is not A's neighbour of 0: 1 of 3.
  EXPECT_DOUBLE_EQ(edge_inconsistency(a, b, 0, 0, identity, identity), 1.0 / 3);
  // 2: A's neighbour 1 is not B's neighbour of 2, B's neighbour 0 is not A's: 2 of 2.
  EXPECT_DOUBLE_EQ(edge_inconsistency(a, b, 2, 2, identity, identity), 1.0);
  // Unmatched neighbours count in the total only.
  const std::vector<std::int32_t> none = {-1, -1, -1};
  EXPECT_DOUBLE_EQ(edge_inconsistency(a, b, 1, 0, none, none), 0.0);
  EXPECT_DOUBLE_EQ(edge_inconsistency(graph(1, {}), graph(1, {}), 0, 0, {-1}, {-1}), 0.0);  // no neighbours
}

TEST(EdgeConsistency, RowsEqualTheDefinition) {
  std::mt19937 random(4);
  EdgeInconsistencyRows rows;  // reused across sizes: no state may leak
  for (int trial = 0; trial < 400; ++trial) {
    const auto random_graph = [&](int n) {
      std::vector<std::int32_t> edges;
      std::uniform_int_distribution<int> node(0, n - 1);
      for (int k = 0; k < 2 * n; ++k) {
        const int u = node(random), v = node(random);
        edges.insert(edges.end(), {u, v});
        if (k % 4 == 0) edges.insert(edges.end(), {v, u});  // a repeated edge (a self-loop when u == v)
      }
      return graph(n, edges);
    };
    const int n = 1 + trial % 13, m = 1 + trial / 13 % 17;
    const MatchableGraph a = random_graph(n), b = random_graph(m);
    // A random partial injection of a's nodes into b's.
    std::vector<std::int32_t> targets(static_cast<std::size_t>(m));
    std::iota(targets.begin(), targets.end(), 0);
    std::shuffle(targets.begin(), targets.end(), random);
    std::vector<std::int32_t> forward(static_cast<std::size_t>(n), -1), backward(static_cast<std::size_t>(m), -1);
    for (std::size_t i = 0; i < forward.size() && i < targets.size(); ++i) {
      if (random() % 4 == 0) continue;
      forward[i] = targets[i];
      backward[static_cast<std::size_t>(targets[i])] = static_cast<std::int32_t>(i);
    }
    rows.reset(a, b, forward, backward);
    for (std::int32_t i = 0; i < n; ++i) {
      const std::vector<double>& row = rows.row(i);
      ASSERT_EQ(row.size(), static_cast<std::size_t>(m));
      for (std::int32_t j = 0; j < m; ++j)
        ASSERT_EQ(row[static_cast<std::size_t>(j)], edge_inconsistency(a, b, i, j, forward, backward))
            << "trial " << trial << ", (" << i << ", " << j << ")";
    }
  }
}

}  // namespace
}  // namespace reebkit

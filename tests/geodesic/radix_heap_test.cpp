#include "reebkit/geodesic/radix_heap.h"

#include <gtest/gtest.h>

#include <queue>
#include <random>

namespace reebkit {
namespace {

// Dijkstra-like use: pops interleaved with pushes of keys >= the last popped
// key. The radix heap must pop the same key sequence as a binary heap.
TEST(RadixHeap, PopsKeysInOrderUnderMonotonePushes) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> step(0.0, 2.0);
  std::uniform_int_distribution<int> pushes(0, 4);
  RadixHeap heap;
  std::priority_queue<double, std::vector<double>, std::greater<>> oracle;
  double last = 0;
  Index id = 0;
  for (int k = 0; k < 5; ++k) {
    heap.push(0.0, id++);
    oracle.push(0.0);
  }
  for (int round = 0; round < 20000 && !oracle.empty(); ++round) {
    const auto [key, value] = heap.pop();
    EXPECT_EQ(key, oracle.top());
    EXPECT_GE(key, last);
    EXPECT_GE(value, 0);
    last = key;
    oracle.pop();
    for (int p = pushes(rng); p > 0; --p) {
      const double next = last + (p == 1 ? 0.0 : step(rng));  // ties included
      heap.push(next, id++);
      oracle.push(next);
    }
  }
  EXPECT_EQ(heap.empty(), oracle.empty());
}

TEST(RadixHeap, ClearAllowsAFreshStart) {
  RadixHeap heap;
  heap.push(5.0, 1);
  heap.push(7.0, 2);
  EXPECT_EQ(heap.pop().first, 5.0);
  heap.clear();
  EXPECT_TRUE(heap.empty());
  heap.push(1.0, 3);  // below the last pop: allowed after clear
  heap.push(0.5, 4);
  EXPECT_EQ(heap.pop(), std::make_pair(0.5, Index{4}));
  EXPECT_EQ(heap.pop(), std::make_pair(1.0, Index{3}));
  EXPECT_TRUE(heap.empty());
}

}  // namespace
}  // namespace reebkit

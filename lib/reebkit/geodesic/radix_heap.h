// A radix heap: the priority queue of Dijkstra's algorithm when keys only grow
// (every key pushed is >= the last key popped). Keys are non-negative doubles,
// compared through their bit patterns (monotone for x >= 0). A push is O(1);
// an entry moves down at most 64 buckets over its life, so a run costs
// O(pushes + 64 n) instead of a binary heap's O(pushes log n), and each bucket
// is a vector filled and drained sequentially, which caches well. A bit mask
// of the non-empty buckets finds the next one to refill from in one step.
// (Ahuja, Mehlhorn, Orlin, Tarjan, "Faster algorithms for the shortest path
// problem", J. ACM 1990.)
#pragma once

#include "reebkit/core/types.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace reebkit {

class RadixHeap {
 public:
  bool empty() const { return size_ == 0; }

  /// Removes every entry; the next key pushed may be anything >= 0.
  void clear() {
    for (auto& bucket : buckets_) bucket.clear();
    last_ = 0;
    size_ = 0;
    nonempty_ = 0;
  }

  /// \pre key >= 0, finite, and >= the key of the last pop.
  void push(double key, Index value) {
    const std::uint64_t k = bits(key);
    put({k, value});
    ++size_;
  }

  /// An entry of smallest key (among equal keys, the last pushed).
  /// \pre !empty()
  std::pair<double, Index> pop() {
    if (buckets_[0].empty()) {
      // Refill bucket 0 from the first non-empty bucket: its smallest key
      // becomes the reference, and every entry of the bucket moves lower.
      const std::size_t i = nonempty_ ? static_cast<std::size_t>(__builtin_ctzll(nonempty_)) : 64;
      std::vector<Entry>& source = buckets_[i];
      std::uint64_t smallest = source.front().key;
      for (const Entry& e : source) smallest = std::min(smallest, e.key);
      last_ = smallest;
      nonempty_ &= ~bit(i);
      for (const Entry& e : source) put(e);  // into buckets below i
      source.clear();
    }
    const Entry e = buckets_[0].back();
    buckets_[0].pop_back();
    --size_;
    double key;
    std::memcpy(&key, &e.key, sizeof key);
    return {key, e.value};
  }

 private:
  struct Entry {
    std::uint64_t key;
    Index value;
  };

  // Buckets 1-63 have a bit in nonempty_; bucket 64 (keys differing in the
  // sign bit) cannot be used by non-negative keys, and bucket 0 is checked
  // directly.
  static std::uint64_t bit(std::size_t bucket) { return bucket < 64 ? std::uint64_t{1} << bucket : 0; }

  void put(const Entry& e) {
    const std::size_t b = bucket_of(e.key);
    buckets_[b].push_back(e);
    if (b > 0) nonempty_ |= bit(b);
  }

  static std::uint64_t bits(double key) {
    std::uint64_t k;
    std::memcpy(&k, &key, sizeof k);
    return k;
  }

  /// 0 for a key equal to the reference, else 1 + the highest bit in which
  /// the key differs from it.
  std::size_t bucket_of(std::uint64_t key) const {
    return key == last_ ? 0 : 64 - static_cast<std::size_t>(__builtin_clzll(key ^ last_));
  }

  std::array<std::vector<Entry>, 65> buckets_;
  std::uint64_t last_ = 0;  // the key of the last refill of bucket 0
  std::size_t size_ = 0;
  std::uint64_t nonempty_ = 0;  // bit i: bucket i (1-63) holds entries
};

}  // namespace reebkit

// How a level line splits where v_t left it, for both incremental builders
// (vertices of C(t) for Definition 6, front triangles for contours): each
// piece of the line holds one of the arcs around v_t, so one search starts
// per arc. The searches advance in turns, one element each, searches that
// meet join one group, and they stop once at most one group is still
// growing: every finished group is a whole piece, found in time proportional
// to its size, and the growing one (or, when all finished, the largest) is
// what remains of the line.
#pragma once

#include "reebkit/core/types.h"

#include <cstdint>
#include <vector>

namespace reebkit {

class LineSplitter {
 public:
  /// Splits the line holding `seeds` (one element per arc around v_t).
  /// `mark(x)` is a per-element Index the splitter owns (initially below 0),
  /// `neighbours(x, visit)` calls visit(y) for each element y of the line
  /// next to x. Returns the pieces to move out of the line, every element
  /// once (empty when the line stays whole).
  template <typename Mark, typename Neighbours>
  const std::vector<std::vector<Index>>& split(const std::vector<Index>& seeds, Mark&& mark, Neighbours&& neighbours) {
    pieces_.clear();
    const auto k = seeds.size();
    if (k < 2) return pieces_;
    const Index base = next_search_;
    next_search_ += static_cast<Index>(k);
    if (queues_.size() < k) queues_.resize(k);
    heads_.assign(k, 0);
    group_.resize(k);
    for (std::size_t s = 0; s < k; ++s) {
      queues_[s].assign(1, seeds[s]);
      mark(seeds[s]) = base + static_cast<Index>(s);
      group_[s] = s;
    }
    for (;;) {
      for (std::size_t s = 0; s < k; ++s) {
        if (heads_[s] == queues_[s].size()) continue;
        const Index x = queues_[s][heads_[s]++];
        neighbours(x, [&](Index y) {
          Index& m = mark(y);
          if (m < base) {
            m = base + static_cast<Index>(s);
            queues_[s].push_back(y);
          } else {
            group_[find(static_cast<std::size_t>(m - base))] = find(s);
          }
        });
      }
      growing_.assign(k, 0);
      std::size_t groups_growing = 0;
      for (std::size_t s = 0; s < k; ++s) {
        if (heads_[s] == queues_[s].size()) continue;
        std::uint8_t& g = growing_[find(s)];
        groups_growing += g == 0;
        g = 1;
      }
      if (groups_growing > 1) continue;
      // The line keeps the growing group, or when all finished, the largest.
      std::size_t keep = k;
      sizes_.assign(k, 0);
      for (std::size_t s = 0; s < k; ++s) {
        const std::size_t r = find(s);
        sizes_[r] += queues_[s].size();
        if (growing_[r] != 0) keep = r;
      }
      if (keep == k)
        for (std::size_t s = 0; s < k; ++s)
          if (find(s) == s && (keep == k || sizes_[s] > sizes_[keep])) keep = s;
      for (std::size_t r = 0; r < k; ++r) {
        if (find(r) != r || r == keep) continue;
        pieces_.emplace_back();
        for (std::size_t s = 0; s < k; ++s)
          if (find(s) == r) pieces_.back().insert(pieces_.back().end(), queues_[s].begin(), queues_[s].end());
      }
      return pieces_;
    }
  }

 private:
  std::size_t find(std::size_t s) {
    while (group_[s] != s) s = group_[s] = group_[group_[s]];
    return s;
  }

  std::vector<std::vector<Index>> queues_;
  std::vector<std::size_t> heads_;
  std::vector<std::size_t> group_;
  std::vector<std::uint8_t> growing_;
  std::vector<std::size_t> sizes_;
  std::vector<std::vector<Index>> pieces_;
  Index next_search_ = 0;
};

}  // namespace reebkit

#include "reebkit/matching/edge_consistency.h"

#include <utility>

namespace reebkit {

double edge_inconsistency(const MatchableGraph& a, const MatchableGraph& b, std::int32_t i, std::int32_t j,
                          const std::vector<std::int32_t>& forward, const std::vector<std::int32_t>& backward) {
  const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
  int bad = 0, total = 0;
  for (std::int32_t k = a.neighbour_offset[ui]; k < a.neighbour_offset[ui + 1]; ++k) {
    const std::int32_t partner = forward[static_cast<std::size_t>(a.neighbours[static_cast<std::size_t>(k)])];
    ++total;
    if (partner >= 0 && !b.adjacent[uj * static_cast<std::size_t>(b.num_nodes) + static_cast<std::size_t>(partner)])
      ++bad;
  }
  for (std::int32_t k = b.neighbour_offset[uj]; k < b.neighbour_offset[uj + 1]; ++k) {
    const std::int32_t partner = backward[static_cast<std::size_t>(b.neighbours[static_cast<std::size_t>(k)])];
    ++total;
    if (partner >= 0 && !a.adjacent[ui * static_cast<std::size_t>(a.num_nodes) + static_cast<std::size_t>(partner)])
      ++bad;
  }
  return total ? static_cast<double>(bad) / total : 0.0;
}

void EdgeInconsistencyRows::reset(const MatchableGraph& a, const MatchableGraph& b,
                                  const std::vector<std::int32_t>& forward, const std::vector<std::int32_t>& backward) {
  a_ = &a;
  b_ = &b;
  forward_ = &forward;
  const auto m = static_cast<std::size_t>(b.num_nodes);
  row_.resize(m);
  matched_neighbours_.assign(m, 0);
  for (std::size_t j = 0; j < m; ++j)
    for (std::int32_t k = b.neighbour_offset[j]; k < b.neighbour_offset[j + 1]; ++k)
      matched_neighbours_[j] += backward[static_cast<std::size_t>(b.neighbours[static_cast<std::size_t>(k)])] >= 0;
  from_a_.assign(m, 0);
  from_b_.assign(m, 0);
  mark_b_.assign(m, -1);
  mark_a_.assign(static_cast<std::size_t>(a.num_nodes), -1);
  stamp_ = 0;
}

// For a neighbour k of i matched to l, and a node j of B:
// - k counts as consistent from i's side when l is adjacent to j, i.e. j
//   is among l's neighbours (each such j once, however often the edge is
//   listed): from_a[j];
// - the neighbours of j matched to k (l, as often as j lists it) count as
//   consistent from j's side when k is adjacent to i (each such k once):
//   from_b[j].
const std::vector<double>& EdgeInconsistencyRows::row(std::int32_t i) {
  const MatchableGraph &a = *a_, &b = *b_;
  const auto ui = static_cast<std::size_t>(i);
  const auto neighbours_of_b = [&](std::int32_t l) {
    const auto ul = static_cast<std::size_t>(l);
    return std::pair{b.neighbours.data() + b.neighbour_offset[ul], b.neighbours.data() + b.neighbour_offset[ul + 1]};
  };
  std::int32_t matched_i = 0;  // i's neighbours with a partner, with repetition
  touched_.clear();
  const std::int32_t row_stamp = stamp_++;
  for (std::int32_t k = a.neighbour_offset[ui]; k < a.neighbour_offset[ui + 1]; ++k) {
    const std::int32_t neighbour = a.neighbours[static_cast<std::size_t>(k)];
    const std::int32_t l = (*forward_)[static_cast<std::size_t>(neighbour)];
    if (l < 0) continue;
    ++matched_i;
    const std::int32_t occurrence = stamp_++;
    for (auto [p, end] = neighbours_of_b(l); p != end; ++p) {
      const auto j = static_cast<std::size_t>(*p);
      if (mark_b_[j] == occurrence) continue;  // l and j joined by a repeated edge
      mark_b_[j] = occurrence;
      if (from_a_[j]++ == 0 && from_b_[j] == 0) touched_.push_back(*p);
    }
    std::int32_t& seen = mark_a_[static_cast<std::size_t>(neighbour)];
    if (seen == row_stamp) continue;  // i and k joined by a repeated edge
    seen = row_stamp;
    for (auto [p, end] = neighbours_of_b(l); p != end; ++p) {
      const auto j = static_cast<std::size_t>(*p);
      if (from_b_[j]++ == 0 && from_a_[j] == 0) touched_.push_back(*p);
    }
  }
  const std::int32_t degree_i = a.neighbour_offset[ui + 1] - a.neighbour_offset[ui];
  for (std::size_t j = 0; j < row_.size(); ++j) {
    const std::int32_t total = degree_i + (b.neighbour_offset[j + 1] - b.neighbour_offset[j]);
    const std::int32_t bad = (matched_i - from_a_[j]) + (matched_neighbours_[j] - from_b_[j]);
    row_[j] = total ? static_cast<double>(bad) / total : 0.0;
  }
  for (const std::int32_t j : touched_) from_a_[static_cast<std::size_t>(j)] = from_b_[static_cast<std::size_t>(j)] = 0;
  return row_;
}

}  // namespace reebkit

// Edge consistency of a node correspondence, the e term of graph matching's
// cost model (graph_matching.h): for nodes i of A and j of B, the share of
// the matched neighbours of i and of j whose partners are not neighbours of
// j and of i. Per pair by definition, or for a whole row of pairs at once
// (the refinement rounds of match_graphs need all n x m of them).
#pragma once

#include "reebkit/matching/graph_matching.h"

#include <cstdint>
#include <vector>

namespace reebkit {

/// e(i, j) by its definition, neighbours counted as often as the graphs
/// list them (a repeated edge twice). `forward` maps a's nodes to b's,
/// `backward` b's to a's (-1: unmatched; inverse of each other). 0 when
/// neither node has a neighbour. O(deg i + deg j).
double edge_inconsistency(const MatchableGraph& a, const MatchableGraph& b, std::int32_t i, std::int32_t j,
                          const std::vector<std::int32_t>& forward, const std::vector<std::int32_t>& backward);

/// edge_inconsistency(a, b, i, j, forward, backward) for every j at once,
/// the same numbers from counts: of i's matched neighbours, those whose
/// partner is not a neighbour of j are all but the ones whose partner is,
/// and likewise for j's; only the neighbours of the partners of i's
/// neighbours are visited, so a row costs O(m + the sum of their degrees)
/// instead of O(m (deg i + deg j)). Buffers are reused.
class EdgeInconsistencyRows {
 public:
  /// Takes a correspondence; the graphs and `forward` are read by row()
  /// until the next reset, so they must outlive it.
  void reset(const MatchableGraph& a, const MatchableGraph& b, const std::vector<std::int32_t>& forward,
             const std::vector<std::int32_t>& backward);
  /// e(i, j) for j = 0 .. b.num_nodes - 1, valid until the next call.
  const std::vector<double>& row(std::int32_t i);

 private:
  const MatchableGraph* a_ = nullptr;
  const MatchableGraph* b_ = nullptr;
  const std::vector<std::int32_t>* forward_ = nullptr;
  std::vector<double> row_;
  // Per node of b: its neighbours with a partner (with repetition), the
  // counts of consistent neighbours from i's side and from j's side, a mark;
  // per node of a: a mark; the nodes of b whose counts are not 0.
  std::vector<std::int32_t> matched_neighbours_, from_a_, from_b_, mark_b_, mark_a_, touched_;
  std::int32_t stamp_ = 0;
};

}  // namespace reebkit

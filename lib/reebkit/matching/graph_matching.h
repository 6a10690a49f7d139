// Distance between two attributed Reeb graphs by attribute-based graph
// matching (issue 5): node-to-node costs from attribute differences and local
// structure, node insertion/deletion costs, solved as an assignment problem
// on the padded square cost matrix, optionally refined for edge consistency.
#pragma once

#include "reebkit/store/collection_file.h"

#include <cstdint>
#include <vector>

namespace reebkit {

/// The cost model (README: "Graph matching"). Weights are documented with
/// the measurement that chose them.
struct MatchingOptions {
  /// Filled in by the implementation: weights of the attribute differences,
  /// of the local structure (degree, type, neighbours), the cost of leaving a
  /// node unmatched, and whether to refine for edge consistency.
  double attribute_weight = 1.0;
  double structure_weight = 1.0;
  double unmatched_cost = 1.0;
  bool refine = true;
};

struct GraphMatch {
  /// >= 0; 0 for identical graphs; symmetric in its arguments.
  double distance = 0.0;
  /// For each node of the first graph, the node of the second it is matched
  /// to, or -1 when it is left unmatched (deleted).
  std::vector<std::int32_t> correspondence;
};

/// Matches the graphs of two collection entries (CollectionEntry holds the
/// attributed graph; make_collection_entry builds one from an analysis).
/// \pre both entries are ok (have a graph); throws InvalidArgument otherwise.
GraphMatch match_graphs(const CollectionEntry& a, const CollectionEntry& b, const MatchingOptions& options = {});

}  // namespace reebkit

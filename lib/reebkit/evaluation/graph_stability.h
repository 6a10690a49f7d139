// How stable the graphs of a classified collection are: for each class, the
// most common graph shape (feature points, nodes, independent cycles) among
// its members and how many members have it. The paper claims a graph that
// pose and sampling leave unchanged (Tierny et al. 2006, sections 4.1.1 and
// 5.3); on a collection whose classes hold one shape in several poses or
// samplings, the share of graphs with their class's most common shape
// measures that claim without any correspondence between the meshes.
#pragma once

#include "reebkit/attributes/graph_record.h"
#include "reebkit/store/collection_file.h"

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

namespace reebkit {

/// What a graph's shape is compared by.
struct GraphShape {
  std::int64_t features = 0;  ///< feature points
  std::int64_t nodes = 0;
  std::int64_t cycles = 0;  ///< independent cycles (first Betti number)
  bool operator<(const GraphShape& o) const {
    return std::tie(features, nodes, cycles) < std::tie(o.features, o.nodes, o.cycles);
  }
  bool operator==(const GraphShape& o) const {
    return std::tie(features, nodes, cycles) == std::tie(o.features, o.nodes, o.cycles);
  }
};

/// A record's feature points, nodes and independent cycles.
GraphShape graph_shape(const GraphRecord& record);

struct ClassStability {
  std::string label;
  std::int64_t members = 0;
  /// The shape most members have; among shapes as common, the smallest
  /// (by features, then nodes, then cycles).
  GraphShape most_common;
  std::int64_t agreeing = 0;  ///< members with most_common
};

struct GraphStability {
  std::vector<ClassStability> classes;  ///< by label
  std::int64_t members = 0;             ///< over every class
  std::int64_t agreeing = 0;
  /// agreeing / members; 0 for no members.
  double share() const { return members > 0 ? static_cast<double>(agreeing) / static_cast<double>(members) : 0.0; }
};

/// Graph i has shape shapes[i] and class labels[i]; graphs with an empty
/// label (no class) are left out. Throws InvalidArgument when the two
/// vectors differ in size.
GraphStability graph_stability(const std::vector<GraphShape>& shapes, const std::vector<std::string>& labels);

/// The same of the graphs a collection file holds (its failed entries left
/// out), read in one pass of batches of their outlines (EntryParts::Outline).
GraphStability graph_stability(const CollectionReader& collection);

}  // namespace reebkit

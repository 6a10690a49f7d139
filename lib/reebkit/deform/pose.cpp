#include "reebkit/deform/pose.h"

#include "reebkit/core/error.h"

#include <algorithm>

namespace reebkit {

std::vector<Index> leaves_by_area(const ReebGraph& graph) {
  std::vector<char> has_parent(graph.nodes.size(), 0), has_child(graph.nodes.size(), 0);
  for (const auto& [from, to] : graph.edges) {
    has_child[static_cast<std::size_t>(from)] = 1;
    has_parent[static_cast<std::size_t>(to)] = 1;
  }
  std::vector<Index> leaves;
  for (Index n = 0; n < graph.num_nodes(); ++n)
    if (has_parent[static_cast<std::size_t>(n)] && !has_child[static_cast<std::size_t>(n)]) leaves.push_back(n);
  std::stable_sort(leaves.begin(), leaves.end(), [&](Index a, Index b) {
    return graph.nodes[static_cast<std::size_t>(a)].area > graph.nodes[static_cast<std::size_t>(b)].area;
  });
  return leaves;
}

RandomPose random_pose(const MeshAnalysis& analysis, const PoseOptions& options) {
  std::mt19937_64 rng(options.seed);
  return random_pose(analysis, options, rng);
}

RandomPose random_pose(const MeshAnalysis& analysis, const PoseOptions& options, std::mt19937_64& rng) {
  if (options.leaves < 0) throw InvalidArgument(analysis.mesh.source + ": negative number of leaves to turn");
  if (!(0.0 <= options.min_degrees && options.min_degrees <= options.max_degrees && options.max_degrees <= 180.0))
    throw InvalidArgument(analysis.mesh.source + ": pose angles must satisfy 0 <= min <= max <= 180 degrees");
  std::vector<Index> leaves = leaves_by_area(analysis.reeb);
  leaves.resize(std::min<std::size_t>(leaves.size(), 4));
  std::shuffle(leaves.begin(), leaves.end(), rng);
  std::uniform_real_distribution<double> magnitude(options.min_degrees, options.max_degrees);
  std::bernoulli_distribution negative(0.5);
  RandomPose pose;
  for (const Index leaf : leaves) {
    if (static_cast<int>(pose.turns.size()) == options.leaves) break;
    DeformOptions deform;
    deform.node = leaf;
    deform.angle_degrees = (negative(rng) ? -1.0 : 1.0) * magnitude(rng);
    try {
      pose.turns.push_back(plan_deformation(analysis, deform));
    } catch (const InvalidArgument& e) {
      pose.skipped.push_back("leaf " + std::to_string(leaf) + ": " + e.what());
    }
  }
  if (options.leaves >= 2 && pose.turns.size() == 1) pose.turns.front().angle_degrees *= -1.0;
  pose.mesh = analysis.mesh;
  for (const Deformation& turn : pose.turns) pose.mesh = apply_deformation(pose.mesh, turn);
  return pose;
}

}  // namespace reebkit

// A random plausible pose: some leaf components of the Reeb graph (the
// limbs) turned about where they attach, with the deformation of Tierny et
// al. 2006, section 5.2 (figure 10b). Section 5.3 claims robustness to pose:
// these are the poses it can be measured on. Angles are bounded; there is no
// self-intersection check (a limb may pass through another).
#pragma once

#include "reebkit/deform/deformation.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace reebkit {

struct PoseOptions {
  /// How many leaves turn, picked at random among the (up to) four largest
  /// leaves by area. A single leaf asked to turn twice turns once by -angle
  /// (the mesh still changes).
  int leaves = 2;
  /// Each leaf turns by an angle drawn uniformly from [min, max] degrees,
  /// either way, about its default axis (Deformation::axis).
  double min_degrees = 20.0;
  double max_degrees = 35.0;
  std::uint64_t seed = 1;  ///< same seed, same pose
};

struct RandomPose {
  Mesh mesh;                         ///< analysis.mesh posed (same vertices and triangles, moved)
  std::vector<Deformation> turns;    ///< what moved, in the order applied
  std::vector<std::string> skipped;  ///< leaves passed over (no default axis), why
};

/// Leaves of the Reeb graph (nodes with a parent and no child), largest area first.
std::vector<Index> leaves_by_area(const ReebGraph& graph);

/// Turns options.leaves leaves of analysis's graph (see PoseOptions). Leaves
/// are independent components, so no turn moves another's pivot. An empty
/// `turns` means nothing turned (no leaf, or none with an axis): the mesh is
/// unchanged. Throws InvalidArgument for leaves < 0 or angles outside
/// 0 <= min <= max <= 180.
RandomPose random_pose(const MeshAnalysis& analysis, const PoseOptions& options = {});

/// The same with every draw from `rng` (options.seed unused).
RandomPose random_pose(const MeshAnalysis& analysis, const PoseOptions& options, std::mt19937_64& rng);

}  // namespace reebkit

#include "reebkit/deform/pose.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reebkit {
namespace {

const MeshAnalysis& star_analysis() {
  StarOptions star;
  star.arms = 5;
  star.levels = 4;
  static const MeshAnalysis a = analyze_mesh(make_star(star));
  return a;
}

TEST(Pose, TurnsLeavesWithinTheAnglesAndKeepsRigidPartsRigid) {
  const MeshAnalysis& a = star_analysis();
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    PoseOptions options;
    options.seed = seed;
    const RandomPose pose = random_pose(a, options);
    ASSERT_EQ(pose.turns.size(), 2u) << "seed " << seed;
    EXPECT_NE(pose.turns[0].nodes, pose.turns[1].nodes);
    for (const Deformation& turn : pose.turns) {
      EXPECT_GE(std::abs(turn.angle_degrees), options.min_degrees);
      EXPECT_LE(std::abs(turn.angle_degrees), options.max_degrees);
    }
    EXPECT_EQ(pose.mesh.triangles, a.mesh.triangles);
    // An edge whose two ends turn by the same share of every turn (both 0:
    // the core; both 1: inside a limb) is an edge of a rigid part.
    Index rigid = 0, stretched = 0;
    for (Index t = 0; t < a.mesh.num_triangles(); ++t)
      for (int k = 0; k < 3; ++k) {
        const Index u = a.mesh.triangles(t, k), v = a.mesh.triangles(t, (k + 1) % 3);
        bool same = true;
        for (const Deformation& turn : pose.turns) {
          const double wu = turn.weight[static_cast<std::size_t>(u)], wv = turn.weight[static_cast<std::size_t>(v)];
          same = same && wu == wv && (wu == 0.0 || wu == 1.0);
        }
        const double before = (a.mesh.vertices.row(u) - a.mesh.vertices.row(v)).norm();
        const double after = (pose.mesh.vertices.row(u) - pose.mesh.vertices.row(v)).norm();
        if (same) {
          ++rigid;
          EXPECT_NEAR(after, before, 1e-12 * (1.0 + before));
        } else {
          stretched += std::abs(after - before) > 1e-9;
        }
      }
    EXPECT_GT(rigid, a.mesh.num_triangles());  // most edges are rigid
    EXPECT_GT(stretched, 0);                   // and the limbs did move
  }
}

TEST(Pose, SameSeedSamePoseAndBadOptionsThrow) {
  const MeshAnalysis& a = star_analysis();
  EXPECT_EQ(random_pose(a, PoseOptions{}).mesh.vertices, random_pose(a, PoseOptions{}).mesh.vertices);
  PoseOptions zero;
  zero.leaves = 0;
  EXPECT_EQ(random_pose(a, zero).mesh.vertices, a.mesh.vertices);
  PoseOptions bad;
  bad.min_degrees = 40;
  bad.max_degrees = 30;
  EXPECT_THROW(random_pose(a, bad), InvalidArgument);
  bad = PoseOptions{};
  bad.leaves = -1;
  EXPECT_THROW(random_pose(a, bad), InvalidArgument);
}

TEST(Pose, LeavesByAreaAreChildlessNodesLargestFirst) {
  const ReebGraph& g = star_analysis().reeb;
  const std::vector<Index> leaves = leaves_by_area(g);
  EXPECT_GE(leaves.size(), 5u);  // one per arm
  for (const Index leaf : leaves) {
    bool parent = false;
    for (const auto& [from, to] : g.edges) {
      EXPECT_NE(from, leaf);
      parent = parent || to == leaf;
    }
    EXPECT_TRUE(parent);
  }
  for (std::size_t i = 1; i < leaves.size(); ++i)
    EXPECT_GE(g.nodes[static_cast<std::size_t>(leaves[i - 1])].area, g.nodes[static_cast<std::size_t>(leaves[i])].area);
}

}  // namespace
}  // namespace reebkit

#include "reebkit/deform/proportions.h"

#include "deform/deform_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace reebkit::test {
namespace {

ProportionOptions change(Index node, double scale, double thickness, double falloff = 0.25,
                         ProportionPart part = ProportionPart::Component) {
  ProportionOptions o;
  o.node = node;
  o.part = part;
  o.scale = scale;
  o.thickness = thickness;
  o.falloff = falloff;
  return o;
}

Vec3 anchor_mean(const Mesh& m, const ProportionPlan& plan) {
  Vec3 sum = Vec3::Zero();
  for (const Index v : plan.anchor) sum += row(m, v);
  return sum / static_cast<double>(plan.anchor.size());
}

bool in_part(const MeshAnalysis& a, const ProportionPlan& plan, Index v) {
  return std::binary_search(plan.nodes.begin(), plan.nodes.end(), a.reeb.vertex_node[static_cast<std::size_t>(v)]);
}

/// Largest geodesic distance (mesh graph of `m`) from the plan's anchor to a vertex of the part.
double extent(const MeshAnalysis& a, const Mesh& m, const ProportionPlan& plan) {
  const DistanceField d = dijkstra(build_mesh_graph(m), plan.anchor);
  double e = 0.0;
  for (Index v = 0; v < m.num_vertices(); ++v)
    if (in_part(a, plan, v)) e = std::max(e, d.distance[static_cast<std::size_t>(v)]);
  return e;
}

/// Area of the triangles with a vertex in the part (all three: `whole` false
/// counts only triangles whose vertices all have weight 1).
double part_area(const MeshAnalysis& a, const Mesh& m, const ProportionPlan& plan, bool only_full_weight) {
  double area = 0.0;
  for (Index t = 0; t < m.num_triangles(); ++t) {
    int inside = 0, full = 0;
    for (int k = 0; k < 3; ++k) {
      inside += in_part(a, plan, m.triangles(t, k)) ? 1 : 0;
      full += plan.weight[static_cast<std::size_t>(m.triangles(t, k))] == 1.0 ? 1 : 0;
    }
    if (only_full_weight ? full == 3 : inside == 3) area += triangle_area(m, t);
  }
  return area;
}

TEST(Proportions, FactorsOfOneGiveTheSameMesh) {
  const MeshAnalysis& a = star_analysis();
  for (const ProportionPart part : {ProportionPart::Component, ProportionPart::Region}) {
    const Mesh same =
        apply_proportions(a.mesh, plan_proportions(a, change(leaf_of_feature(a, 0), 1.0, 1.0, 0.25, part)));
    EXPECT_EQ(same.vertices, a.mesh.vertices);
    EXPECT_EQ(same.triangles, a.mesh.triangles);
  }
}

// A lengthened arm (falloff 0: the whole arm is a similarity, only the
// edges at its attach loop stretch): every vertex of weight 1 keeps its
// direction from the pivot at s times its distance, the full-weight
// triangles' area grows by exactly s^2, the arm's geodesic extent from its
// attach loop by s (within 3 %: the first ring of edges off the fixed loop
// stretches by less), and nothing outside the arm moves, bit for bit.
TEST(Proportions, ScaleLengthensTheArmAboutItsPivotAndNothingElse) {
  const MeshAnalysis& a = star_analysis();
  const double s = 1.15;
  const ProportionPlan plan = plan_proportions(a, change(leaf_of_feature(a, 0), s, 1.0, 0.0));
  const Mesh longer = apply_proportions(a.mesh, plan);
  ASSERT_EQ(longer.num_vertices(), a.mesh.num_vertices());
  EXPECT_EQ(longer.triangles, a.mesh.triangles);
  const Vec3 pivot = anchor_mean(a.mesh, plan);
  EXPECT_EQ(anchor_mean(longer, plan), pivot);  // the attach loop stays
  Index moved = 0;
  for (Index v = 0; v < a.mesh.num_vertices(); ++v) {
    const double w = plan.weight[static_cast<std::size_t>(v)];
    if (!in_part(a, plan, v)) {
      EXPECT_EQ(w, 0.0);
      EXPECT_EQ(row(longer, v), row(a.mesh, v)) << v;
    } else if (w == 1.0) {
      EXPECT_LT((row(longer, v) - pivot - s * (row(a.mesh, v) - pivot)).norm(), 1e-12) << v;
      ++moved;
    }
  }
  EXPECT_GT(moved, 100);
  EXPECT_NEAR(part_area(a, longer, plan, true) / part_area(a, a.mesh, plan, true), s * s, 1e-9);
  const double area_ratio = part_area(a, longer, plan, false) / part_area(a, a.mesh, plan, false);
  EXPECT_GT(area_ratio, 1.0);
  EXPECT_LT(area_ratio, s * s * 1.01);
  EXPECT_NEAR(extent(a, longer, plan) / extent(a, a.mesh, plan), s, 0.03 * s);
}

// A thicker arm: the star's arm is a straight cone about the line from the
// sphere's centre to its tip; thickness t moves its full-weight vertices
// away from that line by t times their distance (on average within 2 %, each
// within 10 %: the skeleton is made of the barycenters of a coarse arm's
// levels, not the exact line) and along it by less than 3 % of the arm's
// length. Its geodesic extent stays within 3 %.
TEST(Proportions, ThicknessWidensTheArmAcrossItsAxisOnly) {
  const MeshAnalysis& a = star_analysis();
  const double t = 1.15;
  const Index leaf = leaf_of_feature(a, 0);
  ProportionOptions options = change(leaf, 1.0, t);
  options.levels = 6;  // the arm is coarse: a few dozen vertices per level
  const ProportionPlan plan = plan_proportions(a, options);
  const Mesh thicker = apply_proportions(a.mesh, plan);
  // The arm's direction: from the sphere's centre to its tip.
  const Vec3 tip = row(a.mesh, a.features.vertices[0]);
  const Vec3 u = tip.normalized();
  const double length = (tip - anchor_mean(a.mesh, plan)).norm();
  const auto off_axis = [&](const Vec3& p) { return (p - p.dot(u) * u).norm(); };
  double largest = 0.0;
  for (Index v = 0; v < a.mesh.num_vertices(); ++v)
    if (in_part(a, plan, v)) largest = std::max(largest, off_axis(row(a.mesh, v)));
  Index checked = 0;
  double ratios = 0.0;
  for (Index v = 0; v < a.mesh.num_vertices(); ++v) {
    if (plan.weight[static_cast<std::size_t>(v)] != 1.0) continue;
    const Vec3 before = row(a.mesh, v), after = row(thicker, v);
    EXPECT_LT(std::abs(after.dot(u) - before.dot(u)), 0.03 * length) << v;
    if (off_axis(before) < 0.25 * largest) continue;  // near the tip: the ratio says little
    const double ratio = off_axis(after) / off_axis(before);
    EXPECT_NEAR(ratio, t, 0.1 * t) << v;
    ratios += ratio;
    ++checked;
  }
  ASSERT_GT(checked, 20);
  EXPECT_NEAR(ratios / static_cast<double>(checked), t, 0.02 * t);
  EXPECT_NEAR(extent(a, thicker, plan) / extent(a, a.mesh, plan), 1.0, 0.03);
}

// The plan holds no position: applied to a rotated and moved copy of the
// mesh it gives the rotated and moved result, for a limb and for the root's
// region.
TEST(Proportions, FollowsARigidMotionOfTheMesh) {
  const MeshAnalysis& a = star_analysis();
  Similarity motion;
  motion.rotation = random_rotation(7);
  motion.translation = Vec3(0.5, -2.0, 3.0);
  const Mesh moved = transformed(a.mesh, motion);
  for (const ProportionOptions& options :
       {change(leaf_of_feature(a, 1), 1.1, 1.12), change(0, 1.1, 1.12, 0.25, ProportionPart::Region)}) {
    const ProportionPlan plan = plan_proportions(a, options);
    const Mesh expected = transformed(apply_proportions(a.mesh, plan), motion);
    const Mesh got = apply_proportions(moved, plan);
    EXPECT_LT((got.vertices - expected.vertices).cwiseAbs().maxCoeff(), 1e-9) << options.node;
  }
}

// The root's region (the core of the star): held where the arms meet it
// (weight 0 there), its other vertices moved and the arms not.
TEST(Proportions, RegionStaysAttachedToTheRest) {
  const MeshAnalysis& a = star_analysis();
  const ProportionPlan plan = plan_proportions(a, change(0, 1.0, 1.2, 0.25, ProportionPart::Region));
  EXPECT_EQ(plan.nodes, std::vector<Index>{0});
  EXPECT_GE(plan.level_position.size(), 2u);
  EXPECT_TRUE(std::is_sorted(plan.level_position.begin(), plan.level_position.end()));
  const Mesh wider = apply_proportions(a.mesh, plan);
  const MeshGraph& g = a.graph;
  Index moved = 0;
  for (Index v = 0; v < a.mesh.num_vertices(); ++v) {
    const bool root = a.reeb.vertex_node[static_cast<std::size_t>(v)] == 0;
    const bool border =
        root && std::any_of(g.neighbor.begin() + g.offset[v], g.neighbor.begin() + g.offset[v + 1],
                            [&](Index n) { return a.reeb.vertex_node[static_cast<std::size_t>(n)] != 0; });
    if (!root || border)
      EXPECT_EQ(row(wider, v), row(a.mesh, v)) << v;
    else if (row(wider, v) != row(a.mesh, v))
      ++moved;
  }
  EXPECT_GT(moved, 0);
}

TEST(Proportions, RejectsBadArguments) {
  const MeshAnalysis& a = star_analysis();
  const Index leaf = leaf_of_feature(a, 0);
  EXPECT_THROW(plan_proportions(a, change(-1, 1.1, 1.0)), InvalidArgument);
  EXPECT_THROW(plan_proportions(a, change(a.reeb.num_nodes(), 1.1, 1.0)), InvalidArgument);
  EXPECT_THROW(plan_proportions(a, change(0, 1.1, 1.0)), InvalidArgument);  // a root has no component
  for (const double bad : {0.0, -1.1, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(plan_proportions(a, change(leaf, bad, 1.0)), InvalidArgument) << bad;
    EXPECT_THROW(plan_proportions(a, change(leaf, 1.0, bad)), InvalidArgument) << bad;
  }
  for (const double falloff : {-0.1, 1.5, std::nan("")})
    EXPECT_THROW(plan_proportions(a, change(leaf, 1.1, 1.0, falloff)), InvalidArgument) << falloff;
  ProportionOptions one_level = change(leaf, 1.1, 1.0);
  one_level.levels = 1;
  EXPECT_THROW(plan_proportions(a, one_level), InvalidArgument);
  AnalysisOptions no_graph;
  no_graph.reeb_graph = false;
  EXPECT_THROW(plan_proportions(analyze_mesh(make_star(five_arms()), no_graph), change(1, 1.1, 1.0)), InvalidArgument);
  EXPECT_THROW(apply_proportions(make_cube(), plan_proportions(a, change(leaf, 1.1, 1.0))), InvalidArgument);
}

}  // namespace
}  // namespace reebkit::test

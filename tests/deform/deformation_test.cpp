#include "reebkit/deform/deformation.h"

#include "deform/deform_test_util.h"
#include "reeb/reeb_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace reebkit::test {
namespace {

constexpr double kDegree = static_cast<double>(EIGEN_PI) / 180.0;

DeformOptions turn(Index node, double degrees) {
  DeformOptions o;
  o.node = node;
  o.angle_degrees = degrees;
  return o;
}

/// Signed angle (radians) by which `before` turned into `after` about `axis`,
/// both taken relative to `pivot`.
double turned_angle(const Vec3& before, const Vec3& after, const Vec3& pivot, const Vec3& axis) {
  const Vec3 a = before - pivot, b = after - pivot;
  return std::atan2(axis.dot(a.cross(b)), a.dot(b) - axis.dot(a) * axis.dot(b));
}

/// Every node of the graph except the roots.
std::vector<Index> non_roots(const ReebGraph& g) {
  std::vector<Index> out;
  for (const auto& e : g.edges) out.push_back(e[1]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

TEST(Deformation, ZeroAngleGivesTheSameMesh) {
  const MeshAnalysis& a = star_analysis();
  const Mesh same = deform_component(a, turn(leaf_of_feature(a, 0), 0.0));
  EXPECT_EQ(same.vertices, a.mesh.vertices);
  EXPECT_EQ(same.triangles, a.mesh.triangles);
}

// Outside the component nothing moves (bit for bit); every vertex keeps its
// distance to the pivot and to the axis (it turns about the axis through the
// pivot); weight-1 vertices all turn by the full angle, so they move rigidly.
TEST(Deformation, TurnsTheComponentAboutThePivotAndNothingElse) {
  const MeshAnalysis& a = star_analysis();
  const Index leaf = leaf_of_feature(a, 0);
  const Deformation plan = plan_deformation(a, turn(leaf, 30.0));
  const Mesh posed = apply_deformation(a.mesh, plan);
  ASSERT_EQ(posed.num_vertices(), a.mesh.num_vertices());
  EXPECT_EQ(posed.triangles, a.mesh.triangles);
  EXPECT_EQ(plan.nodes, std::vector<Index>{leaf});  // a leaf's component is the leaf
  EXPECT_NEAR(plan.axis.norm(), 1.0, 1e-12);
  const double scale = a.features.diameter;
  // The pivot sits inside the attach loop: closer to the loop's barycenter
  // than the loop's farthest vertex.
  ASSERT_FALSE(plan.attach_loop.empty());
  Vec3 loop_center = Vec3::Zero();
  for (const Index v : plan.attach_loop) loop_center += row(a.mesh, v);
  loop_center /= static_cast<double>(plan.attach_loop.size());
  double loop_radius = 0.0;
  for (const Index v : plan.attach_loop) loop_radius = std::max(loop_radius, (row(a.mesh, v) - loop_center).norm());
  EXPECT_LT((plan.pivot - loop_center).norm(), loop_radius);
  std::vector<Index> rigid;
  for (Index v = 0; v < a.mesh.num_vertices(); ++v) {
    const double w = plan.weight[static_cast<std::size_t>(v)];
    ASSERT_TRUE(w >= 0.0 && w <= 1.0) << "vertex " << v;
    if (a.reeb.vertex_node[static_cast<std::size_t>(v)] != leaf) {
      ASSERT_EQ(w, 0.0) << "vertex " << v;
    }
    if (w == 0.0) {
      ASSERT_TRUE(posed.vertices.row(v) == a.mesh.vertices.row(v)) << "vertex " << v;
      continue;
    }
    const Vec3 before = row(a.mesh, v), after = row(posed, v);
    EXPECT_NEAR((after - plan.pivot).norm(), (before - plan.pivot).norm(), 1e-12 * scale);
    EXPECT_NEAR(plan.axis.dot(after - plan.pivot), plan.axis.dot(before - plan.pivot), 1e-12 * scale);
    EXPECT_NEAR(turned_angle(before, after, plan.pivot, plan.axis), w * 30.0 * kDegree, 1e-9);
    if (w == 1.0) rigid.push_back(v);
  }
  // The tip turned by the whole angle, and the end of the arm with it.
  EXPECT_EQ(plan.weight[static_cast<std::size_t>(a.features.vertices[0])], 1.0);
  ASSERT_GE(rigid.size(), 10u);
  const std::size_t stride = std::max<std::size_t>(1, rigid.size() / 150);
  for (std::size_t i = 0; i < rigid.size(); i += stride)
    for (std::size_t j = i + stride; j < rigid.size(); j += stride) {
      const double before = (row(a.mesh, rigid[i]) - row(a.mesh, rigid[j])).norm();
      const double after = (row(posed, rigid[i]) - row(posed, rigid[j])).norm();
      ASSERT_NEAR(after, before, 1e-9 * before) << "vertices " << rigid[i] << ", " << rigid[j];
    }
}

const MeshAnalysis& torus_analysis() {
  static const MeshAnalysis a = analyze_mesh(make_torus(48, 16));
  return a;
}

/// Nodes reachable from `node` along edges (earlier -> later), `node` included.
std::vector<Index> downstream(const ReebGraph& g, Index node) {
  std::vector<char> seen(g.nodes.size(), 0);
  seen[static_cast<std::size_t>(node)] = 1;
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& [a, b] : g.edges)
      if (seen[static_cast<std::size_t>(a)] && !seen[static_cast<std::size_t>(b)]) {
        seen[static_cast<std::size_t>(b)] = 1;
        grew = true;
      }
  }
  std::vector<Index> out;
  for (Index n = 0; n < g.num_nodes(); ++n)
    if (seen[static_cast<std::size_t>(n)]) out.push_back(n);
  return out;
}

// On a star (a tree) the component is everything downstream; on a torus the
// junction closing the cycle is left out of a branch's component, since the
// other branch feeds it too.
TEST(Deformation, ComponentIsTheNodeAndWhatItAloneFeeds) {
  const ReebGraph& star = star_analysis().reeb;
  ASSERT_EQ(star.independent_cycles(), 0);
  for (const Index node : non_roots(star))
    EXPECT_EQ(plan_deformation(star_analysis(), turn(node, 10.0)).nodes, downstream(star, node)) << node;

  const ReebGraph& torus = torus_analysis().reeb;
  ASSERT_EQ(torus.independent_cycles(), 1) << summary(torus);
  for (const Index node : non_roots(torus)) {
    std::vector<Index> expected;
    const std::vector<Index> reach = downstream(torus, node);
    for (const Index n : reach) {
      const bool fed_from_outside = std::any_of(torus.edges.begin(), torus.edges.end(), [&](const auto& e) {
        return n != node && e[1] == n && !std::binary_search(reach.begin(), reach.end(), e[0]);
      });
      if (!fed_from_outside) expected.push_back(n);
    }
    EXPECT_EQ(plan_deformation(torus_analysis(), turn(node, 10.0)).nodes, expected) << node;
  }
}

// The weight is 0 on the component's border and outside, and a product of two
// smoothsteps (slope <= 1.5) of 1-Lipschitz distances inside: along any edge
// it changes by at most 3 x length / (falloff x extent), so the component
// stays attached without a crack, for every non-root node of a star and of a
// torus (whose branches meet again at a junction, where they are held).
TEST(Deformation, WeightsRampWithoutJumps) {
  for (const MeshAnalysis* a : {&star_analysis(), &torus_analysis()}) {
    for (const Index node : non_roots(a->reeb)) {
      DeformOptions options = turn(node, 45.0);
      options.falloff = 0.3;
      const Deformation plan = plan_deformation(*a, options);
      ASSERT_GT(plan.extent, 0.0);
      ASSERT_FALSE(plan.attach_loop.empty());
      for (const Index v : plan.attach_loop) EXPECT_EQ(plan.weight[static_cast<std::size_t>(v)], 0.0);
      // 1 where a vertex lies a ramp away from the loop and from the held
      // vertices; on the torus's shortest branch between two held junctions
      // only within 1 % of it.
      EXPECT_NEAR(*std::max_element(plan.weight.begin(), plan.weight.end()), 1.0, 0.01) << "node " << node;
      const double slope = 3.0 / (options.falloff * plan.extent);
      const MeshGraph& mg = a->graph;
      for (Index v = 0; v < mg.num_vertices(); ++v)
        for (Index i = mg.offset[v]; i < mg.offset[v + 1]; ++i) {
          const auto u = static_cast<std::size_t>(mg.neighbor[static_cast<std::size_t>(i)]);
          ASSERT_LE(std::abs(plan.weight[static_cast<std::size_t>(v)] - plan.weight[u]),
                    slope * mg.length[static_cast<std::size_t>(i)] + 1e-12)
              << "node " << node << ", edge " << v << "-" << u;
        }
    }
  }
}

// falloff 0: everything in the component but its border turns rigidly.
TEST(Deformation, ZeroFalloffTurnsTheWholeComponent) {
  const MeshAnalysis& a = star_analysis();
  const Index leaf = leaf_of_feature(a, 1);
  DeformOptions options = turn(leaf, 20.0);
  options.falloff = 0.0;
  const Deformation plan = plan_deformation(a, options);
  for (Index v = 0; v < a.mesh.num_vertices(); ++v) {
    const bool loop = std::binary_search(plan.attach_loop.begin(), plan.attach_loop.end(), v);
    const bool inside = a.reeb.vertex_node[static_cast<std::size_t>(v)] == leaf;
    EXPECT_EQ(plan.weight[static_cast<std::size_t>(v)], inside && !loop ? 1.0 : 0.0) << v;
  }
}

// Section 5.3, robustness to pose: turning any arm of a star keeps its
// feature points and the structure of its Reeb graph.
TEST(Deformation, PosedStarKeepsItsReebGraph) {
  const MeshAnalysis& a = star_analysis();
  const ReebGraph& g = a.reeb;
  for (std::size_t k = 0; k < a.features.vertices.size(); ++k)
    for (const double degrees : {30.0, -30.0}) {
      const MeshAnalysis posed = analyze_mesh(deform_component(a, turn(leaf_of_feature(a, k), degrees)));
      const ReebGraph& h = posed.reeb;
      EXPECT_EQ(posed.features.vertices.size(), a.features.vertices.size()) << "arm " << k << ", " << degrees;
      EXPECT_EQ(h.num_nodes(), g.num_nodes()) << summary(h) << " vs " << summary(g);
      EXPECT_EQ(h.independent_cycles(), 0);
      for (const NodeType type : {NodeType::Root, NodeType::Bifurcation, NodeType::Junction, NodeType::Termination}) {
        EXPECT_EQ(count_nodes(h, &ReebNode::type, type), count_nodes(g, &ReebNode::type, type));
        EXPECT_EQ(count_nodes(h, &ReebNode::end, type), count_nodes(g, &ReebNode::end, type));
      }
    }
}

/// `a` with its mesh moved by `t`: the same segmentation, f_q and feature
/// points, the graph's lengths and the nodes' areas and barycenters moved
/// along (what analyze_mesh gives for the moved mesh, up to ties in f_q).
MeshAnalysis moved_analysis(const MeshAnalysis& a, const Similarity& t) {
  MeshAnalysis moved = a;
  moved.mesh = transformed(a.mesh, t);
  moved.graph = build_mesh_graph(moved.mesh);
  moved.features.diameter *= t.scale;
  for (ReebNode& node : moved.reeb.nodes) {
    node.area *= t.scale * t.scale;
    node.barycenter = t.scale * t.rotation * node.barycenter + t.translation;
    for (Vec3& point : node.skeleton) point = t.scale * t.rotation * point + t.translation;
  }
  return moved;
}

// The default axis and the pivot follow the mesh: deforming a rotated, scaled
// and moved star equals moving the deformed star, for every non-root node.
TEST(Deformation, CommutesWithSimilarityTransforms) {
  const MeshAnalysis& a = star_analysis();
  Similarity t;
  t.rotation = random_rotation(11);
  t.scale = 3.5;
  t.translation = Vec3(-2, 7, 0.25);
  const MeshAnalysis moved = moved_analysis(a, t);
  for (const Index node : non_roots(a.reeb)) {
    const Mesh expected = transformed(deform_component(a, turn(node, 40.0)), t);
    const Mesh actual = deform_component(moved, turn(node, 40.0));
    EXPECT_LT((actual.vertices - expected.vertices).cwiseAbs().maxCoeff(), 1e-9 * t.scale) << "node " << node;
  }
}

// A plan can be reused: two quarter turns make a half turn, and a given axis
// is used as given (normalized).
TEST(Deformation, PlansComposeAndTakeAGivenAxis) {
  const MeshAnalysis& a = star_analysis();
  DeformOptions options = turn(leaf_of_feature(a, 2), 25.0);
  options.axis = Vec3(0, 0, 2);
  Deformation plan = plan_deformation(a, options);
  EXPECT_EQ(plan.axis, Vec3::UnitZ());
  const Mesh twice = apply_deformation(apply_deformation(a.mesh, plan), plan);
  plan.angle_degrees = 50.0;
  const Mesh once = apply_deformation(a.mesh, plan);
  EXPECT_LT((twice.vertices - once.vertices).cwiseAbs().maxCoeff(), 1e-9 * a.features.diameter);
}

TEST(Deformation, RejectsBadArguments) {
  const MeshAnalysis& a = star_analysis();
  EXPECT_THROW(plan_deformation(a, turn(-1, 10.0)), InvalidArgument);
  EXPECT_THROW(plan_deformation(a, turn(a.reeb.num_nodes(), 10.0)), InvalidArgument);
  EXPECT_THROW(plan_deformation(a, turn(0, 10.0)), InvalidArgument);  // the root
  const Index leaf = leaf_of_feature(a, 0);
  EXPECT_THROW(plan_deformation(a, turn(leaf, std::nan(""))), InvalidArgument);
  for (const double falloff : {-0.1, 1.5, std::nan("")}) {
    DeformOptions options = turn(leaf, 10.0);
    options.falloff = falloff;
    EXPECT_THROW(plan_deformation(a, options), InvalidArgument) << falloff;
  }
  DeformOptions infinite = turn(leaf, 10.0);
  infinite.axis = Vec3(1, std::numeric_limits<double>::infinity(), 0);
  EXPECT_THROW(plan_deformation(a, infinite), InvalidArgument);
  AnalysisOptions no_graph;
  no_graph.reeb_graph = false;
  EXPECT_THROW(plan_deformation(analyze_mesh(make_star(five_arms()), no_graph), turn(1, 10.0)), InvalidArgument);
  EXPECT_THROW(apply_deformation(make_cube(), plan_deformation(a, turn(leaf, 10.0))), InvalidArgument);
}

}  // namespace
}  // namespace reebkit::test

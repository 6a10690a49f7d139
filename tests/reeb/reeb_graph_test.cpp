#include "reebkit/reeb/reeb_graph.h"

#include "reeb/reeb_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"
#include "reebkit/reeb/reeb_reference.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <string>

namespace reebkit::test {
namespace {

ReebGraph graph_with(Index nodes, std::vector<std::array<Index, 2>> edges) {
  ReebGraph g;
  g.nodes.resize(static_cast<std::size_t>(nodes));
  g.edges = std::move(edges);
  return g;
}

TEST(ReebGraph, CyclesAreEdgesMinusNodesPlusComponents) {
  EXPECT_EQ(graph_with(0, {}).independent_cycles(), 0);
  EXPECT_EQ(graph_with(1, {}).independent_cycles(), 0);
  const ReebGraph tree = graph_with(4, {{0, 1}, {0, 2}, {2, 3}});
  EXPECT_EQ(tree.connected_components(), 1);
  EXPECT_EQ(tree.independent_cycles(), 0);
  // Root, bifurcation into 1 and 2, junction 3: the graph of a torus.
  const ReebGraph torus = graph_with(5, {{0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 4}});
  EXPECT_EQ(torus.independent_cycles(), 1);
  // Two disjoint cycles and an isolated node.
  const ReebGraph two = graph_with(7, {{0, 1}, {0, 2}, {1, 2}, {3, 4}, {3, 5}, {4, 5}});
  EXPECT_EQ(two.connected_components(), 3);
  EXPECT_EQ(two.independent_cycles(), 2);
}

TEST(ReebGraph, LeavesAreTheNodesEndingInATermination) {
  EXPECT_EQ(graph_with(0, {}).leaf_count(), 0);
  // The torus graph: only node 4 ends in a termination.
  ReebGraph torus = graph_with(5, {{0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 4}});
  for (const auto& [node, end] : {std::pair{0, NodeType::Bifurcation},
                                  {1, NodeType::Junction},
                                  {2, NodeType::Junction},
                                  {3, NodeType::Bifurcation}})
    torus.nodes[node].end = end;
  EXPECT_EQ(torus.leaf_count(), 1);
  torus.nodes[3].end = NodeType::Termination;
  EXPECT_EQ(torus.leaf_count(), 2);
}

/// build_reeb_graph equals reference_reeb_graph exactly: same nodes (in the
/// same order, with the same attributes), edges and segmentation; the same
/// skeleton points up to the rounding of the fast builder's running sums.
void expect_same_as_reference_with(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                                   const ReebOptions& options) {
  SCOPED_TRACE(std::string("level lines: ") + level_lines_name(options.level_lines));
  const ReebGraph fast = build_reeb_graph(mesh, graph, f, options);
  const ReebGraph reference = reference_reeb_graph(mesh, graph, f, options);
  expect_consistent(fast, mesh, f);
  ASSERT_EQ(fast.num_nodes(), reference.num_nodes())
      << "fast " << summary(fast) << "; reference " << summary(reference);
  for (std::size_t n = 0; n < fast.nodes.size(); ++n) {
    const ReebNode& a = fast.nodes[n];
    const ReebNode& b = reference.nodes[n];
    EXPECT_TRUE(a.type == b.type && a.end == b.end && a.birth_vertex == b.birth_vertex && a.fq_min == b.fq_min &&
                a.fq_max == b.fq_max && a.vertex_count == b.vertex_count && a.area == b.area &&
                a.barycenter == b.barycenter)
        << "node " << n;
    ASSERT_EQ(a.skeleton.size(), b.skeleton.size()) << "node " << n;
    const double tolerance = 1e-9 * (mesh.vertices.colwise().maxCoeff() - mesh.vertices.colwise().minCoeff()).norm();
    for (std::size_t k = 0; k < a.skeleton.size(); ++k)
      EXPECT_LE((a.skeleton[k] - b.skeleton[k]).norm(), tolerance) << "node " << n << " point " << k;
  }
  EXPECT_EQ(fast.edges, reference.edges);
  EXPECT_EQ(fast.vertex_node, reference.vertex_node);
}

/// The same, for both definitions of a level line.
void expect_same_as_reference(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                              ReebOptions options = {}) {
  for (const LevelLines lines : {LevelLines::Contour, LevelLines::Paper}) {
    options.level_lines = lines;
    expect_same_as_reference_with(mesh, graph, f, options);
  }
}

void expect_same_as_reference(const ReebInput& in) { expect_same_as_reference(in.mesh, in.graph, in.fq); }

TEST(BuildReebGraph, EqualsReferenceOnStars) {
  for (const int arms : {2, 3, 4, 5, 6, 7, 8}) {
    for (const int levels : {3, 4}) {
      StarOptions options;
      options.arms = arms;
      options.levels = levels;
      options.twist = 0.1 * arms;
      SCOPED_TRACE(std::to_string(arms) + " arms, " + std::to_string(levels) + " levels");
      expect_same_as_reference(reeb_input(make_star(options)));
    }
  }
}

TEST(BuildReebGraph, EqualsReferenceOnToriAndSpheres) {
  for (const auto& [major, minor] : {std::pair{40, 14}, std::pair{24, 8}, std::pair{64, 20}, std::pair{9, 5}}) {
    SCOPED_TRACE(std::to_string(major) + "x" + std::to_string(minor) + " torus");
    const ReebInput in = reeb_input(make_torus(major, minor));
    expect_same_as_reference(in);
    for (const int axis : {0, 1, 2}) expect_same_as_reference(in.mesh, in.graph, height(in.mesh, axis));
  }
  for (const int levels : {0, 1, 2, 3, 4}) {
    SCOPED_TRACE(std::to_string(levels) + " levels sphere");
    expect_same_as_reference(reeb_input(make_icosphere(levels)));
  }
}

TEST(BuildReebGraph, EqualsReferenceForEverySkeletonThinning) {
  const ReebInput in = reeb_input(make_star(StarOptions{5, 3}));
  for (const Index levels : {1, 2, 7, 1000}) {
    SCOPED_TRACE(std::to_string(levels) + " skeleton levels");
    ReebOptions options;
    options.skeleton_levels = levels;
    expect_same_as_reference(in.mesh, in.graph, in.fq, options);
  }
}

TEST(BuildReebGraph, EqualsReferenceOnRandomFunctions) {
  const std::vector<Mesh> meshes = {make_icosphere(3), make_torus(30, 12), make_grid(20, 15),
                                    make_star(StarOptions{4, 3})};
  unsigned seed = 1;
  for (const Mesh& mesh : meshes) {
    const MeshGraph graph = build_mesh_graph(mesh);
    for (int run = 0; run < 5; ++run, ++seed) {
      SCOPED_TRACE("seed " + std::to_string(seed));
      std::vector<double> f = random_ranks(mesh.num_vertices(), seed);
      expect_same_as_reference(mesh, graph, f);
      for (double& x : f) x = std::fmod(x, 4.0);  // ties everywhere: the vertex id decides
      expect_same_as_reference(mesh, graph, f);
    }
    expect_same_as_reference(mesh, graph, std::vector<double>(static_cast<std::size_t>(mesh.num_vertices()), 0.0));
  }
}

// Two cubes sharing one corner: that corner's ring is Irregular (two fans).
TEST(BuildReebGraph, EqualsReferenceAtNonManifoldVertices) {
  const Mesh cube = make_cube();
  Mesh mesh = disjoint_union(cube, cube);
  mesh.vertices.bottomRows(8).rowwise() += Eigen::RowVector3d(1, 1, 1);  // b's corner (0,0,0) lands on (1,1,1)
  const auto at_corner = [&mesh](Index first) {
    while (mesh.vertices.row(first) != Eigen::RowVector3d(1, 1, 1)) ++first;
    return first;
  };
  const Index corner = at_corner(0);
  const Index twin = at_corner(8);
  // b uses a's corner instead of its own, and the last vertex fills the hole.
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (mesh.triangles(t, k) == twin) mesh.triangles(t, k) = corner;
      if (mesh.triangles(t, k) == 15) mesh.triangles(t, k) = twin;
    }
  }
  mesh.vertices.row(twin) = mesh.vertices.row(15);
  mesh.vertices.conservativeResize(15, 3);
  const MeshGraph graph = build_mesh_graph(mesh);
  ASSERT_EQ(graph.ring[static_cast<std::size_t>(corner)], RingKind::Irregular);
  for (unsigned seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_as_reference(mesh, graph, random_ranks(mesh.num_vertices(), seed));
  }
  for (const int axis : {0, 1, 2}) expect_same_as_reference(mesh, graph, height(mesh, axis));
}

TEST(BuildReebGraph, OneRootPerComponentWhenAsked) {
  const ReebInput torus = reeb_input(make_torus(30, 10));
  const ReebInput sphere = reeb_input(make_icosphere(2));
  const Mesh pair = disjoint_union(torus.mesh, sphere.mesh);
  const MeshGraph graph = build_mesh_graph(pair);
  std::vector<double> f = torus.fq;
  f.insert(f.end(), sphere.fq.begin(), sphere.fq.end());
  EXPECT_THROW(build_reeb_graph(pair, graph, f), InvalidArgument);
  ReebOptions options;
  options.all_components = true;
  const ReebGraph g = build_reeb_graph(pair, graph, f, options);
  const ReebGraph a = build_reeb_graph(torus.mesh, torus.graph, torus.fq);
  const ReebGraph b = build_reeb_graph(sphere.mesh, sphere.graph, sphere.fq);
  EXPECT_EQ(g.connected_components(), 2);
  EXPECT_EQ(g.independent_cycles(), 1);
  EXPECT_EQ(g.num_nodes(), a.num_nodes() + b.num_nodes());
  EXPECT_EQ(count_nodes(g, &ReebNode::type, NodeType::Root), 2);
  // Both minima are 0: the torus's comes first by vertex id.
  for (Index v = 0; v < torus.mesh.num_vertices(); ++v)
    EXPECT_EQ(g.vertex_node[static_cast<std::size_t>(v)], a.vertex_node[static_cast<std::size_t>(v)]);
  for (Index v = 0; v < sphere.mesh.num_vertices(); ++v)
    EXPECT_EQ(g.vertex_node[static_cast<std::size_t>(v + torus.mesh.num_vertices())],
              b.vertex_node[static_cast<std::size_t>(v)] + a.num_nodes());
}

// A sample of the CGAL meshes: closed ones of every genus the set has below
// 10k vertices, and some with boundaries (Open rings).
TEST(BuildReebGraph, EqualsReferenceOnCgalMeshes) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  for (const char* name : {"pipe.off",    "joint.off",        "pinion.off",    "helmet.off",
                           "anchor.off",  "couplingdown.off", "knot1.off",     "elephant.off",
                           "femur.off",   "cheese.off",       "turbine.off",   "cow.off",
                           "hand.off",    "bull.off",         "mushroom.off",  "elephant-with-holes.off",
                           "head.off",    "holes.off",        "nefertiti.off", "pig.off",
                           "cylinder.off"}) {
    SCOPED_TRACE(name);
    expect_same_as_reference(reeb_input(load_mesh(dir / name).components[0]));
  }
}

// Renumbering the vertices (f carried along, without ties) gives the same
// contour graph: the same nodes in the same order, the same edges, and the
// same segmentation up to the renumbering.
TEST(BuildReebGraph, InvariantToVertexRenumbering) {
  const std::vector<Mesh> meshes = {make_torus(30, 12), make_holed_plate(3, 2), make_star(StarOptions{6, 3})};
  unsigned seed = 1;
  for (const Mesh& mesh : meshes) {
    for (int run = 0; run < 3; ++run, ++seed) {
      SCOPED_TRACE("seed " + std::to_string(seed));
      const std::vector<double> f = random_ranks(mesh.num_vertices(), seed);
      std::vector<Index> to(static_cast<std::size_t>(mesh.num_vertices()));
      std::iota(to.begin(), to.end(), Index{0});
      std::shuffle(to.begin(), to.end(), std::mt19937(seed + 100));
      const Mesh other = renumbered(mesh, to);
      std::vector<double> g(f.size());
      for (std::size_t v = 0; v < f.size(); ++v) g[static_cast<std::size_t>(to[v])] = f[v];
      const ReebGraph a = build_reeb_graph(mesh, build_mesh_graph(mesh), f);
      const ReebGraph b = build_reeb_graph(other, build_mesh_graph(other), g);
      ASSERT_EQ(a.num_nodes(), b.num_nodes());
      EXPECT_EQ(a.edges, b.edges);
      for (std::size_t n = 0; n < a.nodes.size(); ++n) {
        EXPECT_EQ(a.nodes[n].type, b.nodes[n].type);
        EXPECT_EQ(a.nodes[n].end, b.nodes[n].end);
        EXPECT_EQ(a.nodes[n].vertex_count, b.nodes[n].vertex_count);
        EXPECT_NEAR(a.nodes[n].area, b.nodes[n].area, 1e-12 * (1 + a.nodes[n].area));
      }
      for (Index v = 0; v < mesh.num_vertices(); ++v)
        EXPECT_EQ(a.vertex_node[static_cast<std::size_t>(v)],
                  b.vertex_node[static_cast<std::size_t>(to[static_cast<std::size_t>(v)])]);
    }
  }
}

// Each arm of a star is a leaf swept from the body to the tip by level lines
// that circle the arm: its skeleton (section 5.2, figure 10a) stays inside
// the arm's cone, near its axis, and moves outward from the base to the tip,
// where it ends at the arm's feature point. Around the tip the lines circle
// that vertex, which is up to a mesh edge off the axis: there the points may
// move back along the axis by up to the longest edge at the tip.
TEST(Skeleton, RunsAlongTheAxisOfEachStarArm) {
  StarOptions options;
  options.arms = 6;
  options.levels = 5;
  const std::vector<Vec3> axes = star_arm_directions(options);
  const Mesh mesh = make_star(options);
  const MeshGraph graph = build_mesh_graph(mesh);
  const std::vector<Index> features = extract_feature_points(mesh, graph).vertices;
  const ReebGraph g = build_reeb_graph(mesh, graph, quotient_function(graph, features).value);
  ASSERT_EQ(g.leaf_count(), options.arms) << summary(g);
  std::vector<int> arm_seen(axes.size(), 0);
  for (const ReebNode& node : g.nodes) {
    if (node.end != NodeType::Termination) continue;
    const std::vector<Vec3>& points = node.skeleton;
    ASSERT_GE(points.size(), 10u);
    const auto tip = std::find_if(features.begin(), features.end(),
                                  [&](Index v) { return (Vec3(mesh.vertices.row(v)) - points.back()).norm() < 1e-12; });
    ASSERT_NE(tip, features.end()) << "the leaf does not end at a feature point";
    const auto tip_edges = graph.length.begin() + graph.offset[*tip];
    const double slack = *std::max_element(tip_edges, tip_edges + graph.degree(*tip));
    std::size_t arm = 0;
    for (std::size_t a = 1; a < axes.size(); ++a)
      if (points.back().dot(axes[a]) > points.back().dot(axes[arm])) arm = a;
    ++arm_seen[arm];
    const Vec3& axis = axes[arm];
    SCOPED_TRACE("arm " + std::to_string(arm));
    EXPECT_LT(points.front().dot(axis), 1.5) << "born away from the arm's base";
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vec3& p = points[k];
      const double along = p.dot(axis);
      EXPECT_LE(std::acos(std::min(1.0, along / p.norm())), options.arm_width) << "point " << k << " outside the arm";
      if (k + 1 == points.size()) break;  // the tip vertex
      // Within half the arm's radius where it leaves the unit sphere.
      EXPECT_LT((p - along * axis).norm(), 0.5 * std::sin(options.arm_width)) << "point " << k;
      if (k > 0) {
        EXPECT_GT(along, points[k - 1].dot(axis) - (along > 1.0 + options.arm_length - slack ? slack : 0.0))
            << "point " << k << " moves back";
      }
    }
  }
  EXPECT_EQ(arm_seen, std::vector<int>(axes.size(), 1));
}

// At most the node's birth, a point per level of f it enters, and its end.
TEST(Skeleton, ThinnedToOnePointPerLevelOfF) {
  const ReebInput in = reeb_input(make_torus(40, 14));
  const auto [lo, hi] = std::minmax_element(in.fq.begin(), in.fq.end());
  for (const Index levels : {1, 10, 100}) {
    ReebOptions options;
    options.skeleton_levels = levels;
    const ReebGraph g = build_reeb_graph(in.mesh, in.graph, in.fq, options);
    const auto level = [&](double x) {
      return std::min(static_cast<Index>((x - *lo) / (*hi - *lo) * levels), levels - 1);
    };
    for (std::size_t n = 0; n < g.nodes.size(); ++n) {
      const ReebNode& node = g.nodes[n];
      const Index span = level(node.fq_max) - level(in.fq[static_cast<std::size_t>(node.birth_vertex)]);
      EXPECT_LE(node.skeleton.size(), static_cast<std::size_t>(std::max(span, 0) + 2))
          << levels << " levels, node " << n;
    }
  }
}

// The graph depends on f and the connectivity only: with the same f on a
// moved copy of the mesh, the skeleton moves with the mesh.
TEST(Skeleton, MovesWithTheMesh) {
  StarOptions options;
  options.arms = 4;
  options.levels = 4;
  const ReebInput in = reeb_input(make_star(options));
  Similarity t;
  t.rotation = random_rotation(3);
  t.scale = 0.04;
  t.translation = Vec3(10, 20, -5);
  const Mesh moved = transformed(in.mesh, t);
  const ReebGraph g = build_reeb_graph(in.mesh, in.graph, in.fq);
  const ReebGraph h = build_reeb_graph(moved, build_mesh_graph(moved), in.fq);
  ASSERT_EQ(h.num_nodes(), g.num_nodes());
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    ASSERT_EQ(h.nodes[n].skeleton.size(), g.nodes[n].skeleton.size()) << "node " << n;
    for (std::size_t k = 0; k < g.nodes[n].skeleton.size(); ++k) {
      const Vec3 expected = t.scale * t.rotation * g.nodes[n].skeleton[k] + t.translation;
      EXPECT_LT((h.nodes[n].skeleton[k] - expected).norm(), 1e-9 * 25.0) << "node " << n << " point " << k;
    }
  }
}

TEST(BuildReebGraph, RejectsMismatchedInputs) {
  const ReebInput in = reeb_input(make_icosphere(1));
  EXPECT_THROW(build_reeb_graph(in.mesh, in.graph, {1.0, 2.0}), InvalidArgument);
  EXPECT_THROW(build_reeb_graph(Mesh{}, MeshGraph{}, {}), InvalidArgument);
  ReebOptions options;
  options.skeleton_levels = 0;
  EXPECT_THROW(build_reeb_graph(in.mesh, in.graph, in.fq, options), InvalidArgument);
  EXPECT_THROW(reference_reeb_graph(in.mesh, in.graph, in.fq, options), InvalidArgument);
}

}  // namespace
}  // namespace reebkit::test

#include "reebkit/mesh/hole_filling.h"

#include "reeb/reeb_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace reebkit::test {
namespace {

constexpr double kFillAll = std::numeric_limits<double>::infinity();

HoleFillingOptions fill_up_to(double max_loop_length) {
  HoleFillingOptions options;
  options.max_loop_length = max_loop_length;
  return options;
}

/// `mesh` without the triangles `drop` selects, then without the vertices no
/// triangle uses (the others renumbered in order).
template <typename Drop>
Mesh without_triangles(const Mesh& mesh, Drop drop) {
  std::vector<Index> kept_triangles;
  std::vector<Index> new_index(static_cast<std::size_t>(mesh.num_vertices()), kInvalidIndex);
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    if (drop(t)) continue;
    kept_triangles.push_back(t);
    for (int k = 0; k < 3; ++k) new_index[static_cast<std::size_t>(mesh.triangles(t, k))] = 0;
  }
  Mesh out;
  Index n = 0;
  for (auto& i : new_index)
    if (i == 0) i = n++;
  out.vertices.resize(n, 3);
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    if (new_index[static_cast<std::size_t>(v)] != kInvalidIndex)
      out.vertices.row(new_index[static_cast<std::size_t>(v)]) = mesh.vertices.row(v);
  out.triangles.resize(static_cast<Index>(kept_triangles.size()), 3);
  for (std::size_t i = 0; i < kept_triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      out.triangles(static_cast<Index>(i), k) =
          new_index[static_cast<std::size_t>(mesh.triangles(kept_triangles[i], k))];
  return out;
}

/// `mesh` with a hole at each vertex of `centers`: the vertex and its
/// triangles removed.
Mesh punched(const Mesh& mesh, const std::vector<Index>& centers) {
  return without_triangles(mesh, [&](Index t) {
    return std::any_of(centers.begin(), centers.end(), [&](Index c) {
      return mesh.triangles(t, 0) == c || mesh.triangles(t, 1) == c || mesh.triangles(t, 2) == c;
    });
  });
}

/// `filled` is `mesh` plus `added` vertices: same original vertices,
/// triangles and source numbering first, the new vertices marked.
void expect_extends(const Mesh& filled, const Mesh& mesh, Index added) {
  ASSERT_EQ(filled.num_vertices(), mesh.num_vertices() + added);
  EXPECT_EQ(filled.vertices.topRows(mesh.num_vertices()), mesh.vertices);
  EXPECT_EQ(filled.triangles.topRows(mesh.num_triangles()), mesh.triangles);
  for (Index v = 0; v < filled.num_vertices(); ++v)
    EXPECT_EQ(filled.source_index(v), v < mesh.num_vertices() ? mesh.source_index(v) : kInvalidIndex) << v;
}

/// A closed, manifold, consistently oriented surface of the given genus.
void expect_closed_surface(const Mesh& mesh, int genus) {
  const MeshTopology topology = analyze_topology(mesh);
  EXPECT_TRUE(topology.closed);
  EXPECT_TRUE(topology.manifold);
  EXPECT_TRUE(topology.orientable);
  EXPECT_EQ(topology.components, 1);
  EXPECT_EQ(topology.genus, genus);
}

TEST(FillHoles, ClosedMeshIsReturnedUnchanged) {
  const Mesh sphere = make_icosphere(2);
  const Mesh filled = fill_holes(sphere, fill_up_to(kFillAll));
  EXPECT_EQ(filled.vertices, sphere.vertices);
  EXPECT_EQ(filled.triangles, sphere.triangles);
  EXPECT_TRUE(filled.source_vertex.empty());
}

/// The unit cube without its two top triangles: area 5, one square loop of length 4.
Mesh open_box() {
  const Mesh cube = make_cube();
  return without_triangles(cube, [&](Index t) {
    return cube.vertices(cube.triangles(t, 0), 2) == 1 && cube.vertices(cube.triangles(t, 1), 2) == 1 &&
           cube.vertices(cube.triangles(t, 2), 2) == 1;
  });
}

TEST(FillHoles, OpenBoxBecomesASphere) {
  const Mesh box = open_box();
  ASSERT_EQ(box.num_triangles(), 10);
  ASSERT_EQ(analyze_topology(box).boundary_loops, 1);
  const Mesh filled = fill_holes(box, fill_up_to(kFillAll));
  expect_extends(filled, box, 1);
  EXPECT_EQ(filled.num_triangles(), 10 + 4);
  expect_closed_surface(filled, 0);
  // The new vertex sits at the centre of the missing face.
  EXPECT_TRUE(filled.vertices.row(8).isApprox(Eigen::RowVector3d(0.5, 0.5, 1.0)));
}

TEST(FillHoles, OnlyLoopsUpToTheThresholdAreFilled) {
  // A 6 x 6 grid without two adjacent inner squares (area 34): an annulus
  // whose inner loop has length 6 and outer loop length 24.
  const Mesh grid = make_grid(6, 6);
  const Mesh annulus = without_triangles(grid, [](Index t) { return t / 2 == 3 * 6 + 2 || t / 2 == 3 * 6 + 3; });
  ASSERT_EQ(annulus.num_vertices(), grid.num_vertices());
  ASSERT_EQ(analyze_topology(annulus).boundary_loops, 2);
  const double unit = std::sqrt(34.0);  // sqrt(area)

  EXPECT_EQ(fill_holes(annulus, fill_up_to(5.9 / unit)).num_vertices(), annulus.num_vertices());

  const Mesh disk = fill_holes(annulus, fill_up_to(6.1 / unit));
  expect_extends(disk, annulus, 1);
  const MeshTopology topology = analyze_topology(disk);
  EXPECT_EQ(topology.boundary_loops, 1);
  EXPECT_EQ(topology.boundary_edges, 24);
  EXPECT_EQ(topology.genus, 0);

  const Mesh sphere = fill_holes(annulus, fill_up_to(24.1 / unit));
  expect_extends(sphere, annulus, 2);
  expect_closed_surface(sphere, 0);
}

TEST(FillHoles, ThresholdIsScaleInvariant) {
  const Mesh box = open_box();
  Similarity grow;
  grow.scale = 1000.0;
  grow.rotation = random_rotation(7);
  // The loop has length 4 on a surface of area 5: 4 / sqrt(5) = 1.789.
  for (const Mesh& mesh : {box, transformed(box, grow)}) {
    EXPECT_EQ(fill_holes(mesh, fill_up_to(1.78)).num_vertices(), 8);
    EXPECT_EQ(fill_holes(mesh, fill_up_to(1.80)).num_vertices(), 9);
  }
}

TEST(FillHoles, PunchedSphereAndTorusRegainTheirGenus) {
  const Mesh sphere = make_icosphere(4);
  const Mesh holed_sphere = punched(sphere, {0, 1, 2, 3});
  ASSERT_EQ(analyze_topology(holed_sphere).boundary_loops, 4);
  const Mesh filled_sphere = fill_holes(holed_sphere);  // default threshold: these holes are small
  expect_extends(filled_sphere, holed_sphere, 4);
  expect_closed_surface(filled_sphere, 0);

  const Mesh torus = make_torus(80, 32);
  const Mesh holed_torus = punched(torus, {5, 1000});
  ASSERT_EQ(analyze_topology(holed_torus).boundary_loops, 2);
  const Mesh filled_torus = fill_holes(holed_torus);
  expect_extends(filled_torus, holed_torus, 2);
  expect_closed_surface(filled_torus, 1);
}

TEST(FillHoles, KeepsTheSourceNumbering) {
  Mesh box = open_box();
  box.source_vertex = {10, 11, 12, 13, 14, 15, 16, 17};
  const Mesh filled = fill_holes(box, fill_up_to(kFillAll));
  expect_extends(filled, box, 1);
}

TEST(FillHoles, OriginalSurfaceUndoesTheFilling) {
  Mesh box = open_box();
  box.source_vertex = {10, 11, 12, 13, 14, 15, 16, 17};
  const Mesh filled = fill_holes(box, fill_up_to(kFillAll));
  ASSERT_EQ(filled.num_vertices(), 9);
  EXPECT_EQ(original_vertex_count(filled), 8);
  const Mesh surface = original_surface(filled);
  EXPECT_EQ(surface.vertices, box.vertices);
  EXPECT_EQ(surface.triangles, box.triangles);
  EXPECT_EQ(surface.source_vertex, box.source_vertex);
  // A mesh without filled holes (identity numbering included) is its own surface.
  const Mesh cube = make_cube();
  EXPECT_EQ(original_vertex_count(cube), 8);
  EXPECT_EQ(original_surface(cube).triangles, cube.triangles);
}

TEST(FillHoles, RejectsANegativeThreshold) {
  EXPECT_THROW(fill_holes(make_cube(), fill_up_to(-1.0)), InvalidArgument);
  EXPECT_THROW(fill_holes(make_cube(), fill_up_to(std::nan(""))), InvalidArgument);
}

/// Nodes by start and end type, leaves, cycles.
void expect_same_structure(const ReebGraph& a, const ReebGraph& b) {
  for (const NodeType type : {NodeType::Root, NodeType::Bifurcation, NodeType::Junction, NodeType::Termination}) {
    EXPECT_EQ(count_nodes(a, &ReebNode::type, type), count_nodes(b, &ReebNode::type, type));
    EXPECT_EQ(count_nodes(a, &ReebNode::end, type), count_nodes(b, &ReebNode::end, type));
  }
  EXPECT_EQ(a.independent_cycles(), b.independent_cycles()) << summary(a) << " vs " << summary(b);
}

/// Vertices of `mesh` on the base sphere of a star, as far as possible from
/// its arms and from each other.
std::vector<Index> far_from_arms(const Mesh& mesh, const StarOptions& star, int count) {
  std::vector<Vec3> taken = star_arm_directions(star);
  std::vector<Index> picked;
  for (int i = 0; i < count; ++i) {
    Index best = kInvalidIndex;
    double best_gap = -1;
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
      const Vec3 d = mesh.vertices.row(v).normalized();
      double gap = 4;
      for (const Vec3& t : taken) gap = std::min(gap, (d - t).norm());
      if (gap > best_gap) best_gap = gap, best = v;
    }
    picked.push_back(best);
    taken.push_back(mesh.vertices.row(best).normalized());
  }
  return picked;
}

TEST(FillHoles, PunchedStarHasTheReebGraphOfTheIntactStar) {
  StarOptions star;
  star.arms = 5;
  star.levels = 4;
  const Mesh intact = make_star(star);
  const Mesh holed = punched(intact, far_from_arms(intact, star, 3));
  ASSERT_EQ(analyze_topology(holed).boundary_loops, 3);
  const MeshAnalysis reference = analyze_mesh(intact);
  const MeshAnalysis filled = analyze_mesh(holed);
  EXPECT_TRUE(analyze_topology(filled.mesh).closed);
  EXPECT_EQ(filled.features.vertices.size(), reference.features.vertices.size());
  expect_same_structure(filled.reeb, reference.reeb);
  EXPECT_EQ(filled.reeb.leaf_count(), star.arms);
}

TEST(FillHoles, PunchedSphereHasTheReebGraphOfTheIntactSphere) {
  const Mesh intact = make_icosphere(4);
  const Mesh holed = punched(intact, {0, 1, 2, 3, 4});
  const MeshAnalysis reference = analyze_mesh(intact);
  const MeshAnalysis filled = analyze_mesh(holed);
  EXPECT_TRUE(analyze_topology(filled.mesh).closed);
  expect_same_structure(filled.reeb, reference.reeb);
  EXPECT_EQ(filled.reeb.independent_cycles(), 0);
}

}  // namespace
}  // namespace reebkit::test

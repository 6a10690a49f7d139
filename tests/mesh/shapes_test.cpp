#include "reebkit/mesh/shapes.h"

#include "reebkit/mesh/mesh_graph.h"

#include <gtest/gtest.h>

namespace reebkit {
namespace {

StarOptions star_options(int arms, int levels) {
  StarOptions o;
  o.arms = arms;
  o.levels = levels;
  return o;
}

// Euler characteristic V - E + F from the graph (E = half-edges / 2).
int euler(const Mesh& mesh) {
  const MeshGraph g = build_mesh_graph(mesh);
  return mesh.num_vertices() - g.num_half_edges() / 2 + mesh.num_triangles();
}

TEST(Shapes, ClosedShapesHaveTheirEulerCharacteristic) {
  EXPECT_EQ(euler(make_cube()), 2);
  EXPECT_EQ(euler(make_icosphere(3)), 2);
  EXPECT_EQ(euler(make_star(star_options(4, 3))), 2);
  EXPECT_EQ(euler(make_torus(20, 10)), 0);
  EXPECT_EQ(euler(make_grid(5, 4)), 1);  // a disk
}

TEST(Shapes, IcosphereCountsAndRadius) {
  const Mesh s = make_icosphere(3, 2.5);
  EXPECT_EQ(s.num_vertices(), 10 * 64 + 2);
  EXPECT_EQ(s.num_triangles(), 20 * 64);
  for (Index v = 0; v < s.num_vertices(); ++v) EXPECT_NEAR(s.vertices.row(v).norm(), 2.5, 1e-12);
}

TEST(Shapes, StarTipsStandOutAlongArmDirections) {
  const StarOptions options = star_options(6, 4);
  const Mesh star = make_star(options);
  for (const Vec3& d : star_arm_directions(options)) {
    double tip = 0;
    for (Index v = 0; v < star.num_vertices(); ++v) tip = std::max(tip, star.vertices.row(v).dot(d));
    EXPECT_GT(tip, 2.5) << "each arm reaches well beyond the unit body";
  }
}

}  // namespace
}  // namespace reebkit

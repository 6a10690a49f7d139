// Meshes of several connected components through load_mesh and analyze_mesh:
// one analysis per component, and the largest component by default.
#include "io/io_test_util.h"
#include "reeb/reeb_test_util.h"
#include "reebkit/io/off.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"
#include "reebkit/pipeline/analyze_mesh.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <vector>

namespace reebkit::test {
namespace {

Mesh star(int arms, int levels) {
  StarOptions options;
  options.arms = arms;
  options.levels = levels;
  return make_star(options);
}

Mesh moved(const Mesh& mesh, double scale, double x) {
  Similarity s;
  s.scale = scale;
  s.translation = Vec3(x, 0, 0);
  return transformed(mesh, s);
}

/// `mesh` written to an OFF file and read back with `options`.
CleanedMesh reloaded(const Mesh& mesh, const CleanupOptions& options) {
  const TempDir dir;
  write_off(dir / "components.off", mesh);
  return load_mesh(dir / "components.off", options);
}

TEST(Components, TwoStarsGiveTwoAnalyses) {
  // A 5-armed star and, far from it, a 3-armed star at half the size.
  const Mesh big = star(5, 4);
  const Mesh small = moved(star(3, 4), 0.5, 20.0);
  const Mesh both = disjoint_union(small, big);
  CleanupOptions all;
  all.keep_all_components = true;
  const CleanedMesh cleaned = reloaded(both, all);
  ASSERT_EQ(cleaned.components.size(), 2u);
  const std::vector<Index> arms{5, 3};  // largest area first
  for (std::size_t c = 0; c < 2; ++c) {
    const MeshAnalysis a = analyze_mesh(cleaned.components[c]);
    EXPECT_EQ(a.reeb.leaf_count(), arms[c]) << "component " << c << ": " << summary(a.reeb);
    EXPECT_EQ(a.reeb.independent_cycles(), 0);
    expect_consistent(a.reeb, a.mesh, a.fq.value);
  }
  // By default only the larger star is kept, numbered as in the file.
  const CleanedMesh largest = reloaded(both, {});
  ASSERT_EQ(largest.components.size(), 1u);
  EXPECT_EQ(largest.components[0].num_vertices(), big.num_vertices());
  EXPECT_EQ(largest.components[0].source_index(0), small.num_vertices());
  EXPECT_EQ(analyze_mesh(largest.components[0]).reeb.leaf_count(), 5);
}

TEST(Components, StarAndTorus) {
  // The torus (area 4 pi^2 R r = 124 at scale 3) is larger than the star.
  const Mesh torus = moved(make_torus(60, 20), 3.0, 0.0);
  const Mesh urchin = moved(star(4, 4), 1.0, 20.0);
  CleanupOptions all;
  all.keep_all_components = true;
  const CleanedMesh cleaned = reloaded(disjoint_union(urchin, torus), all);
  ASSERT_EQ(cleaned.components.size(), 2u);
  const MeshAnalysis first = analyze_mesh(cleaned.components[0]);
  const MeshAnalysis second = analyze_mesh(cleaned.components[1]);
  EXPECT_EQ(first.reeb.independent_cycles(), 1);
  EXPECT_EQ(second.reeb.independent_cycles(), 0);
  EXPECT_EQ(second.reeb.leaf_count(), 4);
  const CleanedMesh largest = reloaded(disjoint_union(urchin, torus), {});
  ASSERT_EQ(largest.components.size(), 1u);
  EXPECT_EQ(analyze_mesh(largest.components[0]).reeb.independent_cycles(), 1);
}

TEST(Components, CgalMeshesOfSeveralComponentsRun) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  CleanupOptions all;
  all.keep_all_components = true;
  for (const char* name : {"blobby_3cc.off", "bones.off"}) {
    const CleanedMesh cleaned = load_mesh(dir / name, all);
    EXPECT_GT(cleaned.components.size(), 1u) << name;
    for (const Mesh& component : cleaned.components) {
      const MeshAnalysis a = analyze_mesh(component);
      EXPECT_FALSE(a.features.vertices.empty()) << name;
      expect_consistent(a.reeb, a.mesh, a.fq.value);
      EXPECT_GE(a.reeb.leaf_count(), 1) << name;
    }
  }
}

}  // namespace
}  // namespace reebkit::test

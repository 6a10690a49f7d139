// The TOSCA horse poses with and without their small holes. Measured in
// results/tosca_graphs.md: the leaf count varies with the pose (15-20 over the
// 8 poses), so holed and closed poses are compared in what the pose leaves
// alone: cycles (the genus, 0), and, pose by pose, the graph of each closed
// pose with the holes of a holed pose punched in.
#include "reeb/reeb_test_util.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/pipeline/analyze_mesh.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace reebkit::test {
namespace {

const std::vector<std::string> kClosedHorses{"horse0", "horse7", "horse10", "horse14", "horse15", "horse17"};
const std::vector<std::string> kHoledHorses{"horse5", "horse6"};

TEST(ToscaHoles, HoledHorsesAreFilledToClosedGenusZeroGraphsLikeTheClosedPoses) {
  REEBKIT_REQUIRE_DATASET(dir, "tosca_dev");
  for (const std::string& name : kClosedHorses) {
    const MeshAnalysis a = analyze_mesh(load_mesh(dir / (name + ".off")).components.front());
    EXPECT_EQ(a.reeb.independent_cycles(), 0) << name << ": " << summary(a.reeb);
  }
  for (const std::string& name : kHoledHorses) {
    const Mesh mesh = load_mesh(dir / (name + ".off")).components.front();
    ASSERT_GT(analyze_topology(mesh).boundary_loops, 0) << name;
    const MeshAnalysis a = analyze_mesh(mesh);
    const MeshTopology filled = analyze_topology(a.mesh);
    EXPECT_TRUE(filled.closed) << name;
    EXPECT_EQ(filled.genus, 0) << name;
    EXPECT_EQ(a.reeb.independent_cycles(), 0) << name << ": " << summary(a.reeb);
    EXPECT_EQ(a.reeb.leaf_count(), static_cast<Index>(a.features.vertices.size())) << name;
  }
}

/// `closed` without its triangles whose three vertices lie on the boundary
/// of `holed` (same vertex numbering): the TOSCA holes have no inner vertices,
/// so this punches the holes of one pose into another (a little smaller where
/// the two triangulations differ by an edge flip).
Mesh with_holes_of(const Mesh& closed, const Mesh& holed) {
  const MeshGraph graph = build_mesh_graph(holed);
  Mesh out = closed;
  Index n = 0;
  for (Index t = 0; t < closed.num_triangles(); ++t) {
    int on_boundary = 0;
    for (int k = 0; k < 3; ++k)
      on_boundary += graph.ring[static_cast<std::size_t>(closed.triangles(t, k))] != RingKind::Closed;
    if (on_boundary < 3) out.triangles.row(n++) = closed.triangles.row(t);
  }
  out.triangles.conservativeResize(n, 3);
  return out;
}

TEST(ToscaHoles, HolesDoNotChangeTheGraphOfAPose) {
  REEBKIT_REQUIRE_DATASET(dir, "tosca_dev");
  const Mesh holed = load_mesh(dir / "horse5.off").components.front();
  for (const std::string& name : kClosedHorses) {
    const Mesh closed = load_mesh(dir / (name + ".off")).components.front();
    const Mesh punched = with_holes_of(closed, holed);
    ASSERT_GT(analyze_topology(punched).boundary_edges, 0) << name;
    const ReebGraph reference = analyze_mesh(closed).reeb;
    const ReebGraph filled = analyze_mesh(punched).reeb;
    EXPECT_EQ(filled.leaf_count(), reference.leaf_count())
        << name << ": " << summary(filled) << " vs " << summary(reference);
    EXPECT_EQ(filled.independent_cycles(), reference.independent_cycles()) << name;
  }
}

}  // namespace
}  // namespace reebkit::test

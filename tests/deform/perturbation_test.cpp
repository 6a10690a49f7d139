// perturb_mesh (deform/perturbation.h): each kind gives the mesh of the
// function it picks, with a correspondence into the original's vertices.
#include "reebkit/deform/perturbation.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/decimation.h"
#include "reebkit/mesh/resampling.h"
#include "reebkit/mesh/shapes.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

namespace reebkit::test {
namespace {

TEST(Perturbation, EachKindIsItsFunctionWithACorrespondence) {
  const Mesh mesh = make_star(StarOptions{3, 2});
  const MeshAnalysis analysis = analyze_mesh(mesh);
  const auto n = mesh.num_vertices();
  const MeshVariant decimated = perturb_mesh(mesh, Perturbation{PerturbationKind::Decimate, 0.5, {}, 1, {}});
  EXPECT_EQ(decimated.mesh.num_vertices(), decimate_mesh(mesh, DecimationOptions{0.5, 0.02}).mesh.num_vertices());
  const MeshVariant noisy = perturb_mesh(mesh, Perturbation{PerturbationKind::Noise, 0.01, {}, 7, {}});
  EXPECT_TRUE(noisy.mesh.vertices == add_normal_noise(mesh, NoiseOptions{0.01, 7, NoiseShape::Gaussian}).vertices);
  const MeshVariant subdivided = perturb_mesh(mesh, Perturbation{PerturbationKind::Subdivide, 1, {}, 1, {}});
  EXPECT_GT(subdivided.mesh.num_vertices(), n);
  std::vector<std::string> notes;
  const MeshVariant posed = perturb_mesh(mesh, Perturbation{PerturbationKind::Pose, 0, {}, 3, {}}, &analysis, &notes);
  EXPECT_EQ(posed.mesh.num_vertices(), n);
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes.back().find("leaf component(s) turned by"), std::string::npos) << notes.back();
  for (const MeshVariant* v : {&decimated, &noisy, &subdivided, &posed}) {
    ASSERT_EQ(v->original_vertex.size(), static_cast<std::size_t>(v->mesh.num_vertices()));
    for (const Index o : v->original_vertex) {
      EXPECT_GE(o, 0);
      EXPECT_LT(o, n);
    }
  }
  EXPECT_THROW(perturb_mesh(mesh, Perturbation{PerturbationKind::Pose, 0, {}, 3, {}}), InvalidArgument);
}

}  // namespace
}  // namespace reebkit::test

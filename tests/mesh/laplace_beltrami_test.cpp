#include "reebkit/mesh/laplace_beltrami.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reebkit {
namespace {

Eigen::VectorXd coordinate(const Mesh& m, int axis) { return m.vertices.col(axis); }

// The stiffness matrix is symmetric, its rows sum to 0 (the constants are in
// its kernel); the consistent mass matrix integrates 1 x 1 to the area, and
// the lumped one is its row sums.
TEST(LaplaceBeltrami, SymmetricWithConstantsInTheKernelAndMassSummingToTheArea) {
  const Mesh m = make_torus(24, 10, 1.0, 0.4);
  const LaplaceBeltrami consistent = laplace_beltrami(m);
  const LaplaceBeltrami lumped = laplace_beltrami(m, {MassMatrix::Lumped});
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m.num_vertices());
  EXPECT_LT((consistent.stiffness * ones).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_LT((Eigen::SparseMatrix<double>(consistent.stiffness.transpose()) - consistent.stiffness).norm(), 1e-12);
  EXPECT_NEAR(ones.dot(consistent.mass * ones), surface_area(m), 1e-12);
  const Eigen::VectorXd row_sums = consistent.mass * ones;
  EXPECT_EQ(lumped.mass.nonZeros(), m.num_vertices());
  for (Index v = 0; v < m.num_vertices(); ++v) EXPECT_NEAR(lumped.mass.coeff(v, v), row_sums(v), 1e-14);
  // Same stiffness whatever the mass.
  EXPECT_EQ((consistent.stiffness - lumped.stiffness).norm(), 0.0);
}

// Linear elements reproduce linear functions exactly: on a flat plate the
// Dirichlet energy x^T L x of the coordinate x is the integral of
// |grad x|^2 = 1, the area; L x vanishes at interior vertices; and the mass
// matrix integrates x^2 exactly (the consistent one).
TEST(LaplaceBeltrami, ExactOnLinearFunctionsOfAFlatPlate) {
  const Mesh m = make_grid(6, 4, 0.5);  // 3 x 2
  const LaplaceBeltrami op = laplace_beltrami(m);
  const Eigen::VectorXd x = coordinate(m, 0), y = coordinate(m, 1);
  EXPECT_NEAR(x.dot(op.stiffness * x), 6.0, 1e-12);
  EXPECT_NEAR(y.dot(op.stiffness * y), 6.0, 1e-12);
  EXPECT_NEAR(x.dot(op.stiffness * y), 0.0, 1e-12);
  const Eigen::VectorXd lx = op.stiffness * x;
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const bool interior = x(v) > 0 && x(v) < 3 && y(v) > 0 && y(v) < 2;
    if (interior) {
      EXPECT_NEAR(lx(v), 0.0, 1e-12) << "vertex " << v;
    }
  }
  EXPECT_NEAR(x.dot(op.mass * x), 3.0 * 3.0 * 3.0 / 3.0 * 2.0, 1e-12);  // int_0^3 x^2 dx x 2
}

// The stiffness matrix does not change with scale, the mass matrix grows
// with the area.
TEST(LaplaceBeltrami, StiffnessScaleFreeMassScalesWithTheArea) {
  Mesh m = make_icosphere(2);
  const LaplaceBeltrami a = laplace_beltrami(m);
  m.vertices *= 3.0;
  const LaplaceBeltrami b = laplace_beltrami(m);
  EXPECT_LT((a.stiffness - b.stiffness).norm(), 1e-12 * a.stiffness.norm());
  EXPECT_LT((9.0 * a.mass - b.mass).norm(), 1e-12 * b.mass.norm());
}

// A triangle of zero area (corners on a line) spans no surface: the
// matrices are those of the mesh without it.
TEST(LaplaceBeltrami, ZeroAreaTrianglesAreLeftOut) {
  Mesh m;  // two triangles and a third whose corners lie on a line
  m.vertices.resize(4, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 2, 0, 0, 1, 1, 0;
  m.triangles.resize(3, 3);
  m.triangles << 0, 1, 3, 1, 2, 3, 0, 2, 1;
  Mesh without = m;
  without.triangles.conservativeResize(2, 3);
  const LaplaceBeltrami a = laplace_beltrami(m), b = laplace_beltrami(without);
  EXPECT_EQ((a.stiffness - b.stiffness).norm(), 0.0);
  EXPECT_EQ((a.mass - b.mass).norm(), 0.0);
  EXPECT_TRUE(std::isfinite(a.stiffness.norm()));
}

// A vertex on triangles of zero area only has no area: it is left out as the
// reader leaves out a vertex no triangle uses, and the matrices are those of
// the mesh without it and its triangles.
TEST(LaplaceBeltrami, VerticesOnZeroAreaTrianglesOnlyAreLeftOut) {
  Mesh m;  // vertices 3 and 4 only on the triangle (1, 3, 4) of zero area
  m.source = "flat.off";
  m.vertices.resize(5, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 3, 0, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 1, 3, 4;
  Mesh without = m;
  without.vertices.conservativeResize(3, 3);
  without.triangles.conservativeResize(1, 3);
  const LaplaceBeltrami a = laplace_beltrami(m), b = laplace_beltrami(without);
  EXPECT_EQ(a.vertex, (std::vector<Index>{0, 1, 2}));
  ASSERT_EQ(a.stiffness.rows(), 3);
  EXPECT_EQ((a.stiffness - b.stiffness).norm(), 0.0);
  EXPECT_EQ((a.mass - b.mass).norm(), 0.0);
  EXPECT_EQ(laplace_beltrami(make_icosphere(1)).vertex.size(), 42u);  // all, on a mesh without zero area

  Mesh flat = m;  // only the triangle of zero area: no operator
  flat.triangles = m.triangles.bottomRows(1);
  EXPECT_NE(test::thrown_message<InvalidMeshError>([&] {
              laplace_beltrami(flat);
            }).find("flat.off: no triangle of nonzero area"),
            std::string::npos);
  Mesh empty;
  empty.source = "empty.off";
  EXPECT_NE(test::thrown_message<InvalidMeshError>([&] { laplace_beltrami(empty); }).find("empty.off: no triangle"),
            std::string::npos);
}

}  // namespace
}  // namespace reebkit

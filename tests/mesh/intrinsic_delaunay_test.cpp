#include "reebkit/mesh/intrinsic_delaunay.h"

#include "reebkit/mesh/decimation.h"
#include "reebkit/mesh/laplace_beltrami.h"
#include "reebkit/mesh/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace reebkit {
namespace {

/// A flat kite whose long diagonal a-b is the mesh's edge: the angles at p
/// and q, opposite it, are both obtuse (about 152 degrees).
Mesh flat_kite() {
  Mesh m;
  m.vertices.resize(4, 3);
  m.vertices << 0, 0, 0,  // a
      4, 0, 0,            // b
      2, 0.5, 0,          // p
      2, -0.5, 0;         // q
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2,  // (a, b, p)
      1, 0, 3;             // (b, a, q)
  return m;
}

/// The mesh's own triangles as an intrinsic triangulation, nothing flipped.
IntrinsicTriangulation as_given(const Mesh& m) {
  IntrinsicTriangulation t;
  t.triangles = m.triangles;
  t.num_vertices = m.num_vertices();
  t.lengths.resize(m.num_triangles(), 3);
  for (Index f = 0; f < m.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k)
      t.lengths(f, k) =
          (m.vertices.row(m.triangles(f, (k + 1) % 3)) - m.vertices.row(m.triangles(f, (k + 2) % 3))).norm();
  return t;
}

double total_area(const IntrinsicTriangulation& t) {
  double sum = 0;
  for (Index f = 0; f < t.triangles.rows(); ++f)
    sum += 0.5 * intrinsic_twice_area(t.lengths(f, 0), t.lengths(f, 1), t.lengths(f, 2));
  return sum;
}

/// The sum of the cotangents of the two angles opposite each interior edge
/// (law of cosines on the lengths), the smallest over the edges.
double least_opposite_cotangent_sum(const IntrinsicTriangulation& t) {
  // Each edge (its corners sorted, and which copy of it) -> the cotangents
  // opposite it.
  std::map<std::pair<Index, Index>, std::vector<double>> opposite;
  for (Index f = 0; f < t.triangles.rows(); ++f) {
    const double area2 = intrinsic_twice_area(t.lengths(f, 0), t.lengths(f, 1), t.lengths(f, 2));
    for (int k = 0; k < 3; ++k) {
      const double a = t.lengths(f, k), b = t.lengths(f, (k + 1) % 3), c = t.lengths(f, (k + 2) % 3);
      const Index u = t.triangles(f, (k + 1) % 3), v = t.triangles(f, (k + 2) % 3);
      opposite[{std::min(u, v), std::max(u, v)}].push_back((b * b + c * c - a * a) / (2 * area2));
    }
  }
  double least = INFINITY;
  for (const auto& [edge, cots] : opposite)
    if (cots.size() == 2) least = std::min(least, cots[0] + cots[1]);
  return least;
}

// The kite's long diagonal is flipped to the short one, of length 1 (the
// distance from p to q across the flat quad), and the two new triangles
// cover the same area.
TEST(IntrinsicDelaunay, FlipsTheLongDiagonalOfAFlatKiteToTheShortOne) {
  const IntrinsicTriangulation t = intrinsic_delaunay(flat_kite());
  EXPECT_EQ(t.flips, 1);
  ASSERT_EQ(t.triangles.rows(), 2);
  for (Index f = 0; f < 2; ++f) {
    const auto row = t.triangles.row(f);
    EXPECT_TRUE((row.array() == 2).any() && (row.array() == 3).any()) << "triangle " << f << " lacks p or q";
    // The side joining p and q is opposite the triangle's third corner.
    for (int k = 0; k < 3; ++k)
      if (row(k) != 2 && row(k) != 3) {
        EXPECT_NEAR(t.lengths(f, k), 1.0, 1e-12);
      }
  }
  EXPECT_NEAR(total_area(t), 2.0, 1e-12);
  EXPECT_GE(least_opposite_cotangent_sum(t), 0.0);
}

// Flipping changes the elements, not the surface: on the flat kite the
// linear function x still has Dirichlet energy x^T L x = the area; the
// mesh's own operator gives the long diagonal a negative weight (a positive
// off-diagonal entry), the intrinsic Delaunay one gives none (Bobenko and
// Springborn 2007).
TEST(IntrinsicDelaunay, TheLaplacianKeepsLinearPrecisionAndLosesItsNegativeWeight) {
  const Mesh kite = flat_kite();
  const LaplaceBeltrami plain = laplace_beltrami(kite);
  LaplaceBeltramiOptions options;
  options.intrinsic_delaunay = true;
  const LaplaceBeltrami flipped = laplace_beltrami(kite, options);
  const Eigen::VectorXd x = kite.vertices.col(0);
  EXPECT_NEAR(x.dot(plain.stiffness * x), 2.0, 1e-12);
  EXPECT_NEAR(x.dot(flipped.stiffness * x), 2.0, 1e-12);
  EXPECT_GT(plain.stiffness.coeff(0, 1), 0.0);
  EXPECT_EQ(flipped.stiffness.coeff(0, 1), 0.0);  // a-b is no longer an edge
  EXPECT_LT(flipped.stiffness.coeff(2, 3), 0.0);  // p-q is
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(4);
  EXPECT_NEAR(ones.dot(flipped.mass * ones), 2.0, 1e-12);
}

// An icosphere is Delaunay already: nothing is flipped, and the lengths are
// the edges'.
TEST(IntrinsicDelaunay, ADelaunayMeshIsLeftAsItIs) {
  const Mesh m = make_icosphere(3);
  const IntrinsicTriangulation t = intrinsic_delaunay(m);
  EXPECT_EQ(t.flips, 0);
  EXPECT_EQ(t.triangles, m.triangles);
  EXPECT_EQ(t.lengths, as_given(m).lengths);
}

// A decimated sphere (slivers and caps, as an edge collapse leaves them):
// after the flips every edge is Delaunay, the area is the mesh's, a second
// run gives the same triangulation, and the Laplacian has no negative edge
// weight (no positive off-diagonal entry).
TEST(IntrinsicDelaunay, EveryEdgeOfADecimatedSphereEndsDelaunay) {
  const Mesh coarse = decimate_mesh(make_icosphere(4), DecimationOptions{0.1, 0.05}).mesh;
  EXPECT_LT(least_opposite_cotangent_sum(as_given(coarse)), -0.1) << "the test needs edges to flip";
  const IntrinsicTriangulation t = intrinsic_delaunay(coarse);
  EXPECT_GT(t.flips, 10);
  EXPECT_GE(least_opposite_cotangent_sum(t), -1e-9);
  EXPECT_NEAR(total_area(t), total_area(as_given(coarse)), 1e-10);
  const IntrinsicTriangulation again = intrinsic_delaunay(coarse);
  EXPECT_EQ(again.triangles, t.triangles);
  EXPECT_EQ(again.lengths, t.lengths);
  LaplaceBeltramiOptions options;
  options.intrinsic_delaunay = true;
  const Eigen::SparseMatrix<double> plain = laplace_beltrami(coarse).stiffness;
  const Eigen::SparseMatrix<double> flipped = laplace_beltrami(coarse, options).stiffness;
  const auto largest_off_diagonal = [](const Eigen::SparseMatrix<double>& a) {
    double largest = -INFINITY;
    for (int c = 0; c < a.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, c); it; ++it)
        if (it.row() != it.col()) largest = std::max(largest, it.value());
    return largest;
  };
  EXPECT_GT(largest_off_diagonal(plain), 0.01);
  EXPECT_LE(largest_off_diagonal(flipped), 1e-12);
}

}  // namespace
}  // namespace reebkit

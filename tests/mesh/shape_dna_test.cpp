#include "reebkit/mesh/shape_dna.h"

#include "reebkit/core/error.h"
#include "reebkit/io/off.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"
#include "support/test_support.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <random>

namespace reebkit {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Largest relative difference between `computed` and `exact` (same length).
double max_relative_error(const std::vector<double>& computed, const std::vector<double>& exact) {
  EXPECT_EQ(computed.size(), exact.size());
  double worst = 0;
  for (std::size_t k = 0; k < std::min(computed.size(), exact.size()); ++k)
    worst = std::max(worst, std::abs(computed[k] - exact[k]) / exact[k]);
  return worst;
}

/// lambda x area of the unit sphere after the zero one: l (l + 1) x 4 pi
/// with multiplicity 2l + 1, for l = 1 .. max_l.
std::vector<double> sphere_spectrum(int max_l) {
  std::vector<double> spectrum;
  for (int l = 1; l <= max_l; ++l) spectrum.insert(spectrum.end(), 2 * l + 1, 4 * kPi * l * (l + 1));
  return spectrum;
}

// The unit sphere: 48 eigenvalues are l = 1 .. 6 each 2l + 1 times; the
// error falls by about 4 per subdivision (h halves, error ~ h^2), so the
// tolerance shrinks with refinement.
TEST(ShapeDna, SphereSpectrumConvergesUnderRefinement) {
  const std::vector<double> exact = sphere_spectrum(6);
  ShapeDnaOptions options;
  options.eigenvalues = static_cast<int>(exact.size());
  std::vector<double> errors;
  for (const int levels : {3, 4, 5}) {
    const ShapeDna dna = shape_dna(make_icosphere(levels), options);
    errors.push_back(max_relative_error(dna.eigenvalues, exact));
  }
  EXPECT_LT(errors[0], 0.07);
  EXPECT_LT(errors[2], 0.005);
  EXPECT_LT(errors[1], errors[0] / 3) << errors[0] << " then " << errors[1];
  EXPECT_LT(errors[2], errors[1] / 3) << errors[1] << " then " << errors[2];
}

// The rectangle [0, 2] x [0, 1] (Neumann eigenvalues pi^2 (m^2 / 4 + n^2))
// on a grid whose vertices are moved within the plane, each by up to 0.4 of
// a cell (those on the border along it): the same flat surface, but the
// grid's diagonals now cut many cells into obtuse triangles whose edges are
// not Delaunay. Their error above the regular grid's (the sampling's own)
// falls by more than 3 on its intrinsic Delaunay triangulation, and the
// eigenvalues stay above the rectangle's (Rayleigh-Ritz).
TEST(ShapeDna, IntrinsicDelaunayBringsASkewedGridNearerItsSpectrum) {
  const int nx = 40, ny = 20;
  const double h = 0.05;
  const Mesh regular = make_grid(nx, ny, h);
  Mesh grid = regular;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> shift(-0.4 * h, 0.4 * h);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const Index v = j * (nx + 1) + i;
      const double dx = shift(rng), dy = shift(rng);
      if (i > 0 && i < nx) grid.vertices(v, 0) += dx;
      if (j > 0 && j < ny) grid.vertices(v, 1) += dy;
    }
  std::vector<double> exact;  // lambda x area, area 2
  for (int m = 0; m <= 8; ++m)
    for (int n = 0; n <= 4; ++n)
      if (m + n > 0) exact.push_back(2 * kPi * kPi * (m * m / 4.0 + n * n));
  std::sort(exact.begin(), exact.end());
  exact.resize(10);
  ShapeDnaOptions options;
  options.eigenvalues = static_cast<int>(exact.size());
  const double plain = max_relative_error(shape_dna(grid, options).eigenvalues, exact);
  options.intrinsic_delaunay = true;
  const ShapeDna flipped = shape_dna(grid, options);
  const double intrinsic = max_relative_error(flipped.eigenvalues, exact);
  options.intrinsic_delaunay = false;
  const double floor = max_relative_error(shape_dna(regular, options).eigenvalues, exact);
  EXPECT_LT(intrinsic - floor, (plain - floor) / 3)
      << "regular grid " << floor << ", own triangles " << plain << ", intrinsic Delaunay " << intrinsic;
  for (std::size_t k = 0; k < exact.size(); ++k) EXPECT_GT(flipped.eigenvalues[k], exact[k] * (1 - 1e-9));
}

// The lumped mass matrix converges to the same spectrum.
TEST(ShapeDna, LumpedMassConvergesToo) {
  const std::vector<double> exact = sphere_spectrum(4);
  ShapeDnaOptions options;
  options.eigenvalues = static_cast<int>(exact.size());
  options.mass = MassMatrix::Lumped;
  const double coarse = max_relative_error(shape_dna(make_icosphere(3), options).eigenvalues, exact);
  const double fine = max_relative_error(shape_dna(make_icosphere(5), options).eigenvalues, exact);
  EXPECT_LT(fine, coarse / 8) << coarse << " then " << fine;
  EXPECT_LT(fine, 0.005);
}

/// The first `count` nonzero eigenvalues x area of the torus of revolution
/// ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), by separation of
/// variables: f = e^{i m u} g(v), with
///   -(rho g')' + (m^2 r^2 / rho) g = lambda r^2 rho g,  rho = R + r cos v,
/// periodic in v, for each m >= 0 (m > 0 twice: cos and sin), solved by
/// second-order finite differences on `cells` points (a symmetric tridiagonal
/// plus corners, diagonalized densely). An oracle independent of the mesh.
std::vector<double> torus_spectrum(double R, double r, int count, int cells = 600) {
  const double h = 2 * kPi / cells;
  const auto rho = [&](double v) { return R + r * std::cos(v); };
  std::vector<double> all;
  for (int m = 0;; ++m) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(cells, cells);
    Eigen::VectorXd inv_sqrt_b(cells);
    for (int i = 0; i < cells; ++i) {
      const double v = i * h, plus = rho(v + h / 2) / (h * h), minus = rho(v - h / 2) / (h * h);
      a(i, i) = plus + minus + m * m * r * r / rho(v);
      a(i, (i + 1) % cells) -= plus;
      a(i, (i + cells - 1) % cells) -= minus;
      inv_sqrt_b(i) = 1 / std::sqrt(r * r * rho(v));
    }
    const Eigen::MatrixXd c = inv_sqrt_b.asDiagonal() * a * inv_sqrt_b.asDiagonal();
    const Eigen::VectorXd values =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(c, Eigen::EigenvaluesOnly).eigenvalues();
    std::sort(all.begin(), all.end());
    if (static_cast<int>(all.size()) > count && values(0) > all[static_cast<std::size_t>(count)]) break;
    for (Eigen::Index k = 0; k < values.size() && k < count + 1; ++k) all.insert(all.end(), m == 0 ? 1 : 2, values(k));
  }
  std::sort(all.begin(), all.end());
  std::vector<double> spectrum(all.begin() + 1, all.begin() + 1 + count);  // without the zero one
  for (double& x : spectrum) x *= 4 * kPi * kPi * R * r;
  return spectrum;
}

// A torus of revolution against its separation-of-variables spectrum; the
// error shrinks by about 4 per refinement.
TEST(ShapeDna, TorusSpectrumMatchesSeparationOfVariables) {
  constexpr double R = 1.0, r = 0.4;
  const std::vector<double> exact = torus_spectrum(R, r, 30);
  ShapeDnaOptions options;
  options.eigenvalues = 30;
  std::vector<double> errors;
  for (const int minor : {12, 24, 48}) {
    const ShapeDna dna = shape_dna(make_torus(3 * minor, minor, R, r), options);
    errors.push_back(max_relative_error(dna.eigenvalues, exact));
  }
  EXPECT_LT(errors[1], errors[0] / 3) << errors[0] << " then " << errors[1];
  EXPECT_LT(errors[2], errors[1] / 3) << errors[1] << " then " << errors[2];
  EXPECT_LT(errors[2], 0.01);
}

// A mesh with boundary gets the Neumann spectrum: the unit square's is
// pi^2 (p^2 + q^2) for p, q >= 0.
TEST(ShapeDna, BoundaryGivesTheNeumannSpectrum) {
  std::vector<double> exact;
  for (int p = 0; p < 12; ++p)
    for (int q = 0; q < 12; ++q) exact.push_back(kPi * kPi * (p * p + q * q));
  std::sort(exact.begin(), exact.end());
  exact.erase(exact.begin());  // the zero one
  exact.resize(24);
  ShapeDnaOptions options;
  options.eigenvalues = 24;
  const double coarse = max_relative_error(shape_dna(make_grid(24, 24, 1.0 / 24), options).eigenvalues, exact);
  const double fine = max_relative_error(shape_dna(make_grid(48, 48, 1.0 / 48), options).eigenvalues, exact);
  EXPECT_LT(fine, coarse / 3) << coarse << " then " << fine;
  EXPECT_LT(fine, 0.015);
}

// Bending without stretching keeps the spectrum (an isometry invariant): the
// unit square rolled into half a cylinder (radius 1 / pi) against the flat
// one; the polygonal arc's chords make the difference O(h^2).
TEST(ShapeDna, IsometricBendingKeepsTheSpectrum) {
  std::vector<double> differences;
  for (const int n : {16, 32}) {
    const Mesh flat = make_grid(n, n, 1.0 / n);
    Mesh rolled = flat;
    for (Index v = 0; v < rolled.num_vertices(); ++v) {
      const double x = flat.vertices(v, 0);
      rolled.vertices.row(v) = Vec3(std::sin(kPi * x) / kPi, flat.vertices(v, 1), (1 - std::cos(kPi * x)) / kPi);
    }
    ShapeDnaOptions options;
    options.eigenvalues = 20;
    differences.push_back(
        max_relative_error(shape_dna(rolled, options).eigenvalues, shape_dna(flat, options).eigenvalues));
  }
  EXPECT_LT(differences[0], 0.01);
  EXPECT_LT(differences[1], differences[0] / 3) << differences[0] << " then " << differences[1];
}

/// `mesh` with its vertices and triangles in a random order, and each
/// triangle's corners rotated.
Mesh renumbered(const Mesh& mesh, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Index> order(static_cast<std::size_t>(mesh.num_vertices()));
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);  // new vertex k is old vertex order[k]
  std::vector<Index> new_of(order.size());
  Mesh out;
  out.vertices.resize(mesh.num_vertices(), 3);
  for (std::size_t k = 0; k < order.size(); ++k) {
    new_of[static_cast<std::size_t>(order[k])] = static_cast<Index>(k);
    out.vertices.row(static_cast<Index>(k)) = mesh.vertices.row(order[k]);
  }
  std::vector<Index> faces(static_cast<std::size_t>(mesh.num_triangles()));
  std::iota(faces.begin(), faces.end(), 0);
  std::shuffle(faces.begin(), faces.end(), rng);
  out.triangles.resize(mesh.num_triangles(), 3);
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int c = 0; c < 3; ++c)
      out.triangles(t, c) =
          new_of[static_cast<std::size_t>(mesh.triangles(faces[static_cast<std::size_t>(t)], (c + t) % 3))];
  return out;
}

// Rigid motion, scale (after the area normalization) and renumbering leave
// the Shape-DNA unchanged, to the solver's tolerance; the distance is then
// about 0, while another shape is far.
TEST(ShapeDna, InvariantToRigidMotionScaleAndRenumbering) {
  StarOptions star;
  star.levels = 3;
  const Mesh mesh = make_star(star);
  const ShapeDna original = shape_dna(mesh);
  ASSERT_EQ(original.eigenvalues.size(), 50u);
  EXPECT_TRUE(std::is_sorted(original.eigenvalues.begin(), original.eigenvalues.end()));
  EXPECT_GT(original.eigenvalues.front(), 1.0);

  Similarity rigid;
  rigid.rotation = random_rotation(5);
  rigid.translation = Vec3(3, -2, 7);
  Similarity scaled = rigid;
  scaled.scale = 0.01;
  for (const Mesh& variant : {transformed(mesh, rigid), transformed(mesh, scaled), renumbered(mesh, 9)}) {
    const ShapeDna dna = shape_dna(variant);
    EXPECT_LT(max_relative_error(dna.eigenvalues, original.eigenvalues), 1e-7);
    EXPECT_LT(shape_dna_distance(dna, original), 1e-6);
  }
  EXPECT_NEAR(shape_dna(transformed(mesh, scaled)).area, 1e-4 * original.area, 1e-9 * original.area);
  star.arms = 3;
  EXPECT_GT(shape_dna_distance(shape_dna(make_star(star)), original), 1.0);
}

// The eigenfunctions are orthonormal for the unit-area mass matrix and solve
// L phi = lambda M phi; the first is the constant 1, and the vertex areas sum
// to 1.
TEST(ShapeDna, EigenfunctionsAreOrthonormalSolutionsOfThePencil) {
  ShapeDnaOptions options;
  options.eigenvalues = 16;
  options.margin = 4;
  options.eigenvectors = true;
  StarOptions star;
  star.levels = 3;
  const Mesh mesh = make_star(star);
  const ShapeDna dna = shape_dna(mesh, options);
  LaplaceBeltrami lb = laplace_beltrami(mesh);
  lb.mass /= dna.area;
  const Eigen::MatrixXd& phi = dna.eigenvectors;
  ASSERT_EQ(phi.cols(), 17);
  ASSERT_EQ(phi.rows(), mesh.num_vertices());
  const Eigen::MatrixXd gram = phi.transpose() * (lb.mass * phi);
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(17, 17)).cwiseAbs().maxCoeff(), 1e-8);
  for (Eigen::Index k = 1; k < 17; ++k) {
    const Eigen::VectorXd residual =
        lb.stiffness * phi.col(k) - dna.eigenvalues[static_cast<std::size_t>(k - 1)] * (lb.mass * phi.col(k));
    EXPECT_LT(residual.norm(), 1e-6 * dna.eigenvalues[static_cast<std::size_t>(k - 1)]) << "eigenpair " << k;
  }
  EXPECT_LT((phi.col(0).cwiseAbs() - Eigen::VectorXd::Ones(phi.rows())).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_NEAR(dna.vertex_area.sum(), 1.0, 1e-12);
  EXPECT_GT(dna.next_eigenvalue, dna.eigenvalues.back());
}

// The distance is the Euclidean distance of lambda_k area / k over the
// common length.
TEST(ShapeDna, DistanceWeighsEachEigenvalueByItsIndex) {
  ShapeDna a, b;
  a.eigenvalues = {10, 20, 30}, a.area = 1.0;
  b.eigenvalues = {13, 28, 30, 99}, b.area = 2.0;
  EXPECT_DOUBLE_EQ(shape_dna_distance(a, b), std::sqrt(3.0 * 3.0 + 4.0 * 4.0));
  EXPECT_EQ(shape_dna_distance(a, a), 0.0);
  EXPECT_EQ(shape_dna_distance(a, b), shape_dna_distance(b, a));
}

// A TOSCA mesh with holes: the Neumann spectrum, one zero eigenvalue (one
// piece), no error.
TEST(ShapeDna, ToscaMeshWithHoles) {
  const auto tosca = test::shared_dataset("tosca_dev");
  if (!tosca) GTEST_SKIP() << "../shared/datasets is not beside the checkout";
  const Mesh mesh = std::move(load_mesh(*tosca / "centaur3.off").components.front());
  const ShapeDna dna = shape_dna(mesh);
  ASSERT_EQ(dna.eigenvalues.size(), 50u);
  EXPECT_GT(dna.eigenvalues.front(), 0.5);
  EXPECT_TRUE(std::is_sorted(dna.eigenvalues.begin(), dna.eigenvalues.end()));
  for (const double x : dna.eigenvalues) EXPECT_TRUE(std::isfinite(x));
}

// Triangles of zero area injected into a mesh the reader accepts (on three
// edges a fin of zero area to a new vertex at the edge's midpoint, which lies
// on that fin only): the spectrum is that of the mesh without them.
TEST(ShapeDna, InjectedZeroAreaTrianglesLeaveTheSpectrum) {
  const Mesh sphere = make_icosphere(3);
  Mesh injected = sphere;
  injected.source = "injected.off";
  const Index n = sphere.num_vertices();
  injected.vertices.conservativeResize(n + 3, 3);
  injected.triangles.conservativeResize(sphere.num_triangles() + 3, 3);
  for (int k = 0; k < 3; ++k) {  // on edge k of triangle 10 k
    const Index a = sphere.triangles(10 * k, k), b = sphere.triangles(10 * k, (k + 1) % 3);
    injected.vertices.row(n + k) = 0.5 * (sphere.vertices.row(a) + sphere.vertices.row(b));
    injected.triangles.row(sphere.num_triangles() + k) << a, b, n + k;
  }
  const std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / "shape_dna_injected.off";
  write_off(path, injected);
  const CleanedMesh cleaned = load_mesh(path);  // the reader keeps it whole
  std::filesystem::remove(path);
  ASSERT_EQ(cleaned.components.size(), 1u);
  ASSERT_EQ(cleaned.components[0].num_vertices(), n + 3);
  ShapeDnaOptions options;
  options.eigenvalues = 20;
  const ShapeDna with = shape_dna(cleaned.components[0], options), without = shape_dna(sphere, options);
  EXPECT_LT(max_relative_error(with.eigenvalues, without.eigenvalues), 1e-7);
}

TEST(ShapeDna, BadInputIsAClearError) {
  Mesh small = make_icosphere(0);  // 12 vertices
  small.source = "small.off";
  const std::string message = test::thrown_message<InvalidMeshError>([&] { shape_dna(small); });
  EXPECT_NE(message.find("small.off: 12 vertices with area: too few for 50"), std::string::npos) << message;
  ShapeDnaOptions options;
  options.eigenvalues = 5;
  EXPECT_EQ(shape_dna(small, options).eigenvalues.size(), 5u);
  options.shift = 0.0;
  EXPECT_THROW(shape_dna(small, options), InvalidArgument);
  options.shift = -0.01;
  options.eigenvalues = 0;
  EXPECT_THROW(shape_dna(small, options), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

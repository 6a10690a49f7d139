#include "reebkit/attributes/region_spectra.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace reebkit {
namespace {

/// s = lambda_k x area / (4 pi k) back from the stored s / (1 + s).
double unsquash(double t) { return t / (1.0 - t); }

/// The unit sphere's Laplace-Beltrami eigenvalues l (l + 1), each 2 l + 1
/// times, from lambda_1 on (the zero one left out).
std::vector<double> sphere_eigenvalues(int count) {
  std::vector<double> out;
  for (int l = 1; static_cast<int>(out.size()) < count; ++l)
    for (int m = -l; m <= l && static_cast<int>(out.size()) < count; ++m) out.push_back(l * (l + 1.0));
  return out;
}

std::vector<Index> labels_by_height(const Mesh& mesh) {
  std::vector<Index> label(static_cast<std::size_t>(mesh.num_vertices()));
  for (Index v = 0; v < mesh.num_vertices(); ++v) label[static_cast<std::size_t>(v)] = mesh.vertices(v, 2) >= 0.0 ? 1 : 0;
  return label;
}

// The whole surface: lambda_k area / (4 pi k) = l (l + 1) / k on the unit
// sphere, on the coarse copy of a 10,242-vertex icosphere (decimated to
// 2,000 vertices) as on a 2,562-vertex one used as it is.
TEST(RegionSpectra, SphereHasTheAnalyticSpectrum) {
  for (const int levels : {4, 5}) {
    SCOPED_TRACE(levels);
    const Mesh sphere = make_icosphere(levels, 3.0);  // any radius: area-normalized
    const SurfaceSpectra s = surface_spectra(sphere, std::vector<Index>(static_cast<std::size_t>(sphere.num_vertices()), 0), 1);
    ASSERT_EQ(s.global.size(), static_cast<std::size_t>(kGlobalSpectrumLength));
    const std::vector<double> exact = sphere_eigenvalues(kGlobalSpectrumLength);
    for (int k = 0; k < kGlobalSpectrumLength; ++k)
      EXPECT_NEAR(unsquash(s.global[static_cast<std::size_t>(k)]) / (exact[static_cast<std::size_t>(k)] / (k + 1)), 1.0, 0.03)
          << "lambda_" << k + 1;
    // One region, the whole sphere: its spectrum is the global one's start
    // (its vertices renumbered, so decimated along other collapses).
    for (int k = 0; k < kRegionSpectrumLength; ++k)
      EXPECT_NEAR(s.region[static_cast<std::size_t>(k)], s.global[static_cast<std::size_t>(k)], 1e-3);
  }
}

// Each half of a sphere cut at its equator, with the Neumann condition on
// the cut: the spherical harmonics even across the equator (l + m even),
// lambda = 2, 2, 6, 6, 6, 12 on the unit hemisphere, of area 2 pi, so
// lambda_k area / (4 pi k) = lambda_k / (2 k). The cut follows the mesh
// edges, so it zig-zags about the equator.
TEST(RegionSpectra, HemispheresHaveTheNeumannSpectrum) {
  const Mesh sphere = make_icosphere(5);
  const SurfaceSpectra s = surface_spectra(sphere, labels_by_height(sphere), 2);
  const double exact[kRegionSpectrumLength] = {2, 2, 6, 6, 6, 12};
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < kRegionSpectrumLength; ++k)
      EXPECT_NEAR(unsquash(s.region[static_cast<std::size_t>(r * kRegionSpectrumLength + k)]) / (exact[k] / (2.0 * (k + 1))),
                  1.0, 0.05)
          << "region " << r << " lambda_" << k + 1;
}

// Rotation, translation, scale and a renumbering of the vertices change the
// spectra only as far as the decimation's choices move with the rounding.
TEST(RegionSpectra, SimilarityAndRenumberingLeaveTheSpectraNearlyUnchanged) {
  StarOptions options;
  options.arms = 5;
  options.levels = 5;
  const Mesh star = make_star(options);
  const std::vector<Index> label = labels_by_height(star);
  const SurfaceSpectra before = surface_spectra(star, label, 2);
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 3; ++trial) {
    SCOPED_TRACE(trial);
    const Mesh moved = transformed(star, random_similarity(star, rng));
    // Renumber the vertices by a random permutation.
    std::vector<Index> order(static_cast<std::size_t>(star.num_vertices()));
    std::iota(order.begin(), order.end(), Index{0});
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Index> moved_label(label.size());
    for (std::size_t v = 0; v < label.size(); ++v) moved_label[static_cast<std::size_t>(order[v])] = label[v];
    const SurfaceSpectra after = surface_spectra(test::renumbered(moved, order), moved_label, 2);
    for (std::size_t k = 0; k < before.global.size(); ++k) EXPECT_NEAR(after.global[k], before.global[k], 0.01) << k;
    for (std::size_t k = 0; k < before.region.size(); ++k) EXPECT_NEAR(after.region[k], before.region[k], 0.01) << k;
  }
}

TEST(RegionSpectra, SmallRegionsGetZerosAndBadInputIsRefused) {
  const Mesh sphere = make_icosphere(3);
  std::vector<Index> label(static_cast<std::size_t>(sphere.num_vertices()), 0);
  label[0] = 1;  // a region of one vertex
  const SurfaceSpectra s = surface_spectra(sphere, label, 2);
  for (int k = 0; k < kRegionSpectrumLength; ++k) {
    EXPECT_GT(s.region[static_cast<std::size_t>(k)], 0.0);
    EXPECT_EQ(s.region[static_cast<std::size_t>(kRegionSpectrumLength + k)], 0.0);
  }
  // A surface of 8 vertices has no 16 eigenvalues to give: zeros, no error
  // (reeb index still indexes its graph).
  const Mesh cube = make_cube();
  const SurfaceSpectra tiny = surface_spectra(cube, std::vector<Index>(static_cast<std::size_t>(cube.num_vertices()), 0), 1);
  for (const double x : tiny.global) EXPECT_EQ(x, 0.0);
  EXPECT_THROW(surface_spectra(sphere, std::vector<Index>(3, 0), 1), InvalidArgument);
  EXPECT_THROW(surface_spectra(sphere, label, 1), InvalidArgument);  // label 1 outside [0, 1)
  SpectraOptions bad;
  bad.coarse_vertices = 10;
  EXPECT_THROW(surface_spectra(sphere, label, 2, bad), InvalidArgument);
  bad = {};
  bad.min_region_area = 1.5;
  EXPECT_THROW(surface_spectra(sphere, label, 2, bad), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

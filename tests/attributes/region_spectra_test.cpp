#include "reebkit/attributes/region_spectra.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/resampling.h"
#include "reebkit/mesh/shape_dna.h"
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

/// The default options with the regions' spectra on.
SpectraOptions with_regions() {
  SpectraOptions options;
  options.regions = true;
  return options;
}

std::vector<Index> labels_by_height(const Mesh& mesh, double level = 0.0) {
  std::vector<Index> label(static_cast<std::size_t>(mesh.num_vertices()));
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    label[static_cast<std::size_t>(v)] = mesh.vertices(v, 2) >= level ? 1 : 0;
  return label;
}

/// The largest difference between the spectra of `mesh` and those of three
/// random similar copies with their vertices renumbered.
double largest_change_under_similarity(const Mesh& mesh, const std::vector<Index>& label, Index regions,
                                       const SpectraOptions& options = with_regions()) {
  const SurfaceSpectra before = surface_spectra(mesh, label, regions, options);
  std::mt19937_64 rng(7);
  double largest = 0.0;
  for (int trial = 0; trial < 3; ++trial) {
    const Mesh moved = transformed(mesh, random_similarity(mesh, rng));
    std::vector<Index> order(static_cast<std::size_t>(mesh.num_vertices()));
    std::iota(order.begin(), order.end(), Index{0});
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Index> moved_label(label.size());
    for (std::size_t v = 0; v < label.size(); ++v) moved_label[static_cast<std::size_t>(order[v])] = label[v];
    const SurfaceSpectra after = surface_spectra(renumbered(moved, order), moved_label, regions, options);
    for (std::size_t k = 0; k < before.global.size(); ++k)
      largest = std::max(largest, std::abs(after.global[k] - before.global[k]));
    for (std::size_t k = 0; k < before.region.size(); ++k)
      largest = std::max(largest, std::abs(after.region[k] - before.region[k]));
  }
  return largest;
}

// The whole surface: lambda_k area / (4 pi k) = l (l + 1) / k on the unit
// sphere, on the coarse copy of a 10,242-vertex icosphere (decimated to
// 2,000 vertices) as on a 2,562-vertex one used as it is.
TEST(RegionSpectra, SphereHasTheAnalyticSpectrum) {
  for (const int levels : {4, 5}) {
    SCOPED_TRACE(levels);
    const Mesh sphere = make_icosphere(levels, 3.0);  // any radius: area-normalized
    const SurfaceSpectra s =
        surface_spectra(sphere, std::vector<Index>(static_cast<std::size_t>(sphere.num_vertices()), 0), 1,
                        with_regions());
    ASSERT_EQ(s.global.size(), static_cast<std::size_t>(kGlobalSpectrumLength + kGlobalHeatLength));
    const std::vector<double> exact = sphere_eigenvalues(kGlobalSpectrumLength);
    for (int k = 0; k < kGlobalSpectrumLength; ++k)
      EXPECT_NEAR(unsquash(s.global[static_cast<std::size_t>(k)]) / (exact[static_cast<std::size_t>(k)] / (k + 1)), 1.0,
                  0.03)
          << "lambda_" << k + 1;
    // The heat kernel signature is the same everywhere: every quantile r of
    // HKS / Z is 1, squashed to 1/2.
    for (int k = 0; k < kGlobalHeatLength; ++k)
      EXPECT_NEAR(s.global[static_cast<std::size_t>(kGlobalSpectrumLength + k)], 0.5, 0.003) << "heat entry " << k;
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
  const SurfaceSpectra s = surface_spectra(sphere, labels_by_height(sphere), 2, with_regions());
  const double exact[kRegionSpectrumLength] = {2, 2, 6, 6, 6, 12};
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < kRegionSpectrumLength; ++k)
      EXPECT_NEAR(unsquash(s.region[static_cast<std::size_t>(r * kRegionSpectrumLength + k)]) /
                      (exact[k] / (2.0 * (k + 1))),
                  1.0, 0.05)
          << "region " << r << " lambda_" << k + 1;
}

// Rotation, translation, scale and a renumbering of the vertices leave the
// spectra unchanged to rounding: the decimation runs on the canonical copy,
// which similar copies share (a star's axes are well-defined, so its copies
// are decimated).
TEST(RegionSpectra, SimilarityAndRenumberingLeaveTheSpectraUnchanged) {
  StarOptions options;
  options.arms = 5;
  options.levels = 5;
  const Mesh star = make_star(options);
  ASSERT_GT(star.num_vertices(), SpectraOptions{}.coarse_vertices);
  ASSERT_GE(canonical_copy(star).axis_gap, SpectraOptions{}.min_axis_gap);
  EXPECT_LT(largest_change_under_similarity(star, labels_by_height(star), 2), 1e-6);
  // Also where the surface is first decimated to a finer copy (a large mesh).
  SpectraOptions fine = with_regions();
  fine.fine_vertices = star.num_vertices() / 2;
  ASSERT_TRUE(spectra_surface(star, fine).decimated());
  EXPECT_LT(largest_change_under_similarity(star, labels_by_height(star), 2, fine), 1e-6);
}

// With the regions' spectra, a surface of more than fine_vertices vertices is
// decimated once to about that many, and the regions' coarse copies are
// taken from there: their spectra stay those of the surface (the bunny's
// subdivided once, its regions cut at mid-height). The whole surface's copy
// is taken from the surface itself: its values depend neither on
// fine_vertices nor on the regions option.
TEST(RegionSpectra, ALargeSurfaceDecimatedOnceFirstKeepsItsSpectra) {
  const Mesh bunny = subdivide_mesh(load_mesh(test::embedded_dataset_dir() / "bunny.off").components.front(), 1)
                         .mesh;  // 7,352 vertices
  ASSERT_LT(bunny.num_vertices(), SpectraOptions{}.fine_vertices);
  SpectraOptions options = with_regions();
  options.fine_vertices = 4000;
  const SpectraSurface surface = spectra_surface(bunny, options);
  ASSERT_TRUE(surface.decimated());
  EXPECT_NEAR(surface.mesh.num_vertices(), options.fine_vertices, 0.25 * options.fine_vertices);
  EXPECT_EQ(surface.input_vertices, bunny.num_vertices());
  std::vector<Index> seen = surface.original_vertex;
  std::sort(seen.begin(), seen.end());
  EXPECT_TRUE(std::adjacent_find(seen.begin(), seen.end()) == seen.end());
  EXPECT_TRUE(seen.front() >= 0 && seen.back() < bunny.num_vertices());
  const double middle = 0.5 * (bunny.vertices.col(1).minCoeff() + bunny.vertices.col(1).maxCoeff());
  std::vector<Index> label(static_cast<std::size_t>(bunny.num_vertices()));
  for (Index v = 0; v < bunny.num_vertices(); ++v) label[static_cast<std::size_t>(v)] = bunny.vertices(v, 1) >= middle;
  const SurfaceSpectra direct = surface_spectra(bunny, label, 2, with_regions());
  const SurfaceSpectra staged = surface_spectra(bunny, surface, label, 2, options);
  double largest = 0.0;
  for (std::size_t k = 0; k < direct.global.size(); ++k)
    largest = std::max(largest, std::abs(staged.global[k] - direct.global[k]));
  for (std::size_t k = 0; k < direct.region.size(); ++k)
    largest = std::max(largest, std::abs(staged.region[k] - direct.region[k]));
  EXPECT_GT(direct.region[0], 0.0);
  EXPECT_LT(largest, 0.01);
  // The whole surface's spectrum is the one prepared with the surface, and
  // the same without the fine copy or without the regions.
  EXPECT_EQ(staged.global, surface.global);
  EXPECT_EQ(direct.global, surface.global);
  const SpectraSurface without_regions = spectra_surface(bunny, SpectraOptions{});
  EXPECT_EQ(without_regions.global, surface.global);
  EXPECT_EQ(without_regions.mesh.num_vertices(), 0);
  EXPECT_THROW(surface_spectra(bunny, without_regions, label, 2, options), InvalidArgument);
  EXPECT_EQ(surface_spectra(bunny, without_regions, label, 2, SpectraOptions{}).global, surface.global);
  // A surface prepared for another mesh, or not by spectra_surface, is refused.
  const Mesh other = make_icosphere(3);
  EXPECT_THROW(surface_spectra(other, surface, std::vector<Index>(static_cast<std::size_t>(other.num_vertices()), 0), 1,
                               options),
               InvalidArgument);
  SpectraSurface without_spectrum = surface;
  without_spectrum.global.clear();
  EXPECT_THROW(surface_spectra(bunny, without_spectrum, label, 2, options), InvalidArgument);
}

// The whole surface's spectrum is computed on a copy of about
// global_vertices vertices, finer than the regions': on the bunny subdivided
// once it is nearer the spectrum of the surface itself than that of a copy
// as coarse as the regions', and the regions' spectra do not depend on it.
TEST(RegionSpectra, TheWholeSurfaceSpectrumComesFromAFinerCopy) {
  const Mesh bunny = subdivide_mesh(load_mesh(test::embedded_dataset_dir() / "bunny.off").components.front(), 1)
                         .mesh;  // 7,352 vertices
  ShapeDnaOptions dna;
  dna.eigenvalues = kGlobalSpectrumLength;
  dna.margin = 4;
  const std::vector<double> whole = shape_dna(canonical_copy(bunny).mesh, dna).eigenvalues;
  const std::vector<Index> label = labels_by_height(bunny);
  // The largest relative error of lambda_k x area against the whole surface's.
  const auto error = [&](const SurfaceSpectra& s) {
    double largest = 0.0;
    for (std::size_t k = 0; k < whole.size(); ++k) {
      const double lambda = unsquash(s.global[k]) * 4.0 * M_PI * static_cast<double>(k + 1);
      largest = std::max(largest, std::abs(lambda / whole[k] - 1.0));
    }
    return largest;
  };
  SpectraOptions finer = with_regions(), as_coarse = with_regions();
  finer.global_vertices = bunny.num_vertices() / 2;
  as_coarse.global_vertices = as_coarse.coarse_vertices;
  const SurfaceSpectra fine = surface_spectra(bunny, label, 2, finer),
                       coarse = surface_spectra(bunny, label, 2, as_coarse);
  EXPECT_LT(error(fine), 0.75 * error(coarse)) << error(fine) << " against " << error(coarse);
  EXPECT_EQ(fine.region, coarse.region);
}

// Bearings (SHREC07 348 and 349, mechanical parts with a symmetry axis and
// flat faces) have ill-defined axes: their spectra are those of the surface
// as given, unchanged by a similarity. Their coarse copies would follow the
// rounding, and so would their canonical copies, snapped to a grid in a
// frame that turns with it: on 348 the spectra moved by up to 1e-4.
TEST(RegionSpectra, NearSymmetricShapeKeepsItsSpectraUnderSimilarity) {
  REEBKIT_REQUIRE_DATASET(dir, "shrec07_watertight");
  for (const char* file : {"348.off", "349.off"}) {
    const Mesh bearing = load_mesh(dir / file).components.front();
    ASSERT_LT(surface_frame(bearing).axis_gap, SpectraOptions{}.min_axis_gap) << file;
    const double middle = 0.5 * (bearing.vertices.col(2).minCoeff() + bearing.vertices.col(2).maxCoeff());
    EXPECT_LT(largest_change_under_similarity(bearing, labels_by_height(bearing, middle), 2), 1e-6) << file;
  }
}

// Where the decimation straight to the whole surface's copy cuts a thin part
// off (SHREC07's glasses, 45: their copy of a quarter of the vertices falls
// in two at a temple), the copy is taken from a milder one of about
// fine_vertices: the values then depend on fine_vertices, which they do not
// where the direct copy holds, and stay near those of the surface itself.
TEST(RegionSpectra, ACopyThatFallsApartIsTakenFromAMilderOne) {
  REEBKIT_REQUIRE_DATASET(dir, "shrec07_watertight");
  const Mesh glasses = load_mesh(dir / "45.off").components.front();  // 5,399 vertices
  SpectraOptions quarter;
  quarter.coarse_vertices = 100;
  quarter.global_vertices = glasses.num_vertices() / 4;
  SpectraOptions milder = quarter, larger = quarter;
  milder.fine_vertices = glasses.num_vertices() / 2;  // the fallback's copy, which holds together
  larger.fine_vertices = glasses.num_vertices() + 1;  // none: the surface itself
  const std::vector<double> from_milder = spectra_surface(glasses, milder).global,
                            whole = spectra_surface(glasses, larger).global;
  EXPECT_NE(from_milder, whole);
  double largest = 0.0;
  for (std::size_t k = 0; k < whole.size(); ++k) {
    EXPECT_GT(from_milder[k], 0.0) << k;
    largest = std::max(largest, std::abs(from_milder[k] - whole[k]));
  }
  EXPECT_LT(largest, 0.05);
  // Where the direct copy holds (half the vertices), fine_vertices does not matter.
  SpectraOptions half = milder;
  half.global_vertices = glasses.num_vertices() / 2;
  half.fine_vertices = glasses.num_vertices() / 4 * 3;
  SpectraOptions half_larger = half;
  half_larger.fine_vertices = glasses.num_vertices() + 1;
  EXPECT_EQ(spectra_surface(glasses, half).global, spectra_surface(glasses, half_larger).global);
}

TEST(RegionSpectra, SmallRegionsGetZerosAndBadInputIsRefused) {
  const Mesh sphere = make_icosphere(3);
  std::vector<Index> label(static_cast<std::size_t>(sphere.num_vertices()), 0);
  label[0] = 1;  // a region of one vertex
  const SurfaceSpectra s = surface_spectra(sphere, label, 2, with_regions());
  for (int k = 0; k < kRegionSpectrumLength; ++k) {
    EXPECT_GT(s.region[static_cast<std::size_t>(k)], 0.0);
    EXPECT_EQ(s.region[static_cast<std::size_t>(kRegionSpectrumLength + k)], 0.0);
  }
  // Without SpectraOptions::regions, zeros for every region; the whole
  // surface's values are the same.
  const SurfaceSpectra whole_only = surface_spectra(sphere, label, 2);
  for (const double x : whole_only.region) EXPECT_EQ(x, 0.0);
  EXPECT_EQ(whole_only.global, s.global);
  // A surface of 8 vertices has no 16 eigenvalues to give: zeros, no error
  // (reeb index still indexes its graph).
  const Mesh cube = make_cube();
  const SurfaceSpectra tiny =
      surface_spectra(cube, std::vector<Index>(static_cast<std::size_t>(cube.num_vertices()), 0), 1);
  for (const double x : tiny.global) EXPECT_EQ(x, 0.0);
  EXPECT_THROW(surface_spectra(sphere, std::vector<Index>(3, 0), 1), InvalidArgument);
  EXPECT_THROW(surface_spectra(sphere, label, 1), InvalidArgument);  // label 1 outside [0, 1)
  SpectraOptions bad;
  bad.coarse_vertices = 10;
  EXPECT_THROW(surface_spectra(sphere, label, 2, bad), InvalidArgument);
  bad = {};
  bad.min_region_area = 1.5;
  EXPECT_THROW(surface_spectra(sphere, label, 2, bad), InvalidArgument);
  bad = {};
  bad.global_vertices = bad.coarse_vertices - 1;
  EXPECT_THROW(surface_spectra(sphere, label, 2, bad), InvalidArgument);
  bad = {};
  bad.fine_vertices = bad.coarse_vertices - 1;
  EXPECT_THROW(surface_spectra(sphere, label, 2, bad), InvalidArgument);
  bad = {};
  bad.min_axis_gap = -0.1;
  EXPECT_THROW(surface_spectra(sphere, label, 2, bad), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

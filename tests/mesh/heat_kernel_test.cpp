#include "reebkit/mesh/heat_kernel.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

namespace reebkit {
namespace {

ShapeDna with_eigenvectors(const Mesh& mesh, int eigenvalues = 16) {
  ShapeDnaOptions options;
  options.eigenvalues = eigenvalues;
  options.margin = 4;
  options.eigenvectors = true;
  return shape_dna(mesh, options);
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
  return worst;
}

// The sum stops before a multiple eigenvalue the range cuts.
TEST(HeatKernel, TheSumStopsBeforeAMultipletTheRangeCuts) {
  ShapeDna dna;
  dna.eigenvalues = {1.0, 2.0, 3.0, 3.001};
  dna.next_eigenvalue = 3.002;
  EXPECT_EQ(whole_eigenspaces(dna, 1e-2), 3);  // k = 0, 1, 2
  dna.next_eigenvalue = 4.0;
  EXPECT_EQ(whole_eigenspaces(dna, 1e-2), 5);
  EXPECT_EQ(whole_eigenspaces(dna, 1e-4), 5);
  dna.next_eigenvalue = std::numeric_limits<double>::infinity();
  EXPECT_EQ(whole_eigenspaces(dna, 1e-2), 5);
  // lambda_1..lambda_16 of a sphere end on the first of the nine copies of
  // l = 4 (k = 16 .. 24): the sum keeps l <= 3 whole.
  EXPECT_EQ(whole_eigenspaces(with_eigenvectors(make_icosphere(3)), HeatKernelOptions{}.multiplet_gap), 16);
}

// On a sphere the heat kernel signature is the same at every point (the sum
// over each whole eigenspace is constant), so every quantile of
// ln(HKS / Z) is 0 and a time's quantiles are equal, up to the
// discretization. With the partial eigenspace of l = 4 in the sum they
// would spread by 0.03.
TEST(HeatKernel, SphereHeatIsUniform) {
  const std::vector<double> q = heat_kernel_quantiles(with_eigenvectors(make_icosphere(4)));
  const HeatKernelOptions defaults;
  const auto quantiles = static_cast<std::size_t>(defaults.quantiles);
  ASSERT_EQ(q.size(), defaults.times.size() * quantiles);
  for (const double x : q) EXPECT_NEAR(x, 0.0, 0.005);
  for (std::size_t t = 0; t < defaults.times.size(); ++t)
    EXPECT_LT(q[(t + 1) * quantiles - 1] - q[t * quantiles], 0.002) << "time " << defaults.times[t];
}

// A star's heat stays longest at the tips of its arms: at the smallest time
// the top quantile is well above 1 x Z and the distribution spreads; each
// time's quantiles ascend.
TEST(HeatKernel, HeatStaysAtTheTips) {
  StarOptions star;
  star.levels = 3;
  const std::vector<double> q = heat_kernel_quantiles(with_eigenvectors(make_star(star)));
  const auto quantiles = static_cast<std::size_t>(HeatKernelOptions{}.quantiles);
  for (std::size_t t = 0; t < q.size() / quantiles; ++t)
    EXPECT_TRUE(std::is_sorted(q.begin() + t * quantiles, q.begin() + (t + 1) * quantiles));
  EXPECT_GT(q[quantiles - 1], 0.3);
  EXPECT_LT(q[0], -0.2);
}

// Rigid motion, scale and vertex renumbering leave the quantiles unchanged.
TEST(HeatKernel, InvariantToSimilarityAndRenumbering) {
  StarOptions star;
  star.levels = 3;
  star.arms = 4;
  const Mesh mesh = make_star(star);
  const std::vector<double> original = heat_kernel_quantiles(with_eigenvectors(mesh));
  Similarity motion;
  motion.rotation = random_rotation(3);
  motion.translation = Vec3(-4, 1, 2);
  motion.scale = 37.0;
  EXPECT_LT(max_difference(heat_kernel_quantiles(with_eigenvectors(transformed(mesh, motion))), original), 1e-6);
  std::vector<Index> to(static_cast<std::size_t>(mesh.num_vertices()));
  std::iota(to.begin(), to.end(), 0);
  std::shuffle(to.begin(), to.end(), std::mt19937_64(4));
  EXPECT_LT(max_difference(heat_kernel_quantiles(with_eigenvectors(renumbered(mesh, to))), original), 1e-6);
}

TEST(HeatKernel, BadInputIsRefused) {
  ShapeDnaOptions plain;
  plain.eigenvalues = 8;
  const ShapeDna without = shape_dna(make_icosphere(2), plain);
  EXPECT_THROW(heat_kernel_quantiles(without), InvalidArgument);
  const ShapeDna dna = with_eigenvectors(make_icosphere(2), 8);
  HeatKernelOptions bad;
  bad.quantiles = 0;
  EXPECT_THROW(heat_kernel_quantiles(dna, bad), InvalidArgument);
  bad = {};
  bad.times = {0.1, -1.0};
  EXPECT_THROW(heat_kernel_quantiles(dna, bad), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

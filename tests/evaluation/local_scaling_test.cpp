#include "reebkit/evaluation/local_scaling.h"

#include "reebkit/core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace reebkit {
namespace {

/// |x_i - x_j| for points on a line.
DistanceMatrix line_distances(const std::vector<double>& x) {
  const auto n = static_cast<Eigen::Index>(x.size());
  DistanceMatrix d(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      d(i, j) = static_cast<float>(std::abs(x[static_cast<std::size_t>(i)] - x[static_cast<std::size_t>(j)]));
  return d;
}

Eigen::Index nearest_other(const DistanceMatrix& d, Eigen::Index i) {
  Eigen::Index best = i == 0 ? 1 : 0;
  for (Eigen::Index j = 0; j < d.cols(); ++j)
    if (j != i && d(i, j) < d(i, best)) best = j;
  return best;
}

// A tight class {0, 0.1, 0.2} next to a loose one {1, 2, 3}: 1.0 is nearer to
// 0.2 (0.8) than to its own class (1.0). With k = 2 the radii are, by hand,
// sigma = 0.2, 0.1, 0.2 (the tight class), 0.9, 1, 2 (the loose one), and
// 1.0's distances become 0.8 / sqrt(0.9 x 0.2) = 1.886 to 0.2 and
// 1 / sqrt(0.9 x 1) = 1.054 to 2.0: its nearest neighbour is now in its class.
TEST(LocalScaling, HandComputedRadiiBringALooseClassTogether) {
  const DistanceMatrix d = line_distances({0.0, 0.1, 0.2, 1.0, 2.0, 3.0});
  ASSERT_EQ(nearest_other(d, 3), 2);
  const DistanceMatrix s = local_scaling(d, 2);
  const double sigma[] = {0.2, 0.1, 0.2, 0.9, 1.0, 2.0};
  for (Eigen::Index i = 0; i < 6; ++i)
    for (Eigen::Index j = 0; j < 6; ++j)
      EXPECT_NEAR(s(i, j), d(i, j) / std::sqrt(sigma[i] * sigma[j]), 1e-5) << i << ", " << j;
  EXPECT_NEAR(s(3, 2), 0.8 / std::sqrt(0.18), 1e-5);
  EXPECT_NEAR(s(3, 4), 1.0 / std::sqrt(0.9), 1e-5);
  EXPECT_EQ(nearest_other(s, 3), 4);
}

TEST(LocalScaling, SymmetricScaleInvariantAndZerosStayZero) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  std::vector<double> x(40);
  for (double& v : x) v = u(random);
  x[7] = x[3];  // a duplicate: a zero off the diagonal
  const DistanceMatrix d = line_distances(x);
  for (const int k : {1, 5, 39}) {
    const DistanceMatrix s = local_scaling(d, k);
    const DistanceMatrix scaled = local_scaling(DistanceMatrix(d * 1000.0f), k);
    for (Eigen::Index i = 0; i < d.rows(); ++i)
      for (Eigen::Index j = 0; j < d.cols(); ++j) {
        EXPECT_EQ(s(i, j), s(j, i));
        EXPECT_NEAR(scaled(i, j), s(i, j), 1e-5 * (1.0 + s(i, j))) << "k " << k;
        if (d(i, j) == 0.0f)
          EXPECT_EQ(s(i, j), 0.0f);
        else
          EXPECT_GT(s(i, j), 0.0f);
      }
  }
}

TEST(LocalScaling, ZeroRadiiAreRaisedAndAllZeroIsUnchanged) {
  // A duplicate: with k = 1 the radii of models 0 and 1 are 0, raised to the
  // smallest positive radius, 3 (that of models 2 and 3).
  const DistanceMatrix d = line_distances({0.0, 0.0, 3.0, 6.0});
  const DistanceMatrix s = local_scaling(d, 1);
  EXPECT_TRUE(s.allFinite());
  EXPECT_NEAR(s(0, 2), 3.0 / std::sqrt(3.0 * 3.0), 1e-6);
  const DistanceMatrix zeros = DistanceMatrix::Zero(3, 3);
  EXPECT_EQ(local_scaling(zeros, 2), zeros);
}

TEST(LocalScaling, RejectsBadInput) {
  const DistanceMatrix d = line_distances({0.0, 1.0, 2.0});
  EXPECT_THROW(local_scaling(d, 0), InvalidArgument);
  EXPECT_THROW(local_scaling(d, 3), InvalidArgument);
  EXPECT_THROW(local_scaling(DistanceMatrix(2, 3), 1), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

#include "reebkit/evaluation/local_scaling.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace reebkit {

DistanceMatrix local_scaling(const DistanceMatrix& distances, int k) {
  const Eigen::Index n = distances.rows();
  if (distances.cols() != n)
    throw InvalidArgument("local_scaling: the matrix is " + std::to_string(n) + " x " +
                          std::to_string(distances.cols()) + ", not square");
  if (k < 1 || k > n - 1)
    throw InvalidArgument("local_scaling: k = " + std::to_string(k) + " is not in [1, " + std::to_string(n - 1) +
                          "] (models other than the query)");
  std::vector<double> sigma(static_cast<std::size_t>(n));
  std::vector<float> others(static_cast<std::size_t>(n - 1));
  double smallest_positive = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < n; ++i) {
    std::size_t m = 0;
    for (Eigen::Index j = 0; j < n; ++j)
      if (j != i) others[m++] = distances(i, j);
    std::nth_element(others.begin(), others.begin() + (k - 1), others.end());
    sigma[static_cast<std::size_t>(i)] = others[static_cast<std::size_t>(k - 1)];
    if (sigma[static_cast<std::size_t>(i)] > 0.0)
      smallest_positive = std::min(smallest_positive, sigma[static_cast<std::size_t>(i)]);
  }
  if (!std::isfinite(smallest_positive)) return distances;
  for (double& s : sigma) s = std::max(s, smallest_positive);
  DistanceMatrix out(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      out(i, j) = static_cast<float>(
          distances(i, j) / std::sqrt(sigma[static_cast<std::size_t>(i)] * sigma[static_cast<std::size_t>(j)]));
  return out;
}

}  // namespace reebkit

#include "reebkit/mesh/heat_kernel.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace reebkit {

int whole_eigenspaces(const ShapeDna& dna, double multiplet_gap) {
  // lambda_k for k = 1 .. N are dna.eigenvalues[k - 1]; k = 0 is the zero one.
  auto count = static_cast<int>(dna.eigenvalues.size());
  double next = dna.next_eigenvalue;
  while (count > 0 && next <= dna.eigenvalues[static_cast<std::size_t>(count - 1)] * (1.0 + multiplet_gap))
    next = dna.eigenvalues[static_cast<std::size_t>(--count)];
  return count + 1;
}

namespace {

/// The area-weighted quantiles at the levels (q + 1/2) / count of
/// `values` (value, area), sorted here, appended to `out`. Value i stands
/// for the area around its midpoint (the area below it plus half its own);
/// a quantile is interpolated linearly between the two values whose
/// midpoints enclose its level.
void append_weighted_quantiles(std::vector<std::pair<double, double>>& values, int count, std::vector<double>& out) {
  std::sort(values.begin(), values.end());
  double total = 0.0;
  for (const auto& [value, area] : values) total += area;
  double below = 0.0, previous_mid = 0.0;
  std::size_t i = 0;
  for (int q = 0; q < count; ++q) {
    const double level = (q + 0.5) / count * total;
    while (i < values.size() && below + values[i].second / 2 < level) {
      previous_mid = below + values[i].second / 2;
      below += values[i].second;
      ++i;
    }
    if (i == 0) {
      out.push_back(values.front().first);
    } else if (i == values.size()) {
      out.push_back(values.back().first);
    } else {
      const double mid = below + values[i].second / 2;
      const double a = mid > previous_mid ? (level - previous_mid) / (mid - previous_mid) : 1.0;
      out.push_back(values[i - 1].first + a * (values[i].first - values[i - 1].first));
    }
  }
}

}  // namespace

std::vector<double> heat_kernel_quantiles(const ShapeDna& dna, const HeatKernelOptions& options) {
  if (dna.eigenvectors.cols() != static_cast<Eigen::Index>(dna.eigenvalues.size()) + 1 ||
      dna.vertex_area.size() != dna.eigenvectors.rows())
    throw InvalidArgument("heat_kernel_quantiles: a Shape-DNA without its eigenvectors");
  if (options.quantiles < 1 || options.times.empty() ||
      !std::all_of(options.times.begin(), options.times.end(), [](double t) { return t > 0; }))
    throw InvalidArgument("heat_kernel_quantiles: the times must be positive and the quantiles >= 1");
  const Eigen::Index pairs = whole_eigenspaces(dna, options.multiplet_gap);
  const Eigen::Index n = dna.eigenvectors.rows();
  const Eigen::MatrixXd squared = dna.eigenvectors.leftCols(pairs).array().square();
  std::vector<double> out;
  std::vector<std::pair<double, double>> values(static_cast<std::size_t>(n));  // (ln HKS / Z, area)
  for (const double t : options.times) {
    Eigen::VectorXd decay(pairs);
    decay(0) = 1.0;  // lambda_0 = 0: the constant
    for (Eigen::Index k = 1; k < pairs; ++k) decay(k) = std::exp(-dna.eigenvalues[static_cast<std::size_t>(k - 1)] * t);
    const Eigen::VectorXd hks = squared * decay;
    const double z = decay.sum();
    for (Eigen::Index v = 0; v < n; ++v)
      values[static_cast<std::size_t>(v)] = {std::log(std::max(hks(v), 1e-300) / z), dna.vertex_area(v)};
    append_weighted_quantiles(values, options.quantiles, out);
  }
  return out;
}

}  // namespace reebkit

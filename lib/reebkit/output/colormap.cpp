#include "reebkit/output/colormap.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace reebkit {

Vec3 viridis(double t) {
  // Nine samples of matplotlib's viridis, linearly interpolated.
  static const std::array<std::array<double, 3>, 9> stops = {{{0.267, 0.005, 0.329},
                                                              {0.283, 0.141, 0.458},
                                                              {0.254, 0.265, 0.530},
                                                              {0.207, 0.372, 0.553},
                                                              {0.164, 0.471, 0.558},
                                                              {0.128, 0.567, 0.551},
                                                              {0.135, 0.659, 0.518},
                                                              {0.267, 0.749, 0.441},
                                                              {0.993, 0.906, 0.144}}};
  const double x = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (stops.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(x), stops.size() - 2);
  const double w = x - static_cast<double>(i);
  Vec3 c;
  for (int k = 0; k < 3; ++k) c[k] = (1 - w) * stops[i][k] + w * stops[i + 1][k];
  return c;
}

Vec3 category_color(int k) {
  // matplotlib's tab20, reordered so that neighbours in id differ strongly.
  static const std::array<std::array<double, 3>, 20> palette = {
      {{0.122, 0.467, 0.706}, {1.000, 0.498, 0.055}, {0.173, 0.627, 0.173}, {0.839, 0.153, 0.157},
       {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294}, {0.890, 0.467, 0.761}, {0.498, 0.498, 0.498},
       {0.737, 0.741, 0.133}, {0.090, 0.745, 0.812}, {0.682, 0.780, 0.910}, {1.000, 0.733, 0.471},
       {0.596, 0.875, 0.541}, {1.000, 0.596, 0.588}, {0.773, 0.690, 0.835}, {0.769, 0.612, 0.580},
       {0.969, 0.714, 0.824}, {0.780, 0.780, 0.780}, {0.859, 0.859, 0.553}, {0.620, 0.855, 0.898}}};
  const auto& c = palette[static_cast<std::size_t>(((k % 20) + 20) % 20)];
  return Vec3(c[0], c[1], c[2]);
}

Points colorize(const std::vector<double>& values, double lo, double hi) {
  Points colors(static_cast<Eigen::Index>(values.size()), 3);
  const double span = hi > lo ? hi - lo : 1.0;
  for (std::size_t i = 0; i < values.size(); ++i)
    colors.row(static_cast<Eigen::Index>(i)) = viridis((values[i] - lo) / span).transpose();
  return colors;
}

}  // namespace reebkit

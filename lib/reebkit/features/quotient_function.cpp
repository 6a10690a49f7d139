#include "reebkit/features/quotient_function.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace reebkit {

namespace {

// Eq. (7) from the distance to the nearest feature point (+inf where the
// graph did not reach: not connected).
QuotientFunction from_distances(std::vector<double> distance, std::vector<Index> nearest, double pass_share) {
  QuotientFunction out;
  for (const double x : distance) {
    if (x == std::numeric_limits<double>::infinity())
      throw InvalidArgument("quotient_function: the mesh graph is not connected");
    out.normalization = std::max(out.normalization, x);
  }
  const double scale = out.normalization > 0.0 ? 1.0 / out.normalization : 0.0;
  out.value = std::move(distance);
  // eq. (7), rounded to a multiple of 2^-24 (6e-8): a rotated or rescaled
  // copy of the mesh has distances that differ in the last bits (1e-16), and
  // unrounded they could reorder two nearly equal vertices and so move a
  // vertex to another region. Rounded, they tie, and ties go by vertex id.
  constexpr double kGrid = 16777216.0;  // 2^24
  for (double& x : out.value) x = std::round((1.0 - x * scale) * kGrid) / kGrid;
  out.nearest_feature = std::move(nearest);
  out.pass_share = pass_share;
  return out;
}

}  // namespace

QuotientFunction quotient_function(const MeshGraph& graph, const std::vector<Index>& features, Geodesic method) {
  return quotient_function(*make_geodesic_solver(graph, method), features);
}

QuotientFunction quotient_function(GeodesicSolver& solver, const std::vector<Index>& features) {
  if (features.empty()) throw InvalidArgument("quotient_function: no feature points");
  GeodesicOptions points;
  points.separate_sources = true;
  solver.run(features, points);
  DistanceField d = solver.release();
  return from_distances(std::move(d.distance), std::move(d.nearest_source), 1.0);
}

QuotientFunction quotient_function(GeodesicSolver& solver, const FeaturePoints& features) {
  const std::vector<Index>& points = features.vertices;
  if (points.empty()) throw InvalidArgument("quotient_function: no feature points");
  const auto n = static_cast<std::size_t>(solver.graph().num_vertices());
  if (features.f1.size() != n || features.f2.size() != n)
    throw InvalidArgument("quotient_function: the feature points' distance fields hold " +
                          std::to_string(features.f1.size()) + " and " + std::to_string(features.f2.size()) +
                          " values for a graph of " + std::to_string(n) + " vertices");
  if (features.geodesic != solver.method())
    throw InvalidArgument(std::string("quotient_function: the feature points' fields are ") +
                          geodesic_name(features.geodesic) + " distances, the solver runs " +
                          geodesic_name(solver.method()));
  // The ends' fields, in the order of the list (a tie goes to the earlier
  // point), then one pass from the other points where they are nearer.
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<Index> nearest(n, kInvalidIndex);
  std::vector<Index> others, other_index;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::vector<double>* field = points[i] == features.source1   ? &features.f1
                                       : points[i] == features.source2 ? &features.f2
                                                                       : nullptr;
    if (field == nullptr) {
      others.push_back(points[i]);
      other_index.push_back(static_cast<Index>(i));
      continue;
    }
    for (std::size_t v = 0; v < n; ++v)
      if ((*field)[v] < distance[v]) {
        distance[v] = (*field)[v];
        nearest[v] = static_cast<Index>(i);
      }
  }
  double share = 0.0;
  if (!others.empty()) {
    GeodesicOptions cells;
    cells.separate_sources = true;
    cells.bound = &distance;
    const DistanceField& d = solver.run(others, cells);
    for (const Index v : solver.settled()) {
      const auto k = static_cast<std::size_t>(v);
      distance[k] = d.distance[k];
      nearest[k] = other_index[static_cast<std::size_t>(d.nearest_source[k])];
    }
    share = static_cast<double>(solver.settled().size()) / static_cast<double>(n);
  }
  return from_distances(std::move(distance), std::move(nearest), share);
}

}  // namespace reebkit

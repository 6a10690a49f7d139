#include "reebkit/features/quotient_function.h"

#include "reebkit/core/error.h"

#include <cmath>

namespace reebkit {

QuotientFunction quotient_function(const MeshGraph& graph, const std::vector<Index>& features, Geodesic method) {
  return quotient_function(*make_geodesic_solver(graph, method), features);
}

QuotientFunction quotient_function(GeodesicSolver& solver, const std::vector<Index>& features) {
  if (features.empty()) throw InvalidArgument("quotient_function: no feature points");
  GeodesicOptions points;
  points.separate_sources = true;
  solver.run(features, points);
  DistanceField d = solver.release();
  if (d.reached != solver.graph().num_vertices())
    throw InvalidArgument("quotient_function: the mesh graph is not connected");
  QuotientFunction out;
  out.normalization = d.max_distance;
  const double scale = d.max_distance > 0.0 ? 1.0 / d.max_distance : 0.0;
  out.value = std::move(d.distance);
  // eq. (7), rounded to a multiple of 2^-24 (6e-8): a rotated or rescaled
  // copy of the mesh has distances that differ in the last bits (1e-16), and
  // unrounded they could reorder two nearly equal vertices and so move a
  // vertex to another region. Rounded, they tie, and ties go by vertex id.
  constexpr double kGrid = 16777216.0;  // 2^24
  for (double& x : out.value) x = std::round((1.0 - x * scale) * kGrid) / kGrid;
  out.nearest_feature = std::move(d.nearest_source);
  return out;
}

}  // namespace reebkit

#include "reebkit/features/quotient_function.h"

#include "reebkit/core/error.h"
#include "reebkit/geodesic/dijkstra.h"

namespace reebkit {

QuotientFunction quotient_function(const MeshGraph& graph, const std::vector<Index>& features) {
  if (features.empty()) throw InvalidArgument("quotient_function: no feature points");
  DistanceField d = dijkstra(graph, features);
  if (d.reached != graph.num_vertices())
    throw InvalidArgument("quotient_function: the mesh graph is not connected");
  QuotientFunction out;
  out.normalization = d.max_distance;
  const double scale = d.max_distance > 0.0 ? 1.0 / d.max_distance : 0.0;
  out.value = std::move(d.distance);
  for (double& x : out.value) x = 1.0 - x * scale;  // eq. (7)
  out.nearest_feature = std::move(d.nearest_source);
  return out;
}

}  // namespace reebkit

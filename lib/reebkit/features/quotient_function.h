// The invariant quotient function f_q (Tierny et al. 2006, section 4.1.3,
// eqs. 7-8): one minus the normalized geodesic distance to the nearest
// feature point, computed in one multi-source geodesic pass.
#pragma once

#include "reebkit/geodesic/geodesic_solver.h"
#include "reebkit/mesh/mesh_graph.h"

#include <vector>

namespace reebkit {

struct QuotientFunction {
  /// f_q(v) = 1 - d(v, v_c) / normalization, in [0, 1]; 1 on feature points.
  /// Rounded to a multiple of 2^-24, so that the last-bit noise of a rotated
  /// or rescaled mesh cannot reorder vertices (equal values order by id).
  std::vector<double> value;
  /// eq. (8): v_c, as an index into the feature point list.
  std::vector<Index> nearest_feature;
  /// max_v d(v, F): the normalization of the hatted delta of eq. (7), chosen
  /// so that f_q spans [0, 1] exactly (its global minimum is 0) whatever the
  /// scale of the mesh.
  double normalization = 0.0;
};

/// f_q for the given feature points (vertex ids), with geodesic distances
/// computed by `method` (that of FeatureOptions::geodesic, for consistency).
/// \pre the graph is connected and `features` is non-empty.
QuotientFunction quotient_function(const MeshGraph& graph, const std::vector<Index>& features,
                                   Geodesic method = Geodesic::FastMarching);

/// The same with a solver the caller already has (that of the feature
/// points, analyze_mesh), on the graph of the mesh.
QuotientFunction quotient_function(GeodesicSolver& solver, const std::vector<Index>& features);

}  // namespace reebkit

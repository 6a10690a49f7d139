// The invariant quotient function f_q (Tierny et al. 2006, section 4.1.3,
// eqs. 7-8): one minus the normalized geodesic distance to the nearest
// feature point, computed in one multi-source geodesic pass; after the
// feature step, the distances from the diameter ends are those it computed
// (FeaturePoints::f1, f2), and the pass covers only the rest.
#pragma once

#include "reebkit/features/feature_points.h"
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
  /// The vertices the geodesic pass settled, as a share of #V: 1 for a pass
  /// from every feature point; less where the diameter ends' fields were
  /// reused (only the other feature points' Voronoi cells are measured), 0
  /// where the ends are the only feature points.
  double pass_share = 0.0;
};

/// f_q for the given feature points (vertex ids), with geodesic distances
/// computed by `method` (that of FeatureOptions::geodesic, for consistency).
/// \pre the graph is connected and `features` is non-empty.
QuotientFunction quotient_function(const MeshGraph& graph, const std::vector<Index>& features,
                                   Geodesic method = Geodesic::FastMarching);

/// The same with a solver the caller already has, on the graph of the mesh.
QuotientFunction quotient_function(GeodesicSolver& solver, const std::vector<Index>& features);

/// f_q of the feature points of extract_feature_points, with the solver of
/// that step (its method): the diameter ends that are feature points (v_s1,
/// v_s2: a mutually farthest pair always is) keep the distance fields the
/// step computed (FeaturePoints::f1, f2), and one pass from the other
/// feature points, bounded by those fields (GeodesicOptions::bound), covers
/// only their Voronoi cells. The result is eq. (8) as the multi-source pass
/// gives it, but where two cells meet: there each field is the end's own
/// single-source fast marching, whose triangles may straddle the border.
/// Throws InvalidArgument for fields of another vertex count or method.
QuotientFunction quotient_function(GeodesicSolver& solver, const FeaturePoints& features);

}  // namespace reebkit

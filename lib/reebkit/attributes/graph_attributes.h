// Geometric attributes of a high-level Reeb graph, for matching graphs of
// different meshes (issue 4). Every attribute is invariant to rotation,
// translation and uniform scale (lengths are relative to sqrt(mesh area) or
// to the geodesic diameter, areas to the mesh area), and chosen to be as
// stable as possible under pose (geodesic rather than Euclidean quantities)
// and sampling (area rather than vertex counts where both exist).
#pragma once

#include "reebkit/pipeline/analyze_mesh.h"

#include <array>
#include <vector>

namespace reebkit {

/// Columns of GraphAttributes::node, in order (README: attribute table).
enum NodeAttribute : int {
  kNodeRelativeArea,      ///< region area / mesh area
  kNodeFqMin,             ///< smallest f_q over the region
  kNodeFqMax,             ///< largest f_q over the region
  kNodeFqSpan,            ///< fq_max - fq_min
  kNodeGeodesicExtent,    ///< geodesic extent of the region / geodesic diameter of the mesh
  kNodeMeanRadius,        ///< mean over its level lines of length / (2 pi), / sqrt(mesh area)
  kNodeVertexShare,       ///< region vertices / mesh vertices
  kNodeDegree,            ///< number of graph edges at the node
  kNodeStartType,         ///< NodeType the region starts with, as a number
  kNodeEndType,           ///< NodeType the region ends with, as a number
  /// Thickness profile: the level-line radius (length / (2 pi) / sqrt(mesh
  /// area)) at each of the kRadiusProfileLevels levels mean_radius averages,
  /// from fq_min to fq_max.
  kNodeRadiusProfile,
  /// Shape of the region: a histogram (kShapeBins bins, sums to 1) of the
  /// Euclidean distance between random points of the region, / sqrt(region
  /// area) (the D2 distribution of Osada et al. 2002, restricted to a part).
  kNodeShapeHistogram = kNodeRadiusProfile + 8,
  kNodeAttributeCount = kNodeShapeHistogram + 8
};

/// Levels of kNodeRadiusProfile and bins of kNodeShapeHistogram.
inline constexpr int kRadiusProfileLevels = kNodeShapeHistogram - kNodeRadiusProfile;
inline constexpr int kShapeBins = kNodeAttributeCount - kNodeShapeHistogram;

/// Columns of GraphAttributes::edge, in order.
enum EdgeAttribute : int {
  kEdgeBoundaryLength,  ///< length of the level line where the two regions meet / sqrt(mesh area)
  kEdgeEventFq,         ///< f_q at the event joining the two regions
  kEdgeAttributeCount
};

/// Column names, for file headers and documentation (snake_case).
extern const std::array<const char*, kNodeAttributeCount> kNodeAttributeNames;
extern const std::array<const char*, kEdgeAttributeCount> kEdgeAttributeNames;

/// Length of the per-graph signature vector used for nearest-neighbour
/// pre-filtering (FLANN): fixed whatever the graph.
inline constexpr int kSignatureLength = 48;
/// The last kGlobalShapeBins entries of the signature: the D2 shape
/// distribution of the whole surface (distances between random points /
/// sqrt(mesh area), bins of 0.15, summing to 1), compared by the matcher.
inline constexpr int kGlobalShapeBins = 16;
inline constexpr int kSigGlobalShape = kSignatureLength - kGlobalShapeBins;
/// Name of each signature entry.
extern const std::array<const char*, kSignatureLength> kSignatureNames;

struct GraphAttributes {
  std::vector<double> node;       ///< #nodes x kNodeAttributeCount, row-major, node order of ReebGraph::nodes
  std::vector<double> edge;       ///< #edges x kEdgeAttributeCount, row-major, edge order of ReebGraph::edges
  std::vector<double> signature;  ///< kSignatureLength entries
};

/// The attributes of `analysis.reeb` on `analysis.mesh` (the surface as read:
/// vertices added by hole filling do not count towards areas and shares).
/// \pre analysis.reeb has been built (AnalysisOptions::reeb_graph).
GraphAttributes compute_attributes(const MeshAnalysis& analysis);

}  // namespace reebkit

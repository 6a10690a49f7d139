// The attributed graph record: one mesh's high-level Reeb graph with its
// geometric attributes, in flat arrays (node and edge tables, CSR skeleton,
// fixed-length signature), plus the mesh's name, class, content hash and
// status. It is the one type the later stages exchange: the store writes and
// reads it, the matcher compares two of them, retrieval and output read it.
// This header depends on nothing else of reebkit, so those stages see flat
// arrays only, never the pipeline that made them.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace reebkit {

/// Columns of the node attributes (GraphRecord::node_attributes), in order (docs/method.md, "Graph attributes").
enum NodeAttribute : int {
  kNodeRelativeArea,    ///< region area / mesh area
  kNodeFqMin,           ///< smallest f_q over the region
  kNodeFqMax,           ///< largest f_q over the region
  kNodeFqSpan,          ///< fq_max - fq_min
  kNodeGeodesicExtent,  ///< geodesic extent of the region / geodesic diameter of the mesh
  kNodeMeanRadius,      ///< mean over its level lines of length / (2 pi), / sqrt(mesh area)
  kNodeVertexShare,     ///< region vertices / mesh vertices
  kNodeDegree,          ///< number of graph edges at the node
  kNodeStartType,       ///< NodeType the region starts with, as a number
  kNodeEndType,         ///< NodeType the region ends with, as a number
  /// Thickness profile: the level-line radius (length / (2 pi) / sqrt(mesh
  /// area)) at each of the kRadiusProfileLevels levels mean_radius averages,
  /// from fq_min to fq_max.
  kNodeRadiusProfile,
  /// Shape of the region: a histogram (kShapeBins bins, sums to 1) of the
  /// Euclidean distance between random points of the region, / sqrt(region
  /// area) (the D2 distribution of Osada et al. 2002, restricted to a part).
  /// Changes when the part bends.
  kNodeShapeHistogram = kNodeRadiusProfile + 8,
  /// Intrinsic shape of the region: a histogram (kShapeBins bins, sums to 1)
  /// of the area of the region by geodesic distance (paths inside the
  /// region) from its highest vertex, / sqrt(region area). Invariant to
  /// bending.
  kNodeGeodesicHistogram = kNodeShapeHistogram + 8,
  /// Laplace-Beltrami spectrum of the region (attributes/region_spectra.h):
  /// its first kRegionSpectrumLength Neumann eigenvalues lambda_k, each as
  /// s / (1 + s) with s = lambda_k x region area / (4 pi k). Invariant to
  /// bending; changes with the part's proportions.
  kNodeSpectrum = kNodeGeodesicHistogram + 8,
  kNodeAttributeCount = kNodeSpectrum + 6
};

/// Levels of kNodeRadiusProfile and bins of kNodeShapeHistogram and kNodeGeodesicHistogram.
inline constexpr int kRadiusProfileLevels = kNodeShapeHistogram - kNodeRadiusProfile;
inline constexpr int kShapeBins = kNodeGeodesicHistogram - kNodeShapeHistogram;
static_assert(kNodeSpectrum - kNodeGeodesicHistogram == kShapeBins, "both region histograms have kShapeBins bins");
/// Eigenvalues of kNodeSpectrum.
inline constexpr int kRegionSpectrumLength = kNodeAttributeCount - kNodeSpectrum;

/// Columns of the edge attributes (GraphRecord::edge_attributes), in order.
enum EdgeAttribute : int {
  kEdgeBoundaryLength,  ///< length of the level line where the two regions meet / sqrt(mesh area)
  kEdgeEventFq,         ///< f_q at the event joining the two regions
  kEdgeAttributeCount
};

/// Column names, for file headers and documentation (snake_case).
extern const std::array<const char*, kNodeAttributeCount> kNodeAttributeNames;
extern const std::array<const char*, kEdgeAttributeCount> kEdgeAttributeNames;

/// kGlobalShapeBins entries of the signature from kSigGlobalShape: the D2
/// shape distribution of the whole surface (Euclidean distances between
/// random points / sqrt(mesh area), bins of 0.15, summing to 1), compared by
/// the matcher. Changes when a part moves.
inline constexpr int kGlobalShapeBins = 16;
inline constexpr int kSigGlobalShape = 32;
/// The next kGlobalShapeBins entries: the intrinsic counterpart, the area of
/// the surface by its place relative to the main axis, the geodesic path
/// between the diameter ends v_s1, v_s2 (section 4.1.2), with d1, d2 the
/// geodesic distances to them and D = d(v_s1, v_s2): along the axis, the
/// axis position |d1 - d2| / D (0 midway, 1 at an end; 8 bins of 1/8,
/// summing to 1/2), and off it, the axis offset (d1 + d2 - D) / D (0 on the
/// axis; 8 bins of 1/16, summing to 1/2). Invariant to bending, and to
/// exchanging the two ends.
inline constexpr int kSigGlobalGeodesic = kSigGlobalShape + kGlobalShapeBins;
/// The last kGlobalSpectrumLength entries: the Laplace-Beltrami spectrum of
/// the whole surface (its Shape-DNA, attributes/region_spectra.h), lambda_1
/// .. lambda_16 each as s / (1 + s) with s = lambda_k x area / (4 pi k).
/// Invariant to bending.
inline constexpr int kGlobalSpectrumLength = 16;
inline constexpr int kSigGlobalSpectrum = kSigGlobalGeodesic + kGlobalShapeBins;
/// The last kGlobalHeatLength entries: the distribution of the heat kernel
/// signature over the whole surface (mesh/heat_kernel.h), HKS(x, t) / Z(t)
/// at each of kGlobalHeatTimes times (0.01, 0.03, 0.1, 0.3 x area), given by
/// kGlobalHeatQuantiles area-weighted quantiles, each quantile r as
/// r / (1 + r). Invariant to bending.
inline constexpr int kGlobalHeatTimes = 4;
inline constexpr int kGlobalHeatQuantiles = 8;
inline constexpr int kGlobalHeatLength = kGlobalHeatTimes * kGlobalHeatQuantiles;
inline constexpr int kSigGlobalHeat = kSigGlobalSpectrum + kGlobalSpectrumLength;
/// Length of the per-graph signature vector used for nearest-neighbour
/// pre-filtering (FLANN): fixed whatever the graph, every entry in [0, 1].
inline constexpr int kSignatureLength = kSigGlobalHeat + kGlobalHeatLength;
/// Name of each signature entry.
extern const std::array<const char*, kSignatureLength> kSignatureNames;

/// Integer columns of the `nodes` dataset.
enum NodeColumn : int { kNodeType, kNodeEnd, kNodeBirthVertex, kNodeVertexCount, kNodeColumnCount };
/// Columns of the `node_geometry` dataset (absolute, not invariant).
enum NodeGeometryColumn : int {
  kGeomArea,
  kGeomFqMin,
  kGeomFqMax,
  kGeomBarycenterX,
  kGeomBarycenterY,
  kGeomBarycenterZ,
  kGeomColumnCount
};
/// Columns of the `timings` dataset (milliseconds).
enum TimingColumn : int {
  kTimeLoad,
  kTimeGraph,
  kTimeFeatures,
  kTimeQuotient,
  kTimeReeb,
  kTimeAttributes,
  kTimeColumnCount
};

/// One mesh and its attributed Reeb graph: what the extractor produces, the
/// collection file stores, the matcher compares and the graph JSON shows.
struct GraphRecord {
  std::string name;                ///< the mesh as named on input (path relative to the input folder, or as given)
  std::string class_label;         ///< from the .cla file, "" when none
  std::uint64_t content_hash = 0;  ///< hash of the file's bytes (content_hash.h): what --resume compares
  std::int64_t vertices = 0;       ///< of the surface as read (hole filling excluded); 0 when failed
  std::int64_t faces = 0;
  bool ok = false;  ///< false: `error` says why; the graph arrays are empty
  std::string error;
  std::array<double, kTimeColumnCount> timings{};  ///< ms per TimingColumn

  // The graph (node ids local to this graph, vertex ids in the file's numbering).
  std::vector<std::int32_t> nodes;            ///< #nodes x kNodeColumnCount
  std::vector<double> node_geometry;          ///< #nodes x kGeomColumnCount
  std::vector<double> node_attributes;        ///< #nodes x kNodeAttributeCount
  std::vector<std::int32_t> edges;            ///< #edges x 2
  std::vector<double> edge_attributes;        ///< #edges x kEdgeAttributeCount
  std::vector<std::int32_t> feature_points;   ///< vertex ids (-1: a vertex added to close a hole)
  std::vector<std::int64_t> skeleton_offset;  ///< #nodes + 1, into skeleton_points rows
  std::vector<double> skeleton_points;        ///< #points x 3
  std::vector<double> signature;              ///< kSignatureLength (NaN when failed)

  std::int32_t num_nodes() const { return static_cast<std::int32_t>(nodes.size() / kNodeColumnCount); }
  std::int32_t num_edges() const { return static_cast<std::int32_t>(edges.size() / 2); }
};

/// First Betti number of a record's graph: #edges - #nodes + #connected components.
std::int64_t independent_cycles(const GraphRecord& record);
/// Nodes whose region ends in a termination (leaves).
std::int64_t leaf_count(const GraphRecord& record);

}  // namespace reebkit

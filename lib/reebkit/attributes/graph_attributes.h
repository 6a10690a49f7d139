// Geometric attributes of a high-level Reeb graph, for matching graphs of
// different meshes. Every attribute is invariant to rotation,
// translation and uniform scale (lengths are relative to sqrt(mesh area) or
// to the geodesic diameter, areas to the mesh area), and chosen to be as
// stable as possible under pose (geodesic rather than Euclidean quantities)
// and sampling (area rather than vertex counts where both exist).
#pragma once

#include "reebkit/attributes/graph_record.h"
#include "reebkit/attributes/region_spectra.h"
#include "reebkit/core/mesh.h"
#include "reebkit/features/feature_points.h"
#include "reebkit/geodesic/geodesic_solver.h"
#include "reebkit/mesh/mesh_graph.h"
#include "reebkit/reeb/reeb_graph.h"

#include <array>
#include <vector>

namespace reebkit {

struct GraphAttributes {
  std::vector<double> node;       ///< #nodes x kNodeAttributeCount, row-major, node order of ReebGraph::nodes
  std::vector<double> edge;       ///< #edges x kEdgeAttributeCount, row-major, edge order of ReebGraph::edges
  std::vector<double> signature;  ///< kSignatureLength entries
};

/// What one pass over the triangles gathers (graph_attributes.cpp's file comment).
struct TriangleSums {
  std::vector<double> vertex_area;    ///< a third of the area of each triangle of the surface as read at its vertices
  std::vector<double> node_area;      ///< per node, over the surface as read
  double total_area = 0.0;            ///< of the surface as read
  std::vector<double> level_length;   ///< isocontour lengths, #nodes x kLevels, row-major
  std::vector<double> border_length;  ///< per graph edge
};

/// What the searches inside the regions give (graph_attributes.cpp's file comment).
struct RegionGeodesics {
  std::vector<double> extent;     ///< per node, unnormalized
  std::vector<double> histogram;  ///< kNodeGeodesicHistogram, #nodes x kShapeBins, row-major
};

/// Everything compute_attributes measures on the surface but the spectra:
/// the sums over the triangles, the searches inside the regions and the
/// shape distributions.
struct RegionMeasures {
  TriangleSums sums;
  RegionGeodesics geodesics;
  std::vector<double> shape;         ///< kNodeShapeHistogram, #nodes x kShapeBins, row-major
  std::vector<double> global_shape;  ///< kGlobalShapeBins: the D2 of the whole surface
};

/// The RegionMeasures of `reeb` on `mesh`, for compute_attributes to take
/// prepared (analyze_mesh measures them on the graph's thread while the
/// spectra's surface is built on the other). `solver`, when given, runs the
/// searches inside the regions (a solver on `graph` of the feature points'
/// method, such as the one that found them: its construction is saved);
/// otherwise one is made. Same preconditions as compute_attributes;
/// throws InvalidArgument for a solver of another graph or method.
RegionMeasures measure_regions(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& fq,
                               const FeaturePoints& features, const ReebGraph& reeb, GeodesicSolver* solver = nullptr);

/// The attributes of `reeb`, the high-level Reeb graph of f_q on `mesh` (its
/// graph `graph`), with the columns of graph_record.h. Areas and shares count
/// the surface as read (vertices added by hole filling, see
/// original_vertex_count, are left out); geodesic extents are divided by
/// the geodesic diameter of the feature point search (`features`: its
/// FeaturePoints::diameter, section 4.1.2; its diameter ends v_s1, v_s2 give
/// the main axis).
/// `spectra`, when given, is spectra_surface(mesh, spectra_options)
/// (region_spectra.h), prepared beforehand; otherwise it is prepared here.
/// `measures`, when given, is measure_regions of the same arguments;
/// otherwise they are measured here, beside the spectra.
/// \pre reeb has nodes, and mesh, graph, fq and reeb.vertex_node agree in
///      vertex count; throws InvalidArgument otherwise.
GraphAttributes compute_attributes(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& fq,
                                   const FeaturePoints& features, const ReebGraph& reeb,
                                   const SpectraSurface* spectra = nullptr, const SpectraOptions& spectra_options = {},
                                   const RegionMeasures* measures = nullptr);

}  // namespace reebkit

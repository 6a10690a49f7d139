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

/// The attributes of `reeb`, the high-level Reeb graph of f_q on `mesh` (its
/// graph `graph`), with the columns of graph_record.h. Areas and shares count
/// the surface as read (vertices added by hole filling, see
/// original_vertex_count, are left out); geodesic extents are divided by
/// the geodesic diameter of the feature point search (`features`: its
/// FeaturePoints::diameter, section 4.1.2; its diameter ends v_s1, v_s2 give
/// the main axis).
/// `spectra`, when given, is spectra_surface(mesh, spectra_options)
/// (region_spectra.h), prepared beforehand; otherwise it is prepared here.
/// \pre reeb has nodes, and mesh, graph, fq and reeb.vertex_node agree in
///      vertex count; throws InvalidArgument otherwise.
GraphAttributes compute_attributes(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& fq,
                                   const FeaturePoints& features, const ReebGraph& reeb,
                                   const SpectraSurface* spectra = nullptr, const SpectraOptions& spectra_options = {});

}  // namespace reebkit

// The per-mesh pipeline of reebkit in one call: mesh graph -> feature points
// -> quotient function f_q -> high-level Reeb graph, with the time of each
// step; then its attributes.
// Tools and experiments compose this; each step stays callable on its own.
#pragma once

#include "reebkit/attributes/graph_attributes.h"
#include "reebkit/features/feature_points.h"
#include "reebkit/features/quotient_function.h"
#include "reebkit/mesh/hole_filling.h"
#include "reebkit/mesh/mesh_graph.h"
#include "reebkit/reeb/reeb_graph.h"

namespace reebkit {

struct AnalysisOptions {
  /// Small holes are closed first (fill_holes), so that they add no nodes to
  /// the Reeb graph; max_loop_length = 0 keeps the mesh as it is.
  HoleFillingOptions holes;
  FeatureOptions features;  ///< feature point extraction (epsilon, start vertex, ...)
  ReebOptions reeb;         ///< Reeb graph construction
  bool reeb_graph = true;   ///< false: stop after f_q (no Reeb graph)
  /// With a Reeb graph, also prepare what compute_attributes takes from the
  /// surface: the surface the attributes' spectra are computed on and its
  /// spectrum (MeshAnalysis::spectra), beside the graph on a second thread
  /// where one is free, and the region measures (MeshAnalysis::measures)
  /// after the graph on its own thread. false: the analysis is the graph
  /// alone, and compute_attributes prepares both.
  bool prepare_attributes = true;
  /// The attributes' spectra (region_spectra.h): whether the regions get
  /// theirs, and the copies they are computed on.
  SpectraOptions spectra;
};

/// Wall-clock milliseconds of each step (file reading excluded).
struct AnalysisTimings {
  double graph = 0;     ///< fill_holes + build_mesh_graph
  double features = 0;  ///< extract_feature_points
  double quotient = 0;  ///< quotient_function
  double reeb = 0;      ///< build_reeb_graph (0 when not built)
  /// spectra_surface (region_spectra.h: the surface of the attributes'
  /// spectra and the whole surface's spectrum): run alongside
  /// features .. Reeb graph where a second thread is free, so not in total().
  double spectra_surface = 0;
  /// measure_regions (graph_attributes.h), after the Reeb graph: attributes'
  /// work, so not in total() either.
  double measures = 0;
  double total() const { return graph + features + quotient + reeb; }
};

/// Everything computed for one mesh.
struct MeshAnalysis {
  Mesh mesh;  ///< the input with its small holes filled (new vertices last, see fill_holes)
  MeshGraph graph;
  FeaturePoints features;
  QuotientFunction fq;
  ReebGraph reeb;  ///< empty when options.reeb_graph is false
  /// The whole surface's spectrum and, with the regions' spectra, the
  /// surface they are cut from (spectra_surface, region_spectra.h); empty
  /// unless options.reeb_graph and options.prepare_attributes.
  SpectraSurface spectra;
  /// The attributes' measures of the surface but the spectra
  /// (measure_regions); empty under the same conditions.
  RegionMeasures measures;
  SpectraOptions spectra_options;  ///< AnalysisOptions::spectra, for compute_attributes
  AnalysisTimings timings;
};

/// Runs the pipeline on a cleaned, connected mesh (see load_mesh). With a
/// Reeb graph (and options.prepare_attributes), the surface of the
/// attributes' spectra and its spectrum are prepared on a second OpenMP
/// thread while the feature points, f_q, the graph and then the region
/// measures are computed (on one thread inside a parallel region, e.g. reeb
/// index's workers). Throws InvalidArgument when the mesh graph is
/// not connected.
MeshAnalysis analyze_mesh(Mesh mesh, const AnalysisOptions& options = {});

/// The attributes of the analysis's Reeb graph (graph_attributes.h).
/// \pre analysis.reeb has been built (AnalysisOptions::reeb_graph).
GraphAttributes compute_attributes(const MeshAnalysis& analysis);

}  // namespace reebkit

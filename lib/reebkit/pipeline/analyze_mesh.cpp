#include "reebkit/pipeline/analyze_mesh.h"

#include "reebkit/core/parallel.h"
#include "reebkit/core/timer.h"

#include <algorithm>
#include <memory>

namespace reebkit {

MeshAnalysis analyze_mesh(Mesh mesh, const AnalysisOptions& options) {
  MeshAnalysis a;
  a.spectra_options = options.spectra;
  Timer timer;
  a.mesh = std::move(mesh);
  a.graph = build_mesh_graph(a.mesh);
  // Only a mesh with a boundary (a ring that is not a closed cycle) can have
  // holes to fill; the graph already says whether there is one.
  const bool closed =
      std::all_of(a.graph.ring.begin(), a.graph.ring.end(), [](RingKind r) { return r == RingKind::Closed; });
  if (!closed && options.holes.max_loop_length > 0) {
    a.mesh = fill_holes(a.mesh, options.holes);
    a.graph = build_mesh_graph(a.mesh);
  }
  a.timings.graph = timer.lap();
  // The graph (feature points, f_q, Reeb graph, region measures) beside the
  // spectra's surface.
  run_side_by_side(
      [&] {
        // One solver for the feature points, f_q and the region measures.
        const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(a.graph, options.features.geodesic);
        a.features = extract_feature_points(a.mesh, a.graph, options.features, *solver);
        a.timings.features = timer.lap();
        a.fq = quotient_function(*solver, a.features);
        a.timings.quotient = timer.lap();
        if (options.reeb_graph) {
          a.reeb = build_reeb_graph(a.mesh, a.graph, a.fq.value, options.reeb);
          a.timings.reeb = timer.lap();
          if (options.prepare_attributes) {
            a.measures = measure_regions(a.mesh, a.graph, a.fq.value, a.features, a.reeb, solver.get());
            a.timings.measures = timer.lap();
          }
        }
      },
      [&] {
        if (!options.reeb_graph || !options.prepare_attributes) return;
        Timer steps;
        a.spectra = spectra_surface(a.mesh, options.spectra);
        a.timings.spectra_surface = steps.lap();
      });
  return a;
}

GraphAttributes compute_attributes(const MeshAnalysis& analysis) {
  const bool prepared = !analysis.spectra.global.empty();
  const bool measured = !analysis.measures.sums.node_area.empty();
  return compute_attributes(analysis.mesh, analysis.graph, analysis.fq.value, analysis.features, analysis.reeb,
                            prepared ? &analysis.spectra : nullptr, analysis.spectra_options,
                            measured ? &analysis.measures : nullptr);
}

}  // namespace reebkit

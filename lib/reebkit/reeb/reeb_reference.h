// The paper's own Reeb graph construction (Tierny et al. 2006, section 5.1):
// at every propagation step all discrete level lines (of either definition,
// ReebOptions::level_lines) are rebuilt from scratch and compared with those
// of the previous step. O(n |C|) time, up to O(n^2):
// the oracle the fast build_reeb_graph (reeb_graph.h) is tested against, for
// small meshes only.
#pragma once

#include "reebkit/reeb/reeb_graph.h"

#include <vector>

namespace reebkit {

/// The dual Reeb graph of f by discrete level-line propagation from the
/// global minimum of f (by (value, vertex id)), every level line recomputed
/// at each step t, with its barycenter for the skeleton. Gives
/// exactly the graph of build_reeb_graph (skeleton points up to rounding:
/// the fast builder keeps running sums).
/// \pre mesh, graph and f describe the same non-empty vertex set, f is
///      finite and the graph is connected; throws InvalidArgument otherwise.
///      Of `options` only level_lines and skeleton_levels are used (one
///      component only).
ReebGraph reference_reeb_graph(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                               const ReebOptions& options = {});

}  // namespace reebkit

// Pit cancellation: leaves of the dual Reeb graph only where f peaks.
//
// The propagation absorbs the candidate vertices in (f, vertex id) order
// from the global minimum (reeb_graph.h), so it is not a sweep of f: where
// f_q has shallow local minima (on the ridges where the fronts of two
// feature points meet, eq. 7), the front can pass over a vertex's higher
// neighbours before it reaches the vertex from below, close around it, and
// split off a level line that vanishes when that vertex is absorbed: a
// termination whose region holds no local maximum of f. The paper's
// terminations are the local maxima of f (section 4.2, eq. 11: a leaf per
// feature point); these pits are an artefact of the discrete propagation,
// and how many a mesh has depends on its sampling. Cancelling them keeps
// the graph's cycles (a leaf and the split that made it go together).
#pragma once

#include "reebkit/mesh/mesh_graph.h"
#include "reebkit/reeb/reeb_graph.h"

#include <vector>

namespace reebkit {

/// `graph` with every pit cancelled: a Termination node whose region holds
/// no local maximum of f (sos_less order on `mesh_graph`) and that one edge
/// enters gives its region to the node it came from. When that node's line
/// then feeds one node only, which it alone feeds, the two become one (the
/// split was the pit's): the region, the skeleton and the end of the later
/// one go to the earlier. A node left feeding none ends in a Termination
/// and is checked in turn. Node ids stay in creation order, renumbered.
/// \pre graph was built on mesh_graph's vertices with f (build_reeb_graph).
ReebGraph cancel_pits(ReebGraph graph, const MeshGraph& mesh_graph, const std::vector<double>& f);

}  // namespace reebkit

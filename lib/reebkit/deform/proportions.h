// Body proportions changed the same way in every pose of a shape: a part of
// the shape (a component of the high level Reeb graph, Tierny et al. 2006,
// section 5.2: an arm, a leg, the head, or the core region, the torso) made
// longer or thicker. The change is planned once on a reference pose and then
// applied to any pose that shares the reference's vertex numbering (the
// poses of a TOSCA class): the plan holds vertex lists and per-vertex numbers
// only, never a position, and every position it needs (the pivot, the
// part's skeleton) is taken from the pose it is applied to, so the change
// follows the pose. It makes shapes of one kind with different proportions,
// "people", on which retrieval by body shape can be measured.
#pragma once

#include "reebkit/pipeline/analyze_mesh.h"

#include <vector>

namespace reebkit {

/// Which part of the shape a node stands for.
enum class ProportionPart {
  /// The node and every node downstream of it (Deformation::nodes: a limb
  /// with whatever hangs off it), attached where it leaves its parent
  /// (Deformation::attach_loop) and cut along the geodesic distance from
  /// there. The node must have a parent.
  Component,
  /// The node's region alone (the part of a torso between the limbs), held
  /// where it meets the other regions and cut along f_q: the region is swept
  /// by one level line of f_q (section 4.2), so its levels are its
  /// cross-sections and their barycenters its skeleton (section 5.2).
  Region,
};

struct ProportionOptions {
  /// The part: this node's component or region (see `part`).
  Index node = kInvalidIndex;
  ProportionPart part = ProportionPart::Component;
  /// Similarity factor of the part about its pivot (> 0): 1.1 makes it 10 %
  /// longer and 10 % thicker. 1: no similarity.
  double scale = 1.0;
  /// Factor of the part's cross-sections about its skeleton (> 0): 1.1
  /// makes it 10 % thicker and no longer. scale s with thickness 1 / s makes
  /// it s times longer only. 1: no thickening.
  double thickness = 1.0;
  /// Fraction of the part's extent over which the change ramps up from 0 at
  /// its border (where it meets the rest of the shape) to the full factors,
  /// in [0, 1], as DeformOptions::falloff.
  double falloff = 0.25;
  /// Cross-sections of the part whose barycenters make its skeleton (>= 2).
  int levels = 24;
};

/// What change_proportions does, planned on the reference pose; valid for
/// every mesh with the reference's vertices (same count and numbering).
struct ProportionPlan {
  /// The part's nodes, ascending (options.node first when it has a parent).
  std::vector<Index> nodes;
  /// The vertices whose mean position, in the mesh the plan is applied to,
  /// is the pivot of the similarity: the attach loop of a component (the
  /// birth vertex when it has none, as plan_deformation), every vertex of a
  /// region.
  std::vector<Index> anchor;
  /// #V: how much of the change each vertex gets, in [0, 1]: 0 outside the
  /// part and on its border, smoothstep up to falloff x extent from the
  /// border, 1 beyond (Deformation::weight for a component; for a region,
  /// the same ramp of the geodesic distance from its vertices next to other
  /// regions, all 1 when there are none).
  std::vector<double> weight;
  /// #V: the cross-section each vertex of the part belongs to, in
  /// [0, levels), -1 outside it: equal slices of the part's range of
  /// `position`. Empty levels are dropped, so every level in
  /// [0, level_position.size()) holds vertices.
  std::vector<Index> level;
  /// #V: where each vertex of the part lies along it, 0 outside it: the
  /// geodesic distance from the attach loop for a component, f_q for a
  /// region.
  std::vector<double> position;
  /// Per level: the mean position of its vertices, increasing. A vertex's
  /// skeleton point is the barycenter of the levels' vertices interpolated
  /// linearly between the two levels whose mean positions enclose its own.
  std::vector<double> level_position;
  double scale = 1.0;
  double thickness = 1.0;
};

/// Plans the change of options.node's part on `reference`.
/// \pre reference has its Reeb graph; throws InvalidArgument for a missing
///      graph, an unknown node, the component of a root, a scale or thickness not finite and > 0, a
///      falloff outside [0, 1] or fewer than 2 levels.
ProportionPlan plan_proportions(const MeshAnalysis& reference, const ProportionOptions& options);

/// `mesh` (a pose of the plan's reference) with the part changed: each
/// vertex v of weight w is moved off the part's skeleton (the barycenters of
/// the levels in `mesh`) across the skeleton's direction by (thickness - 1)
/// w times its distance to it, then scaled about the pivot (the anchor's
/// mean in `mesh`) by 1 + (scale - 1) w. Vertices of weight 0, and all of
/// them when both factors are 1, are copied bit for bit.
/// \pre mesh has as many vertices as the plan's weights (else InvalidArgument).
Mesh apply_proportions(const Mesh& mesh, const ProportionPlan& plan);

}  // namespace reebkit

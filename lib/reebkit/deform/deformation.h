// Mesh deformation driven by the high level Reeb graph (Tierny et al. 2006,
// section 5.2, figure 10b): a node references the level lines of its region,
// so every vertex of a whole component (the node and everything downstream of
// it) can be moved with a displacement parameterized by its level, here a
// rotation about the point where the component attaches to the rest of the
// shape, ramped along the component so that the mesh stays connected and
// smooth.
#pragma once

#include "reebkit/pipeline/analyze_mesh.h"

#include <string>
#include <vector>

namespace reebkit {

struct DeformOptions {
  /// The node whose component moves: it and every node downstream of it (see
  /// Deformation::nodes). Must not be a root (a node without a parent: the
  /// region grown from the global minimum of f_q, the core of the shape, has
  /// nothing to pivot on).
  Index node = kInvalidIndex;
  /// Rotation angle, right-handed about `axis`.
  double angle_degrees = 0.0;
  /// Rotation axis (any length but zero). Zero (default): chosen from the
  /// geometry, see Deformation::axis.
  Vec3 axis = Vec3::Zero();
  /// Fraction of the component's extent (the largest geodesic distance from
  /// the attach loop) over which the rotation ramps up from 0 to the full
  /// angle, in [0, 1]. 0: the component turns rigidly, only the edges at
  /// its border (see Deformation::weight) stretch.
  double falloff = 0.25;
};

/// What deform_component does, computed once: apply it to the mesh it was
/// planned on, or to a copy already deformed by other plans of the same
/// analysis (apply the downstream ones first so that each pivot is still in
/// place: "applying recursively simple rotations to components").
struct Deformation {
  /// The component: options.node, then every node all of whose parents are
  /// in the component, ascending. A node that is also fed by another branch
  /// of the graph (the junction closing a cycle) is left out, together with
  /// what only it feeds.
  std::vector<Index> nodes;
  /// Vertices of the component next (in the mesh graph) to a vertex of a
  /// parent region of options.node: where the component attaches, ascending.
  std::vector<Index> attach_loop;
  /// Where the component turns: the node's first skeleton point, the
  /// barycenter of its level line at its birth, i.e. of the loop where it
  /// leaves its parent (the position of its birth vertex, the vertex whose
  /// absorption created the node, for a graph without skeleton).
  Vec3 pivot = Vec3::Zero();
  /// Unit rotation axis. The default is d x w with d = area-weighted
  /// barycenter of the component - pivot and w = barycenter of the root
  /// region - pivot, so positive angles fold the component towards the core
  /// of the shape; when d and w are less than about 6 degrees from parallel,
  /// w = the attach loop vertex with the smallest id - pivot instead. Both
  /// follow any rotation, translation or scaling of the mesh.
  Vec3 axis = Vec3::UnitZ();
  double angle_degrees = 0.0;
  /// Largest geodesic distance (mesh graph) from the attach loop to a
  /// vertex of the component.
  double extent = 0.0;
  /// #V: the fraction of the angle each vertex turns, in [0, 1]. 0 outside
  /// the component; inside, r(d_loop) x r(d_held) where d_loop is the
  /// geodesic distance from the attach loop, d_held the one from the held
  /// vertices (component vertices next to a region outside the component
  /// that is not a parent: where a left-out junction meets it; r = 1 when
  /// there are none), r(d) = smoothstep(d / (falloff extent)) up to
  /// falloff extent and 1 beyond: 0 on the border, so the mesh stays
  /// connected without a crack, 1 inside.
  std::vector<double> weight;
};

/// Throws InvalidArgument, its message starting with `who`, unless
/// `analysis` has its Reeb graph and `node` is one of its nodes: what every
/// plan of a change of a node's part checks first.
void check_graph_node(const MeshAnalysis& analysis, Index node, const std::string& who);

/// Plans the rotation of options.node's component.
/// \pre analysis has its Reeb graph; throws InvalidArgument for a missing
///      graph, an unknown node, a root, a falloff outside [0, 1], a
///      non-finite angle or axis, or no default axis
///      (component without area, or both candidate directions parallel to d).
Deformation plan_deformation(const MeshAnalysis& analysis, const DeformOptions& options);

/// `mesh` with every vertex v turned by weight[v] x angle about the axis
/// through the pivot. Vertices that do not turn (weight or angle 0) are
/// copied bit for bit.
/// \pre mesh has as many vertices as the plan's weights (else InvalidArgument).
Mesh apply_deformation(const Mesh& mesh, const Deformation& deformation);

/// analysis.mesh with options.node's component rotated:
/// apply_deformation(analysis.mesh, plan_deformation(analysis, options)).
Mesh deform_component(const MeshAnalysis& analysis, const DeformOptions& options);

}  // namespace reebkit

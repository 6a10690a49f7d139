// One perturbation of a mesh and the correspondence of its vertices to the
// mesh's, for the robustness experiments (Tierny et al. 2006, section 5.3:
// robustness to pose and to sampling): the steps `reeb perturb` chains and
// experiments/robustness.cpp applies one at a time. Each is a library
// function (mesh/decimation.h, mesh/remeshing.h, mesh/resampling.h,
// mesh/transform.h, deform/pose.h); this picks one by kind.
#pragma once

#include "reebkit/deform/pose.h"
#include "reebkit/mesh/remeshing.h"
#include "reebkit/mesh/surface_correspondence.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace reebkit {

enum class PerturbationKind { Decimate, Remesh, Subdivide, Noise, Pose };

struct Perturbation {
  PerturbationKind kind = PerturbationKind::Noise;
  /// Decimate: the share of the vertices kept, in (0, 1]; Subdivide: rounds
  /// of 1-to-4 midpoint subdivision; Noise: sigma of the Gaussian noise along
  /// the normals, a fraction of the bounding box diagonal; Remesh and Pose:
  /// unused.
  double amount = 0;
  RemeshOptions remesh;    ///< Remesh: the target vertex count or edge length, and the seed
  std::uint64_t seed = 1;  ///< Noise: the seed of the noise; Pose: of the turned leaves (random_pose)
  /// Pose: how many leaves turn and by how much (its own seed unused: `seed` is).
  PoseOptions pose;
};

/// `mesh` perturbed by `p`, original_vertex[v] the vertex of `mesh` that
/// vertex v stands for. A pose turns leaf components of the Reeb graph of
/// `analysis`, the analysis of `mesh` (needed then only; InvalidArgument
/// without it), and adds to `notes` (when given) the leaves it skipped and
/// the angles it turned by.
MeshVariant perturb_mesh(const Mesh& mesh, const Perturbation& p, const MeshAnalysis* analysis = nullptr,
                         std::vector<std::string>* notes = nullptr);

}  // namespace reebkit

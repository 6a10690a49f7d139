// Perturbations of a mesh that keep the shape: a different sampling of the
// same surface, and small noise along the normals. They make the variants of
// the embedded demo collection (reeb variants), whose classes a retrieval
// method has to recognize through these changes, and some of the variants of
// the robustness experiments (reeb perturb, experiments/robustness.sh).
#pragma once

#include "reebkit/mesh/surface_correspondence.h"

#include <cstdint>

namespace reebkit {

struct ResamplingOptions {
  /// Each edge gets a new vertex at parameter t, drawn uniformly from
  /// [0.5 - jitter, 0.5 + jitter] along it (0 = the midpoint), in [0, 0.5).
  double jitter = 0.2;
  std::uint64_t seed = 1;  ///< same seed, same mesh
};

/// One step of 1-to-4 subdivision whose edge vertices slide along their edge
/// by a random amount (a tangential jitter): the surface, and so its area,
/// genus and shape, stay exactly those of `mesh`, while the sampling changes
/// (#V + #E vertices, 4 #F triangles). Vertices of `mesh` keep their ids and
/// positions; edge vertices follow, in the order of their first triangle.
/// Throws InvalidArgument for a jitter outside [0, 0.5).
Mesh resample_mesh(const Mesh& mesh, const ResamplingOptions& options = {});

/// How far each vertex moves along its normal, as a fraction `amplitude` of
/// the bounding box diagonal.
enum class NoiseShape {
  Uniform,  ///< uniform in [-amplitude, amplitude] x diagonal
  Gaussian  ///< normal with mean 0 and standard deviation amplitude x diagonal
};

/// `rounds` steps of midpoint subdivision (resample_mesh with jitter 0): the
/// same surface, 4^rounds times the triangles, the vertices of `mesh` first
/// with their ids; original_vertex maps each new vertex to the nearest
/// corner of its original triangle (a midpoint: either end of its edge).
/// Throws InvalidArgument naming mesh.source for negative rounds.
MeshVariant subdivide_mesh(const Mesh& mesh, int rounds);

struct NoiseOptions {
  /// Size of the displacements, as a fraction of the bounding box diagonal (see NoiseShape).
  double amplitude = 0.002;
  std::uint64_t seed = 1;  ///< same seed, same mesh
  NoiseShape shape = NoiseShape::Uniform;
};

/// `mesh` with every vertex moved along its unit normal (the sum of its
/// triangles' area-weighted normals; vertices whose sum vanishes stay).
/// Connectivity unchanged. Throws InvalidArgument for a negative or
/// non-finite amplitude.
Mesh add_normal_noise(const Mesh& mesh, const NoiseOptions& options = {});

}  // namespace reebkit

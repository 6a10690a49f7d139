// Perturbations of a mesh that keep the shape: a different sampling of the
// same surface, and small noise along the normals. They make the variants of
// the embedded demo collection (reeb variants), whose classes a retrieval
// method has to recognize through these changes.
#pragma once

#include "reebkit/core/mesh.h"

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

struct NoiseOptions {
  /// Largest displacement, as a fraction of the bounding box diagonal; each
  /// vertex moves by a uniform amount in [-amplitude, amplitude] x diagonal.
  double amplitude = 0.002;
  std::uint64_t seed = 1;  ///< same seed, same mesh
};

/// `mesh` with every vertex moved along its unit normal (the sum of its
/// triangles' area-weighted normals; vertices whose sum vanishes stay).
/// Connectivity unchanged. Throws InvalidArgument for a negative or
/// non-finite amplitude.
Mesh add_normal_noise(const Mesh& mesh, const NoiseOptions& options = {});

}  // namespace reebkit

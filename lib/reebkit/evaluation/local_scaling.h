// Local scaling of a dissimilarity matrix (Zelnik-Manor and Perona,
// "Self-tuning spectral clustering", NIPS 2004): each distance is divided by
// the geometric mean of its two models' neighbourhood radii,
//   d'(i, j) = d(i, j) / sqrt(sigma_i sigma_j),
// sigma_i = the distance from model i to its k-th nearest other model. A
// model in a loose class (large sigma) comes nearer to its own class than to
// a tight class it happens to lie next to. It is a re-ranking in the context
// of a whole collection: it needs every model's sigma, so it applies to
// all-pairs matrices (reeb eval --local-scaling), not to a single query.
#pragma once

#include "reebkit/evaluation/distance_matrix.h"

namespace reebkit {

/// `distances` (N x N, row i = from model i) after local scaling with the
/// k-th nearest other model (the diagonal is not a neighbour). Invariant to
/// multiplying `distances` by a positive number; symmetric when `distances`
/// is; zeros stay zero. A sigma of 0 (k models at distance 0) is raised to
/// the smallest positive sigma, so that no distance is divided by 0; when
/// every sigma is 0 the matrix is returned as it is. Throws InvalidArgument
/// for a non-square matrix or k outside [1, N - 1].
DistanceMatrix local_scaling(const DistanceMatrix& distances, int k);

}  // namespace reebkit

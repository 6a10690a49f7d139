// The Laplace-Beltrami operator of a triangle mesh discretized by linear
// finite elements: the cotangent stiffness matrix and the mass matrix of the
// weak eigenproblem  L phi = lambda M phi  (Reuter, Wolter and Peinecke,
// "Laplace-Beltrami spectra as 'Shape-DNA' of surfaces and solids", CAD 38(4),
// 2006, section 4: the Ritz-Galerkin system of the variational form, here with
// piecewise linear elements; Pinkall and Polthier, "Computing discrete
// minimal surfaces and their conjugates", Experimental Mathematics 2(1), 1993,
// for the cotangent form of the linear stiffness matrix). The spectrum is the
// Shape-DNA baseline of shape_dna.h.
//
// Without boundary conditions imposed the discretization is that of the
// Neumann problem, so meshes with holes need no special case.
#pragma once

#include "reebkit/core/mesh.h"

#include <Eigen/SparseCore>

#include <vector>

namespace reebkit {

/// The mass matrix of the linear elements.
enum class MassMatrix {
  /// The exact integrals of the hat functions, area/12 x [2 1 1; 1 2 1; 1 1 2]
  /// per triangle (Reuter et al. 2006's Galerkin mass matrix, with linear
  /// elements): Rayleigh-Ritz, so every eigenvalue is an upper bound of the
  /// smooth surface's one (min-max principle).
  Consistent,
  /// Row sums of the consistent matrix, a third of the area of the incident
  /// triangles on the diagonal: diagonal, cheaper, no bound.
  Lumped,
};

struct LaplaceBeltramiOptions {
  MassMatrix mass = MassMatrix::Consistent;  ///< see MassMatrix
  /// The elements on the intrinsic Delaunay triangulation of the mesh
  /// (intrinsic_delaunay.h: the same surface and vertices, its edges flipped
  /// until each is Delaunay) instead of the mesh's own triangles. Off: the
  /// operator of Reuter et al. on the triangles as given.
  bool intrinsic_delaunay = false;
};

/// The stiffness and mass matrices, n x n for the n vertices with area (all
/// #V on a mesh without degenerate triangles), symmetric, both full (upper and
/// lower triangles stored). stiffness(i, j) = -(cot a_ij + cot b_ij) / 2 for
/// an edge ij opposite the angles a_ij and b_ij (one angle on a boundary
/// edge), the diagonal the negated off-diagonal row sum: positive
/// semi-definite with the constants as its kernel on a connected mesh. mass
/// is positive definite. Both scale as the mesh does: the stiffness not at
/// all, the mass with the area.
struct LaplaceBeltrami {
  Eigen::SparseMatrix<double> stiffness;
  Eigen::SparseMatrix<double> mass;
  /// The mesh vertex of each row (and column), increasing: every vertex on a
  /// triangle of nonzero area.
  std::vector<Index> vertex;
};

/// The matrices of `mesh`. A triangle of zero area (to rounding: twice its
/// area at most 1e-12 of its longest edge squared; the cleaned meshes of
/// real collections have a few, e.g. SHREC07's 351.off) spans no surface and
/// its cotangents are undefined: it is left out of both matrices, and so is
/// a vertex left on triangles of zero area only (its rows would be zero and
/// the mass matrix singular), as the mesh reader drops the vertices no
/// triangle uses (mesh_cleanup.h); the same rule holds for the triangles of
/// the intrinsic Delaunay triangulation. Those slits are Neumann borders of no
/// length: the spectrum of the surface does not change. Throws
/// InvalidMeshError naming mesh.source when the mesh has no triangle of
/// nonzero area.
LaplaceBeltrami laplace_beltrami(const Mesh& mesh, const LaplaceBeltramiOptions& options = {});

}  // namespace reebkit

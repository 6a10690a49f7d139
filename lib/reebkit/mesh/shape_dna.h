// Shape-DNA (Reuter, Wolter and Peinecke, "Laplace-Beltrami spectra as
// 'Shape-DNA' of surfaces and solids", Computer-Aided Design 38(4), 2006):
// the beginning of the Laplace-Beltrami spectrum of a surface, normalized by
// its area. The spectrum is an isometry invariant, so it does not change when
// a shape bends without stretching (a limb moving); with the area
// normalization it does not change with scale either. The retrieval baseline
// of experiments/baselines.cpp.
//
// The eigenvalues are those of the linear finite element discretization of
// laplace_beltrami.h, found by Lanczos iterations with shift and invert
// (Spectra, libspectra-dev, MPL-2.0) around a small negative shift: the
// eigenvalues nearest the shift are the smallest, and the shifted matrix
// L - shift M is positive definite, so a sparse Cholesky factorization
// C C^T of it turns the generalized problem into the standard symmetric one
// of C^-1 M C^-T, on which Lanczos needs no mass-matrix inner products.
#pragma once

#include "reebkit/mesh/laplace_beltrami.h"

#include <Eigen/Dense>

#include <vector>

namespace reebkit {

struct ShapeDnaOptions {
  /// How many eigenvalues after the zero one (lambda_1 .. lambda_N). 50,
  /// the lower end of the usual 50-100: the linear elements' relative error
  /// grows with the eigenvalue (as lambda h^2), so the later ones say more
  /// about the triangulation than about the shape on meshes of a few
  /// thousand vertices, and the solver's time grows with the count.
  int eigenvalues = 50;
  /// Consistent: the Galerkin mass matrix of Reuter et al. (see MassMatrix).
  MassMatrix mass = MassMatrix::Consistent;
  /// The shift of the shift-and-invert iterations, in units of 1 / area
  /// (the scale of lambda x area): small and negative, below the zero
  /// eigenvalue of the Neumann problem.
  double shift = -0.01;
  /// Relative tolerance of the Lanczos iterations on the residuals of the
  /// Ritz pairs. An eigenvalue's error goes as the square of its residual
  /// (over its gap to the rest of the spectrum), so 1e-8 already gives the
  /// eigenvalues to rounding, in fewer iterations than Spectra's default
  /// 1e-10.
  double tolerance = 1e-8;
  /// Eigenvalues computed beyond the last one kept, so that a multiple
  /// eigenvalue at the end of the range comes out whole (Lanczos finds its
  /// copies one after another); -1: max(10, eigenvalues / 5). Fewer are
  /// cheaper where multiplicities are not expected (parts of a shape).
  int margin = -1;
  /// Also return the eigenfunctions (ShapeDna::eigenvectors, vertex_area),
  /// for the heat kernel (mesh/heat_kernel.h).
  bool eigenvectors = false;
  /// The linear elements on the intrinsic Delaunay triangulation of the mesh
  /// (LaplaceBeltramiOptions::intrinsic_delaunay): the eigenvalues of a mesh
  /// with slivers and caps, as decimation leaves them, come out nearer the
  /// surface's. Off: Reuter et al.'s elements on the triangles as given.
  bool intrinsic_delaunay = false;
};

struct ShapeDna {
  /// lambda_k x area for k = 1 .. N, ascending: the area-normalized spectrum
  /// without its first eigenvalue, which is 0 (the constants) on every mesh.
  std::vector<double> eigenvalues;
  double area = 0;  ///< the surface area, to get lambda_k back
  /// lambda_{N+1} x area, the first eigenvalue computed beyond the range
  /// (ShapeDnaOptions::margin); infinity where none was.
  double next_eigenvalue = 0;
  /// With ShapeDnaOptions::eigenvectors: one row per vertex with area
  /// (LaplaceBeltrami::vertex), column k the eigenfunction of lambda_k for
  /// k = 0 .. N (column 0 the constant), orthonormal for the mass matrix of
  /// the surface scaled to unit area. Empty otherwise.
  Eigen::MatrixXd eigenvectors;
  /// With ShapeDnaOptions::eigenvectors: each of those vertices' share of
  /// the area (its row sum of the mass matrix / area; they sum to 1).
  Eigen::VectorXd vertex_area;
};

/// The Shape-DNA of `mesh` (one connected surface; with several components
/// each adds a zero eigenvalue). Meshes with boundary get their Neumann
/// spectrum. Throws InvalidArgument for options.eigenvalues < 1 or a shift
/// not negative, InvalidMeshError naming mesh.source for a mesh without a
/// triangle of nonzero area, one with at most eigenvalues + 1 vertices on
/// such triangles (see laplace_beltrami: triangles of zero area and the
/// vertices on them only are left out, so every mesh the reader accepts has
/// a spectrum when it is large enough), or one on which the iterations do
/// not converge.
ShapeDna shape_dna(const Mesh& mesh, const ShapeDnaOptions& options = {});

/// The distance between two Shape-DNAs: the Euclidean distance of the
/// normalized spectra (Reuter et al. 2006 compare spectra by a norm of
/// their difference), each eigenvalue first divided by its index k.
/// By Weyl's law lambda_k area ~ 4 pi k, so without that weight the last
/// eigenvalues, the least accurate, would dominate the sum; with it each
/// counts alike (the linear re-weighting of Reuter's own implementation,
/// LaPy's shapedna.reweight_ev). Compares the first min(|a|, |b|) eigenvalues.
double shape_dna_distance(const ShapeDna& a, const ShapeDna& b);

}  // namespace reebkit

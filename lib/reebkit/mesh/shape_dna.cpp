#include "reebkit/mesh/shape_dna.h"

#include "reebkit/core/error.h"

#include <Eigen/SparseCholesky>
#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace reebkit {

namespace {

/// The symmetric operator S = C^-1 P M P^T C^-T of the Cholesky factor
/// P (L - shift M) P^T = C C^T (P a fill-reducing permutation): S is similar
/// to (L - shift M)^-1 M, so its eigenvalues are 1 / (lambda - shift) for the
/// eigenvalues lambda of L phi = lambda M phi, the largest for the lambda
/// nearest the shift. The standard form of shift-and-invert (Ericsson and
/// Ruhe, "The spectral transformation Lanczos method", Math. Comp. 35, 1980):
/// one application costs the same solve and mass product as the generalized
/// form's, but Lanczos then orthogonalizes in the Euclidean inner product,
/// with no further mass product per inner product and norm. L - shift M is
/// positive definite for shift < 0 (L semi-definite, M definite).
class InvertedPencil {
 public:
  using Scalar = double;

  InvertedPencil(const LaplaceBeltrami& operators, double shift, const std::string& source) {
    cholesky_.compute(operators.stiffness - shift * operators.mass);
    if (cholesky_.info() != Eigen::Success)
      throw InvalidMeshError(source, "the shifted Laplace-Beltrami matrix cannot be factorized");
    const auto& p = cholesky_.permutationP();
    mass_ = operators.mass.twistedBy(p);
    work_.resize(mass_.rows());
  }

  Eigen::Index rows() const { return mass_.rows(); }
  Eigen::Index cols() const { return mass_.rows(); }

  /// y = C^-1 P M P^T C^-T x, by the two triangular solves on the factor's
  /// own arrays (the solves are most of the time Lanczos takes).
  void perform_op(const double* x, double* y) const {
    const auto n = static_cast<int>(rows());
    work_ = Eigen::Map<const Eigen::VectorXd>(x, n);
    solve_transposed(work_.data());
    Eigen::Map<Eigen::VectorXd> out(y, n);
    out.noalias() = mass_ * work_;
    const auto& c = factor();
    const int* start = c.outerIndexPtr();
    const int* row = c.innerIndexPtr();
    const double* value = c.valuePtr();
    for (int j = 0; j < n; ++j) {  // C out = P M P^T w
      const double t = y[j] /= value[start[j]];
      for (int k = start[j] + 1; k < start[j + 1]; ++k) y[row[k]] -= value[k] * t;
    }
  }

  /// The eigenfunction phi = P^T C^-T y of the pencil for an eigenvector y
  /// of this operator (S y = mu y gives M phi = mu (L - shift M) phi),
  /// scaled to phi^T M phi = 1.
  Eigen::VectorXd eigenfunction(const Eigen::VectorXd& y) const {
    Eigen::VectorXd w = y;
    solve_transposed(w.data());
    w /= std::sqrt(w.dot(mass_ * w));
    return cholesky_.permutationPinv() * w;
  }

 private:
  /// C by columns, each its diagonal first.
  const Eigen::SparseMatrix<double>& factor() const { return cholesky_.matrixL().nestedExpression(); }

  /// w = C^-T w: row j of C^T is column j of C. Eigen's solve with C^T is a
  /// chain of dependent additions per column, which four partial sums break up.
  void solve_transposed(double* w) const {
    const auto& c = factor();
    const int* start = c.outerIndexPtr();
    const int* row = c.innerIndexPtr();
    const double* value = c.valuePtr();
    for (auto j = static_cast<int>(rows()) - 1; j >= 0; --j) {
      double sum[4] = {0.0, 0.0, 0.0, 0.0};
      int k = start[j] + 1;
      for (; k + 4 <= start[j + 1]; k += 4)
        for (int u = 0; u < 4; ++u) sum[u] += value[k + u] * w[row[k + u]];
      for (; k < start[j + 1]; ++k) sum[0] += value[k] * w[row[k]];
      w[j] = (w[j] - ((sum[0] + sum[1]) + (sum[2] + sum[3]))) / value[start[j]];
    }
  }

  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> cholesky_;
  Eigen::SparseMatrix<double> mass_;  ///< P M P^T
  mutable Eigen::VectorXd work_;
};

}  // namespace

ShapeDna shape_dna(const Mesh& mesh, const ShapeDnaOptions& options) {
  if (options.eigenvalues < 1) throw InvalidArgument("shape_dna: eigenvalues must be >= 1");
  if (!(options.shift < 0)) throw InvalidArgument("shape_dna: the shift must be negative");
  const std::string source = mesh.source.empty() ? "mesh" : mesh.source;
  const Eigen::Index wanted = options.eigenvalues + 1;  // with the zero eigenvalue
  LaplaceBeltrami operators = laplace_beltrami(mesh, {options.mass, options.intrinsic_delaunay});
  const auto n = static_cast<Eigen::Index>(operators.vertex.size());  // the vertices with area
  if (n <= wanted)
    throw InvalidMeshError(source, std::to_string(n) + " vertices with area: too few for " +
                                       std::to_string(options.eigenvalues) + " Laplace-Beltrami eigenvalues");
  ShapeDna result;
  result.area = surface_area(mesh);
  // With the mass matrix divided by the area the eigenvalues are lambda x
  // area directly, and one shift suits every scale.
  operators.mass /= result.area;

  // Lanczos finds the copies of a multiple eigenvalue one after another, so
  // a multiple eigenvalue at the end of the range may come out with too few
  // copies: a few more eigenvalues than kept make the kept range whole.
  const int margin = options.margin >= 0 ? options.margin : std::max(10, options.eigenvalues / 5);
  const Eigen::Index computed = std::min<Eigen::Index>(wanted + margin, n - 1);
  const Eigen::Index subspace = std::min<Eigen::Index>(n, std::max<Eigen::Index>(2 * computed + 1, 20));
  InvertedPencil op(operators, options.shift, source);
  Spectra::SymEigsSolver<InvertedPencil> solver(op, computed, subspace);
  solver.init();
  // The largest 1 / (lambda - shift), hence the smallest lambda, in
  // decreasing order of it: increasing lambda.
  solver.compute(Spectra::SortRule::LargestAlge, 1000, options.tolerance, Spectra::SortRule::LargestAlge);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw InvalidMeshError(source, "the Laplace-Beltrami eigenvalue iterations did not converge");
  const Eigen::VectorXd inverted = solver.eigenvalues();
  for (Eigen::Index k = 1; k < wanted; ++k) result.eigenvalues.push_back(options.shift + 1.0 / inverted(k));
  result.next_eigenvalue =
      computed > wanted ? options.shift + 1.0 / inverted(wanted) : std::numeric_limits<double>::infinity();
  if (options.eigenvectors) {
    const Eigen::MatrixXd ritz = solver.eigenvectors(wanted);
    result.eigenvectors.resize(n, wanted);
    for (Eigen::Index k = 0; k < wanted; ++k) result.eigenvectors.col(k) = op.eigenfunction(ritz.col(k));
    result.vertex_area = operators.mass * Eigen::VectorXd::Ones(n);
  }
  return result;
}

double shape_dna_distance(const ShapeDna& a, const ShapeDna& b) {
  const std::size_t n = std::min(a.eigenvalues.size(), b.eigenvalues.size());
  double sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double d = (a.eigenvalues[k] - b.eigenvalues[k]) / static_cast<double>(k + 1);
    sum += d * d;
  }
  return std::sqrt(sum);
}

}  // namespace reebkit

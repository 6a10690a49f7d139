#include "reebkit/mesh/shape_dna.h"

#include "reebkit/core/error.h"

#include <Eigen/SparseCholesky>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace reebkit {

namespace {

/// y = (L - shift M)^-1 x by a sparse LDL^T factorization, the operator
/// Spectra's shift-and-invert mode asks for. L - shift M is positive
/// definite for shift < 0 (L semi-definite, M definite), so no pivoting.
class ShiftedSolve {
 public:
  using Scalar = double;

  ShiftedSolve(const Eigen::SparseMatrix<double>& stiffness, const Eigen::SparseMatrix<double>& mass,
               std::string source)
      : stiffness_(stiffness), mass_(mass), source_(std::move(source)) {}

  Eigen::Index rows() const { return stiffness_.rows(); }
  Eigen::Index cols() const { return stiffness_.cols(); }

  void set_shift(double shift) {
    solver_.compute(stiffness_ - shift * mass_);
    if (solver_.info() != Eigen::Success)
      throw InvalidMeshError(source_, "the shifted Laplace-Beltrami matrix cannot be factorized");
  }

  void perform_op(const double* x, double* y) const {
    Eigen::Map<Eigen::VectorXd>(y, rows()) = solver_.solve(Eigen::Map<const Eigen::VectorXd>(x, rows()));
  }

 private:
  const Eigen::SparseMatrix<double>& stiffness_;
  const Eigen::SparseMatrix<double>& mass_;
  std::string source_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

/// y = M x, the product Spectra's B-inner products ask for (the whole
/// matrix is stored, so a plain product: faster than a self-adjoint view).
class MassProduct {
 public:
  using Scalar = double;
  explicit MassProduct(const Eigen::SparseMatrix<double>& mass) : mass_(mass) {}
  Eigen::Index rows() const { return mass_.rows(); }
  Eigen::Index cols() const { return mass_.cols(); }
  void perform_op(const double* x, double* y) const {
    Eigen::Map<Eigen::VectorXd>(y, rows()).noalias() = mass_ * Eigen::Map<const Eigen::VectorXd>(x, rows());
  }

 private:
  const Eigen::SparseMatrix<double>& mass_;
};

}  // namespace

ShapeDna shape_dna(const Mesh& mesh, const ShapeDnaOptions& options) {
  if (options.eigenvalues < 1) throw InvalidArgument("shape_dna: eigenvalues must be >= 1");
  if (!(options.shift < 0)) throw InvalidArgument("shape_dna: the shift must be negative");
  const std::string source = mesh.source.empty() ? "mesh" : mesh.source;
  const Eigen::Index wanted = options.eigenvalues + 1;  // with the zero eigenvalue
  LaplaceBeltrami operators = laplace_beltrami(mesh, {options.mass});
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
  ShiftedSolve op(operators.stiffness, operators.mass, source);
  MassProduct mass_op(operators.mass);
  Spectra::SymGEigsShiftSolver<ShiftedSolve, MassProduct, Spectra::GEigsMode::ShiftInvert> solver(op, mass_op, computed,
                                                                                                  subspace,
                                                                                                  options.shift);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, options.tolerance, Spectra::SortRule::SmallestAlge);
  if (solver.info() != Spectra::CompInfo::Successful)
    throw InvalidMeshError(source, "the Laplace-Beltrami eigenvalue iterations did not converge");
  const Eigen::VectorXd values = solver.eigenvalues();  // ascending
  result.eigenvalues.assign(values.data() + 1, values.data() + wanted);
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

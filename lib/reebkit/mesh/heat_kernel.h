// The heat kernel signature (Sun, Ovsjanikov and Guibas, "A concise and
// provably informative multi-scale signature based on heat diffusion",
// SGP 2009): HKS(x, t) = sum_k exp(-lambda_k t) phi_k(x)^2, the heat left at
// x after time t from a unit source at x, from the Laplace-Beltrami
// eigenpairs of shape_dna.h. Like the spectrum it does not change when the
// surface bends without stretching, nor under rigid motion; with the surface
// scaled to unit area (times in units of the area, as lambda x area) it does
// not change with scale either. Small times see the tips of the parts (heat
// stays at a tip longer), large times the parts themselves.
//
// The descriptor of a whole surface is the distribution of HKS(x, t) / Z(t)
// over its area, Z(t) = sum_k exp(-lambda_k t) being its mean on the
// unit-area surface (each phi_k has unit mass), so that the distribution
// says how the heat spreads over the surface and not how much there is: the
// spectrum (Z) is compared apart. Each distribution is given by quantiles of
// ln(HKS / Z), area-weighted: a distance between quantile functions is the
// L1 transport distance between the distributions, with no bins to choose.
//
// The sum is truncated to the eigenpairs the Shape-DNA computed, and ends
// before a multiple eigenvalue whose copies the range does not hold whole:
// a part of an eigenspace depends on the basis Lanczos happens to return,
// the whole eigenspace does not (on a sphere the sum over each whole
// eigenspace is constant, so HKS is too).
#pragma once

#include "reebkit/mesh/shape_dna.h"

#include <vector>

namespace reebkit {

struct HeatKernelOptions {
  /// The times t, in units of the area (the scale of 1 / (lambda x area)):
  /// from the tips to the parts. Positive.
  std::vector<double> times = {0.01, 0.03, 0.1, 0.3};
  /// Quantiles per time, at the levels (q + 1/2) / quantiles. >= 1.
  int quantiles = 8;
  /// Two eigenvalues closer than this, relative, are copies of one multiple
  /// eigenvalue (the linear elements split exact multiplicities a little).
  double multiplet_gap = 1e-2;
};

/// The eigenpairs the heat kernel sums over: k = 0 .. the result - 1 of
/// `dna`, ending before the last multiple eigenvalue of its range whose
/// copies run past it (`next_eigenvalue`).
int whole_eigenspaces(const ShapeDna& dna, double multiplet_gap);

/// The distribution of ln(HKS(x, t) / Z(t)) over the area of the surface
/// of `dna` (computed with ShapeDnaOptions::eigenvectors), at each of
/// options.times: times.size() x quantiles values, time after time, each
/// time's ascending. Throws InvalidArgument for a Shape-DNA without
/// eigenvectors or options out of range.
std::vector<double> heat_kernel_quantiles(const ShapeDna& dna, const HeatKernelOptions& options = {});

}  // namespace reebkit

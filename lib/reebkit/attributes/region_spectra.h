// Laplace-Beltrami spectra of the whole surface and of each region of the
// high-level Reeb graph: intrinsic attributes that carry the proportions of
// a shape and of its parts, which its graph alone does not (a thin arm and a
// thick one have the same graph). Tierny et al. 2006, section 5.3: the graphs
// "can be extended with geometrical attributes"; the spectrum is the
// Shape-DNA of Reuter, Wolter and Peinecke (CAD 38(4), 2006, mesh/shape_dna.h)
// taken per region, with the Neumann condition on the level lines that cut
// the region out (Reuter et al. 2009, "Discrete Laplace-Beltrami operators
// for shape analysis and segmentation", use the same per-part spectra).
//
// Invariances: the Laplace-Beltrami spectrum does not change when the
// surface bends without stretching (a limb moving), nor under rigid motion;
// each eigenvalue is multiplied by the area it belongs to (the surface's, or
// the region's), so scale drops out too. Each is also divided by 4 pi k, its
// value under Weyl's law (lambda_k area ~ 4 pi k), so that every index counts
// alike, and squashed into [0, 1) by x / (1 + x), the range the matcher and
// the signature's nearest-neighbour search expect.
//
// Cost: the regions' spectra are computed on each region cut from the
// surface and decimated to about SpectraOptions::coarse_vertices x its share
// of the vertices (mesh/decimation.h): the lowest eigenvalues describe the
// shape at the scale of its parts, which the coarse copy keeps, and the
// solver's time grows with the vertex count. The whole surface's spectrum
// is computed on a finer copy (SpectraOptions::global_vertices): it has to
// tell apart people whose proportions differ by a few percent, within the
// error of the linear elements on the coarse copy; it is decimated straight
// from the surface whatever its size, so that a fine and a coarse sampling
// of one shape get the same kind of copy. With the regions' spectra, a surface of more than
// SpectraOptions::fine_vertices vertices is first decimated once to about
// that many (spectra_surface), and the regions are cut from that: one
// decimation of the large surface for all of them, instead of one per
// region, each a pass over every vertex. A
// decimation depends on the frame, the rounding and the vertex order of its
// input, so it is done on the surface's canonical copy (canonical_copy,
// mesh/transform.h), which similar copies share: the values are the same for
// every similar copy of a surface whose frame is well-defined, and computed
// on the surface itself where it is not.
#pragma once

#include "reebkit/attributes/graph_record.h"
#include "reebkit/core/mesh.h"

#include <vector>

namespace reebkit {

struct SpectraOptions {
  /// The regions are cut from the surface and decimated to about this many
  /// vertices x their share of the surface's vertices before their spectra
  /// are computed (a smaller mesh is used as it is). >= 100.
  Index coarse_vertices = 1500;
  /// The whole surface is decimated to about this many vertices before its
  /// spectrum is computed (a smaller mesh is used as it is): finer than the
  /// regions', since the relative error of the linear elements' eigenvalues
  /// (about lambda h^2) is what separates one build of a body from another.
  /// >= coarse_vertices.
  Index global_vertices = 6000;
  /// The surface is used as it is, not decimated, when the gap between the
  /// second moments about its principal axes (SurfaceFrame::axis_gap,
  /// mesh/transform.h) is below this: its frame, hence its coarse copy,
  /// would turn with the rounding of its input. In [0, 1]; 0 always
  /// decimates.
  double min_axis_gap = 1e-3;
  /// A region with less than this share of the surface's area (counted on
  /// the surface before the decimation, so that the decision does not move
  /// with it) gets zeros: too few coarse vertices to resolve its first
  /// eigenvalues (about coarse_vertices x share). In [0, 1].
  double min_region_area = 0.01;
  /// With the regions' spectra, a surface of more vertices is first
  /// decimated once to about this many (spectra_surface), from which the
  /// regions' coarse copies are taken. Far above coarse_vertices, so that
  /// the regions' borders cut from it are finer than an edge of their coarse
  /// copies. The whole surface's copy does not depend on it. >= coarse_vertices.
  Index fine_vertices = 120000;
  /// Compute the regions' spectra (SurfaceSpectra::region). Off by default:
  /// the default matching cost does not compare them (its r term has weight
  /// 0, results/matching_weights.md), and they are about a tenth of the
  /// time of `reeb index`; off, they are zeros. The whole surface's values
  /// are always computed.
  bool regions = false;
};

/// What the spectra of a mesh are computed from, prepared from the mesh
/// alone (not its Reeb graph), so that it can be done while the graph is
/// built (analyze_mesh): the whole surface's values, computed on the
/// canonical copy of the mesh (canonical_copy, mesh/transform.h) decimated
/// to about SpectraOptions::global_vertices, and, with
/// SpectraOptions::regions, the surface the regions are cut from: the
/// canonical copy, decimated to about SpectraOptions::fine_vertices
/// vertices where it has more. Both on the mesh as given where its frame is
/// ill-defined (axis_gap below SpectraOptions::min_axis_gap).
struct SpectraSurface {
  /// The surface the regions are cut from; empty without
  /// SpectraOptions::regions.
  Mesh mesh;
  /// #V of `mesh`: the vertex of the input that vertex v is.
  std::vector<Index> original_vertex;
  /// #V of the input.
  Index input_vertices = 0;
  /// SurfaceFrame::axis_gap of the input.
  double axis_gap = 0.0;
  /// SurfaceSpectra::global: the whole surface's values need no regions,
  /// so they are computed here, while the graph is built.
  std::vector<double> global;
  /// `mesh` is a decimation of the canonical copy (not the copy itself, nor
  /// empty).
  bool decimated() const { return mesh.num_vertices() > 0 && mesh.num_vertices() < input_vertices; }
};

/// The whole surface's spectrum of `mesh` and, with the regions' spectra, the
/// surface they are cut from. Throws InvalidArgument for options out of range.
SpectraSurface spectra_surface(const Mesh& mesh, const SpectraOptions& options = {});

struct SurfaceSpectra {
  /// The whole surface's entries of the signature from kSigGlobalSpectrum:
  /// its spectrum, kGlobalSpectrumLength values s / (1 + s), s = lambda_k x
  /// area / (4 pi k), k = 1 .. kGlobalSpectrumLength (the zero eigenvalue
  /// left out), then the distribution of its heat kernel signature,
  /// kGlobalHeatLength values r / (1 + r) of the quantiles r of HKS / Z
  /// (mesh/heat_kernel.h, default options), from the same eigenpairs.
  std::vector<double> global;
  /// #regions x kRegionSpectrumLength, row-major: the same for each
  /// region (its own area, its Neumann spectrum); zeros without
  /// SpectraOptions::regions, for a region below
  /// min_region_area, or left with fewer than kRegionSpectrumLength + 2
  /// vertices on the coarse copy.
  std::vector<double> region;
};

/// The spectra of `mesh` (one connected surface) and of its regions, computed
/// on its spectra_surface:
/// vertex v belongs to region vertex_region[v] in [0, regions). A triangle
/// belongs to the region of at least two of its corners (none when all three
/// differ). Throws InvalidArgument for a vertex_region of another size, a
/// label out of range or options out of range. A spectrum that cannot be
/// computed (see shape_dna: a surface or region of a handful of vertices)
/// is left at zeros.
SurfaceSpectra surface_spectra(const Mesh& mesh, const std::vector<Index>& vertex_region, Index regions,
                               const SpectraOptions& options = {});

/// The same on `surface`, the spectra_surface of `mesh` with the same
/// options, prepared beforehand. Throws InvalidArgument as above, for a
/// surface of another vertex count, and for SpectraOptions::regions on a
/// surface prepared without them.
SurfaceSpectra surface_spectra(const Mesh& mesh, const SpectraSurface& surface, const std::vector<Index>& vertex_region,
                               Index regions, const SpectraOptions& options = {});

}  // namespace reebkit

#include "reebkit/attributes/region_spectra.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/decimation.h"
#include "reebkit/mesh/heat_kernel.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shape_dna.h"
#include "reebkit/mesh/surface_correspondence.h"
#include "reebkit/mesh/transform.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace reebkit {

namespace {

std::size_t at(Index i) { return static_cast<std::size_t>(i); }

/// s / (1 + s) of s = lambda_k x area / (4 pi k) for each eigenvalue of a
/// Shape-DNA (whose eigenvalues are lambda_k x area already), into out[0 .. n).
void squash(const ShapeDna& dna, int n, double* out) {
  for (int k = 0; k < n; ++k) {
    const double s = dna.eigenvalues[at(k)] / (4.0 * M_PI * (k + 1));
    out[k] = s / (1.0 + s);
  }
}

/// The triangles of `mesh` listed in `triangles`, as a mesh of their own
/// (vertices numbered in order of first use). `renumber` holds
/// kInvalidIndex for every vertex of `mesh`, and does again on return.
Mesh submesh(const Mesh& mesh, const std::vector<Index>& triangles, std::vector<Index>& renumber) {
  Mesh out;
  out.source = mesh.source;
  out.triangles.resize(static_cast<Index>(triangles.size()), 3);
  std::vector<Index> used;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const Index v = mesh.triangles(triangles[i], c);
      if (renumber[at(v)] == kInvalidIndex) {
        renumber[at(v)] = static_cast<Index>(used.size());
        used.push_back(v);
      }
      out.triangles(static_cast<Index>(i), c) = renumber[at(v)];
    }
  out.vertices.resize(static_cast<Index>(used.size()), 3);
  for (std::size_t i = 0; i < used.size(); ++i) {
    out.vertices.row(static_cast<Index>(i)) = mesh.vertices.row(used[i]);
    renumber[at(used[i])] = kInvalidIndex;
  }
  return out;
}

/// The connected piece of `part` with the largest area: the triangles near
/// a region's border may cut it into pieces (a thin bridge of triangles with
/// two corners outside), and each further piece would add a zero
/// eigenvalue, shifting the spectrum by one.
Mesh largest_piece(const Mesh& part) {
  const ComponentLabels pieces = connected_components(part.triangles, part.num_vertices());
  if (pieces.count <= 1) return part;
  std::vector<double> area(at(pieces.count), 0.0);
  for (Index t = 0; t < part.num_triangles(); ++t)
    area[at(pieces.vertex_component[at(part.triangles(t, 0))])] += triangle_area(part, t);
  const Index keep = static_cast<Index>(std::max_element(area.begin(), area.end()) - area.begin());
  std::vector<Index> kept;
  for (Index t = 0; t < part.num_triangles(); ++t)
    if (pieces.vertex_component[at(part.triangles(t, 0))] == keep) kept.push_back(t);
  std::vector<Index> renumber(at(part.num_vertices()), kInvalidIndex);
  return submesh(part, kept, renumber);
}

void check_options(const SpectraOptions& options) {
  if (options.coarse_vertices < 100 || options.global_vertices < options.coarse_vertices ||
      options.fine_vertices < options.coarse_vertices ||
      !(options.min_region_area >= 0.0 && options.min_region_area <= 1.0) ||
      !(options.min_axis_gap >= 0.0 && options.min_axis_gap <= 1.0))
    throw InvalidArgument(
        "surface_spectra: options out of range (coarse_vertices >= 100, global_vertices and fine_vertices >= "
        "coarse_vertices, "
        "min_region_area and min_axis_gap in [0, 1])");
}

/// The region of triangle t of `mesh`: that of at least two of its corners
/// (vertex v in region label[v]), kInvalidIndex when all three differ.
Index triangle_region(const Mesh& mesh, const std::vector<Index>& label, Index t) {
  const Index a = label[at(mesh.triangles(t, 0))], b = label[at(mesh.triangles(t, 1))],
              c = label[at(mesh.triangles(t, 2))];
  return a == b || a == c ? a : b == c ? b : kInvalidIndex;
}

/// `m` decimated to `ratio` of its vertices (within `tolerance`; a try that
/// keeps too many is decimated further, DecimationOptions::refine_last_try);
/// `m` itself where the decimation leaves a triangle it cannot repair or
/// cuts `m` in two (a thin part collapsed: each further piece adds a zero
/// eigenvalue).
MeshVariant decimated_or_whole(const Mesh& m, double ratio, double tolerance) {
  if (ratio < 1.0) try {
      DecimationOptions options{ratio, tolerance};
      options.refine_last_try = true;
      MeshVariant coarse = decimate_mesh(m, options);
      if (connected_components(coarse.mesh.triangles, coarse.mesh.num_vertices()).count == 1) return coarse;
    } catch (const InvalidMeshError&) {
    }
  return same_vertices(m);
}

/// The share of `surface`'s vertices its coarse copies keep to have about
/// `vertices`: 1 (the surface itself) where the frame is ill-defined (its
/// coarse copies would differ with the rounding: a quadric collapse's
/// choice between collapses of nearly equal cost, as on the flat faces of a
/// mechanical part, turns on a change of the last bit).
double coarse_ratio(const Mesh& surface, double axis_gap, Index vertices, const SpectraOptions& options) {
  return axis_gap < options.min_axis_gap
             ? 1.0
             : std::min(1.0, static_cast<double>(vertices) / static_cast<double>(surface.num_vertices()));
}

/// The coarse copy of a connected piece, decimated to `ratio` of its
/// vertices; the piece itself where the decimation leaves a triangle it
/// cannot repair, or cuts the piece in two: slower, not wrong.
Mesh coarsened(const Mesh& piece, double ratio) { return decimated_or_whole(piece, ratio, 0.05).mesh; }

/// The copy of about fine_vertices of `surface` (which has more), or the
/// surface where the decimation cannot make it: its size matters little (a
/// loose tolerance, one try).
MeshVariant fine_copy(const Mesh& surface, const SpectraOptions& options) {
  return decimated_or_whole(surface,
                            static_cast<double>(options.fine_vertices) / static_cast<double>(surface.num_vertices()),
                            0.25);
}

/// SurfaceSpectra::global of `surface` (the canonical copy of a mesh, or the
/// mesh itself where it has no frame of its own, of frame gap `axis_gap`),
/// computed on its copy of about global_vertices decimated straight from
/// it, whatever its size, so that a fine and a coarse sampling of one shape
/// get the same kind of copy. Where that copy cannot be made (the
/// decimation cut a thin part off, or left a triangle it cannot repair) or
/// its operator cannot be solved: the same from a copy of about
/// fine_vertices of a larger surface (a milder decimation first), then on
/// the surface itself; zeros where none can be taken (a handful of
/// vertices), as for a region too small.
std::vector<double> global_spectrum(const Mesh& surface, double axis_gap, const SpectraOptions& options) {
  std::vector<double> out(at(kGlobalSpectrumLength + kGlobalHeatLength), 0.0);
  ShapeDnaOptions global;
  global.eigenvalues = kGlobalSpectrumLength;
  global.margin = 4;
  global.eigenvectors = true;
  global.intrinsic_delaunay = true;  // the coarse copy's slivers, ShapeDnaOptions::intrinsic_delaunay
  const HeatKernelOptions heat;
  if (heat.times.size() * at(heat.quantiles) != at(kGlobalHeatLength))
    throw std::logic_error("global_spectrum: HeatKernelOptions does not give kGlobalHeatLength values");
  const auto computed_on = [&](const Mesh& m) {
    try {
      const ShapeDna dna = shape_dna(m, global);
      squash(dna, kGlobalSpectrumLength, out.data());
      const std::vector<double> quantiles = heat_kernel_quantiles(dna, heat);
      for (std::size_t i = 0; i < quantiles.size(); ++i)
        out[at(kGlobalSpectrumLength) + i] = 1.0 / (1.0 + std::exp(-quantiles[i]));  // r / (1 + r), r = e^q
      return true;
    } catch (const InvalidMeshError&) {
      return false;
    }
  };
  const Index n = surface.num_vertices();
  const double ratio = coarse_ratio(surface, axis_gap, options.global_vertices, options);
  if (ratio < 1.0) {  // a frame of its own, and more vertices than the copy
    const Mesh copy = coarsened(surface, ratio);
    if (copy.num_vertices() < n && computed_on(copy)) return out;
    if (n > options.fine_vertices) {
      const Mesh fine = fine_copy(surface, options).mesh;
      if (fine.num_vertices() < n) return global_spectrum(fine, axis_gap, options);
    }
  }
  computed_on(surface);
  return out;
}

}  // namespace

SpectraSurface spectra_surface(const Mesh& mesh, const SpectraOptions& options) {
  check_options(options);
  // Everything below on the surface's canonical copy (mesh/transform.h)
  // where it has a frame of its own: the decimation follows the frame, the
  // rounding and the order of its input, the spectrum none of them, so
  // similar copies of a surface get the same coarse copies and the same
  // values.
  const SurfaceFrame frame = surface_frame(mesh);
  SpectraSurface out;
  out.input_vertices = mesh.num_vertices();
  out.axis_gap = frame.axis_gap;
  if (frame.axis_gap < options.min_axis_gap) {
    // No frame of its own (a rotational symmetry): the copy's coordinates,
    // snapped in a frame that turns with the rounding, and its order would
    // differ between similar copies; the surface as given does not.
    out.global = global_spectrum(mesh, out.axis_gap, options);
    if (options.regions) {
      out.mesh = mesh;
      out.original_vertex.resize(at(mesh.num_vertices()));
      std::iota(out.original_vertex.begin(), out.original_vertex.end(), Index{0});
    }
    return out;
  }
  CanonicalCopy canonical = canonical_copy(mesh, frame);
  // The whole surface's values from the canonical copy, whatever its size
  // and the regions option: they do not depend on the fine copy below.
  out.global = global_spectrum(canonical.mesh, out.axis_gap, options);
  if (!options.regions) return out;
  if (mesh.num_vertices() > options.fine_vertices) {
    MeshVariant fine = fine_copy(canonical.mesh, options);
    out.mesh = std::move(fine.mesh);
    for (const Index v : fine.original_vertex) out.original_vertex.push_back(canonical.original_vertex[at(v)]);
  } else {
    out.mesh = std::move(canonical.mesh);
    out.original_vertex = std::move(canonical.original_vertex);
  }
  return out;
}

SurfaceSpectra surface_spectra(const Mesh& mesh, const std::vector<Index>& vertex_region, Index regions,
                               const SpectraOptions& options) {
  return surface_spectra(mesh, spectra_surface(mesh, options), vertex_region, regions, options);
}

SurfaceSpectra surface_spectra(const Mesh& mesh, const SpectraSurface& prepared,
                               const std::vector<Index>& vertex_region, Index regions, const SpectraOptions& options) {
  const std::string where = mesh.source.empty() ? std::string("mesh in memory") : mesh.source;
  if (vertex_region.size() != at(mesh.num_vertices()))
    throw InvalidArgument("surface_spectra: " + where + ": " + std::to_string(vertex_region.size()) +
                          " region labels for " + std::to_string(mesh.num_vertices()) + " vertices");
  if (prepared.input_vertices != mesh.num_vertices() ||
      prepared.global.size() != at(kGlobalSpectrumLength + kGlobalHeatLength))
    throw InvalidArgument("surface_spectra: " + where + ": a spectra surface of a mesh of " +
                          std::to_string(prepared.input_vertices) + " vertices for one of " +
                          std::to_string(mesh.num_vertices()) + ", or not made by spectra_surface");
  for (const Index r : vertex_region)
    if (r < 0 || r >= regions)
      throw InvalidArgument("surface_spectra: " + where + ": region label " + std::to_string(r) + " outside [0, " +
                            std::to_string(regions) + ")");
  check_options(options);
  if (options.regions && prepared.mesh.num_vertices() == 0)
    throw InvalidArgument("surface_spectra: " + where +
                          ": the regions' spectra asked of a spectra surface prepared without them");
  const int n = kRegionSpectrumLength;
  SurfaceSpectra out;
  out.global = prepared.global;
  out.region.assign(at(regions) * at(n), 0.0);
  if (!options.regions) return out;
  const Mesh& surface = prepared.mesh;
  // Each region's triangles (those with at least two corners in it) and its
  // share of the area, counted on the surface before any decimation, so that
  // the decision below does not move with it.
  std::vector<Index> surface_region(at(surface.num_vertices()));
  for (Index v = 0; v < surface.num_vertices(); ++v)
    surface_region[at(v)] = vertex_region[at(prepared.original_vertex[at(v)])];
  std::vector<std::vector<Index>> region_triangles(at(regions));
  for (Index t = 0; t < surface.num_triangles(); ++t) {
    const Index r = triangle_region(surface, surface_region, t);
    if (r != kInvalidIndex) region_triangles[at(r)].push_back(t);
  }
  const Mesh& measured = prepared.decimated() ? mesh : surface;
  const std::vector<Index>& measured_region = prepared.decimated() ? vertex_region : surface_region;
  std::vector<double> region_area(at(regions), 0.0);
  double total_area = 0.0;
  for (Index t = 0; t < measured.num_triangles(); ++t) {
    const double area = triangle_area(measured, t);
    total_area += area;
    const Index r = triangle_region(measured, measured_region, t);
    if (r != kInvalidIndex) region_area[at(r)] += area;
  }

  const double region_ratio = coarse_ratio(surface, prepared.axis_gap, options.coarse_vertices, options);
  std::vector<Index> renumber(at(surface.num_vertices()), kInvalidIndex);
  ShapeDnaOptions local;
  local.eigenvalues = n;
  local.margin = 2;                 // a part of a shape has no symmetry to make its eigenvalues multiple
  local.intrinsic_delaunay = true;  // as the whole surface's
  for (Index r = 0; r < regions; ++r) {
    if (!(region_area[at(r)] >= options.min_region_area * total_area) || region_area[at(r)] == 0.0) continue;
    // Cut from the surface before its decimation, then coarsened at the regions' ratio: a
    // border cut from the coarse copy would zig-zag with the collapses.
    const Mesh part = coarsened(largest_piece(submesh(surface, region_triangles[at(r)], renumber)), region_ratio);
    if (part.num_vertices() < n + 2) continue;
    try {
      squash(shape_dna(part, local), n, out.region.data() + at(r) * at(n));
    } catch (const InvalidMeshError&) {
      // Left at zero: a region the operator cannot take (a strip of
      // degenerate triangles) says nothing about its shape.
    }
  }
  return out;
}

}  // namespace reebkit

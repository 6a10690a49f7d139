#include "reebkit/attributes/region_spectra.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/decimation.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/shape_dna.h"

#include <algorithm>
#include <cmath>
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

/// The triangles of `mesh` that belong to `region` (at least two corners
/// labelled so), as a mesh of their own (vertices renumbered).
Mesh region_mesh(const Mesh& mesh, const std::vector<Index>& label, Index region, std::vector<Index>& renumber) {
  Mesh out;
  out.source = mesh.source;
  std::vector<Index> corners;
  Index count = 0;
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    int inside = 0;
    for (int c = 0; c < 3; ++c) inside += label[at(mesh.triangles(t, c))] == region;
    if (inside < 2) continue;
    for (int c = 0; c < 3; ++c) {
      Index& v = renumber[at(mesh.triangles(t, c))];
      if (v == kInvalidIndex) v = count++;
      corners.push_back(v);
    }
  }
  out.vertices.resize(count, 3);
  out.triangles.resize(static_cast<Index>(corners.size() / 3), 3);
  for (std::size_t i = 0; i < corners.size(); ++i) out.triangles(static_cast<Index>(i / 3), static_cast<Index>(i % 3)) = corners[i];
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    if (renumber[at(v)] != kInvalidIndex) {
      out.vertices.row(renumber[at(v)]) = mesh.vertices.row(v);
      renumber[at(v)] = kInvalidIndex;  // ready for the next region
    }
  return out;
}

/// The connected piece of `part` with the largest area: the copy's
/// triangles near a region's border may cut it into pieces (a thin bridge of
/// triangles with two corners outside), and each further piece would add a
/// zero eigenvalue, shifting the spectrum by one.
Mesh largest_piece(const Mesh& part) {
  const ComponentLabels pieces = connected_components(part.triangles, part.num_vertices());
  if (pieces.count <= 1) return part;
  std::vector<double> area(at(pieces.count), 0.0);
  for (Index t = 0; t < part.num_triangles(); ++t) area[at(pieces.vertex_component[at(part.triangles(t, 0))])] += triangle_area(part, t);
  const Index keep = static_cast<Index>(std::max_element(area.begin(), area.end()) - area.begin());
  std::vector<Index> label(at(part.num_vertices()));
  for (Index v = 0; v < part.num_vertices(); ++v) label[at(v)] = pieces.vertex_component[at(v)] == keep ? 0 : 1;
  std::vector<Index> renumber(at(part.num_vertices()), kInvalidIndex);
  return region_mesh(part, label, 0, renumber);
}

}  // namespace

SurfaceSpectra surface_spectra(const Mesh& mesh, const std::vector<Index>& vertex_region, Index regions,
                               const SpectraOptions& options) {
  const std::string where = mesh.source.empty() ? std::string("mesh in memory") : mesh.source;
  if (vertex_region.size() != at(mesh.num_vertices()))
    throw InvalidArgument("surface_spectra: " + where + ": " + std::to_string(vertex_region.size()) +
                          " region labels for " + std::to_string(mesh.num_vertices()) + " vertices");
  for (const Index r : vertex_region)
    if (r < 0 || r >= regions)
      throw InvalidArgument("surface_spectra: " + where + ": region label " + std::to_string(r) + " outside [0, " +
                            std::to_string(regions) + ")");
  if (options.coarse_vertices < 100 || !(options.min_region_area >= 0.0 && options.min_region_area <= 1.0))
    throw InvalidArgument("surface_spectra: options out of range (coarse_vertices >= 100, min_region_area in [0, 1])");
  // Each region's share of the area, its triangles counted as region_mesh counts them.
  std::vector<double> region_area(at(regions), 0.0);
  double total_area = 0.0;
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const double area = triangle_area(mesh, t);
    total_area += area;
    const Index a = vertex_region[at(mesh.triangles(t, 0))], b = vertex_region[at(mesh.triangles(t, 1))],
                c = vertex_region[at(mesh.triangles(t, 2))];
    if (a == b || a == c) region_area[at(a)] += area;
    else if (b == c) region_area[at(b)] += area;
  }

  // The coarse copy: the surface decimated to about coarse_vertices.
  const double ratio = std::min(1.0, static_cast<double>(options.coarse_vertices) / static_cast<double>(mesh.num_vertices()));
  // (A piece whose decimation leaves a triangle it cannot repair is used as
  // it is: slower, not wrong.)
  const auto coarsened = [ratio](const Mesh& m) {
    if (ratio >= 1.0) return m;
    try {
      return decimate_mesh(m, {ratio, 0.05}).mesh;
    } catch (const InvalidMeshError&) {
      return m;
    }
  };
  const Mesh coarse = coarsened(mesh);

  SurfaceSpectra out;
  out.global.assign(at(kGlobalSpectrumLength), 0.0);
  ShapeDnaOptions global;
  global.eigenvalues = kGlobalSpectrumLength;
  global.margin = 4;
  // The coarse copy; where the operator or the iterations cannot take it,
  // the surface as given; where they cannot take that either (a handful of
  // vertices), zeros, as for a region too small.
  for (const Mesh* surface : {&coarse, &mesh}) {
    try {
      squash(shape_dna(*surface, global), kGlobalSpectrumLength, out.global.data());
      break;
    } catch (const InvalidMeshError&) {
    }
  }

  const int n = kRegionSpectrumLength;
  out.region.assign(at(regions) * at(n), 0.0);
  std::vector<Index> renumber(at(mesh.num_vertices()), kInvalidIndex);
  ShapeDnaOptions local;
  local.eigenvalues = n;
  local.margin = 2;  // a part of a shape has no symmetry to make its eigenvalues multiple
  for (Index r = 0; r < regions; ++r) {
    if (!(region_area[at(r)] >= options.min_region_area * total_area) || region_area[at(r)] == 0.0) continue;
    // Cut from the surface as given, then coarsened at the same ratio: a
    // border cut from the coarse copy would zig-zag with the collapses.
    const Mesh part = coarsened(largest_piece(region_mesh(mesh, vertex_region, r, renumber)));
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

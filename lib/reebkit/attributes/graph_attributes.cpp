// Geometric attributes of the high level Reeb graph (Tierny et al. 2006,
// section 5.3: "those graphs can be extended with geometrical attributes and
// shape comparison can be achieved with graph matching algorithms").
//
// Choices (docs/method.md, "Graph attributes"):
// - Areas and vertex shares count the surface as read (original_surface):
//   the fans fill_holes adds are left out. Geodesics, level lines and region
//   borders run on the analyzed, hole-filled mesh, where level lines are
//   closed curves, as f_q and the graph were computed there.
// - Geodesic extent of a region: the eccentricity of its highest vertex
//   (largest f_q, then largest id; a leaf's feature point), the largest
//   shortest-path distance from it to a vertex of the region, paths kept to
//   the region and its one-ring (GeodesicOptions::labels), by the method of
//   the feature points (FeaturePoints::geodesic). For a leaf, the
//   length of the protrusion from tip to attach loop, whatever its pose. A
//   region absorbed in several pieces (a line living between two close
//   events takes scattered vertices) gets its largest piece's value. One
//   search per piece, about one geodesic pass over the mesh in all (a double
//   sweep for the region's diameter would double the cost and depend on a
//   local optimum). Divided by the diameter of the feature point search
//   (FeaturePoints::diameter, section 4.1.2).
// - Mean radius: the exact piecewise-linear isocontours f_q = c of the
//   region at kLevels levels c_k = fq_min + (k + 1/2) span / kLevels; a
//   triangle crossing c_k adds its segment times the share of its vertices in
//   the region (one third per vertex, as ReebNode::area), so triangles on a
//   region border are split between the regions like their area. The mean of
//   length / (2 pi) over the levels, divided by sqrt(mesh area); the radius
//   profile keeps the kLevels values.
// - Shape histogram of a region: D2 (Osada et al. 2002) restricted to it,
//   from kShapeSamples random points drawn by area (a triangle on a border
//   split between regions like its area), distances / sqrt(region area);
//   the signature's global D2 is the same on the whole surface. A fixed
//   seed per region keeps the result a function of the mesh. Both follow
//   the pose: a limb that turns changes the distances between its points
//   and the rest.
// - Geodesic histogram of a region, its intrinsic counterpart: the area of
//   the region (one third of each triangle per vertex, as ReebNode::area)
//   by geodesic distance from its highest vertex, from the searches that
//   measure the geodesic extent (no other geodesic pass), / sqrt(region
//   area). Geodesic distances, hence the histogram, do not change when the
//   surface bends without stretching (the isometries under which the paper
//   builds f_q, section 4.1).
// - The main axis: the geodesic distance fields d1, d2 from the diameter
//   ends v_s1, v_s2 of the feature point search (section 4.1.2, eqs. 2-4),
//   D = d1(v_s2). A vertex's axis position |d1 - d2| / D and axis offset
//   (d1 + d2 - D) / D locate it on the surface whatever the pose: along the
//   longest geodesic and away from it (for a path graph, the two coordinates
//   of the bipolar parameterization). Both are symmetric in the two ends,
//   whose order is arbitrary. The signature's global geodesic histogram is
//   their distribution over the surface, by area. No geodesic pass: d1 and
//   d2 are the feature point search's f1 and f2 (FeaturePoints::f1, f2).
// - Boundary length of an edge (a, b): the curve joining the midpoints of the
//   mesh edges from a vertex of a to a vertex of b (through the centroid in a
//   triangle with three regions), the discrete border between the two
//   regions, divided by sqrt(mesh area). Zero when the regions do not touch
//   (a node without vertices). Event f_q: f_q of the later node's birth
//   vertex, v_t of the step where the two regions meet.
#include "reebkit/attributes/graph_attributes.h"

#include "reebkit/attributes/region_spectra.h"
#include "reebkit/core/error.h"
#include "reebkit/core/parallel.h"
#include "reebkit/geodesic/geodesic_solver.h"
#include "reebkit/mesh/hole_filling.h"
#include "reebkit/mesh/surface_sampling.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

namespace reebkit {

namespace {

constexpr int kLevels = kRadiusProfileLevels;    // level lines per region for kNodeMeanRadius
constexpr int kShapeSamples = 128;               // random points per region for kNodeShapeHistogram
constexpr double kShapeBinWidth = 0.2;           // of distance / sqrt(region area)
constexpr double kGeodesicBinWidth = 0.25;       // of geodesic distance / sqrt(region area), kNodeGeodesicHistogram
constexpr int kAxisBins = kGlobalShapeBins / 2;  // of each half of the global geodesic histogram
constexpr double kAxisPositionBinWidth = 1.0 / kAxisBins;  // of |d1 - d2| / D
constexpr double kAxisOffsetBinWidth = 0.5 / kAxisBins;    // of (d1 + d2 - D) / D
constexpr int kGlobalShapeSamples = 512;                   // random points of the whole surface for its D2
constexpr double kGlobalShapeBinWidth = 0.15;              // of distance / sqrt(mesh area)
constexpr int kLeafSlots = 6;                              // largest leaves listed in the signature
constexpr int kAreaBins = 6;                               // histogram of node relative areas
constexpr int kEigenvalues = 8;                            // normalized Laplacian eigenvalues 2 .. 9
constexpr double kCountScale = 8.0;                        // counts c enter as log2(1 + c) / 8 (1 at c = 255)

// Signature layout (kSignatureNames lists the same order).
constexpr int kSigCounts = 0;  // nodes, leaves, bifurcation starts, junction starts, cycles
constexpr int kSigRootArea = 5;
constexpr int kSigLeafArea = 6;
constexpr int kSigLeafExtent = kSigLeafArea + kLeafSlots;
constexpr int kSigAreaHistogram = kSigLeafExtent + kLeafSlots;
constexpr int kSigEigenvalues = kSigAreaHistogram + kAreaBins;
static_assert(kSigEigenvalues + kEigenvalues == kSigGlobalShape &&
                  kSigGlobalShape + kGlobalShapeBins == kSigGlobalGeodesic,
              "signature layout must fill kSignatureLength");

/// Upper ends of the relative area bins but the last: half decades, so that
/// finger tips (~1e-3) and torsos (> 0.1) land in different bins.
constexpr std::array<double, kAreaBins - 1> kAreaBinEnds = {1e-3, 3.1622776601683795e-3, 1e-2, 3.1622776601683795e-2,
                                                            1e-1};

std::size_t at(Index i) { return static_cast<std::size_t>(i); }

Vec3 point(const Mesh& mesh, Index v) { return mesh.vertices.row(v).transpose(); }

/// Where f = c on the mesh edge (i, j), f(i) != f(j).
Vec3 crossing(const Mesh& mesh, const std::vector<double>& f, Index i, Index j, double c) {
  const double t = (c - f[at(i)]) / (f[at(j)] - f[at(i)]);
  return point(mesh, i) + t * (point(mesh, j) - point(mesh, i));
}

/// The regions of a triangle's vertices (`label`), each once, with its share
/// of the triangle (its vertices / 3, as ReebNode::area splits areas):
/// visit(node, share).
template <class Visit>
void for_each_region(const std::array<Index, 3>& label, Visit&& visit) {
  for (int i = 0; i < 3; ++i) {
    const Index node = label[at(i)];
    if ((i > 0 && node == label[0]) || (i > 1 && node == label[1])) continue;  // counted already
    visit(node, static_cast<double>(std::count(label.begin(), label.end(), node)) / 3.0);
  }
}

/// The regions of triangle t's vertices.
std::array<Index, 3> triangle_labels(const Mesh& mesh, const ReebGraph& reeb, Index t) {
  return {reeb.vertex_node[at(mesh.triangles(t, 0))], reeb.vertex_node[at(mesh.triangles(t, 1))],
          reeb.vertex_node[at(mesh.triangles(t, 2))]};
}

/// Whether triangle t is part of the surface as read (not a fan hole filling added).
bool is_original(const Mesh& mesh, Index t, Index original_vertices) {
  return mesh.triangles(t, 0) < original_vertices && mesh.triangles(t, 1) < original_vertices &&
         mesh.triangles(t, 2) < original_vertices;
}

/// Adds `weight` to the histogram h of `bins` bins (the first centred at
/// 0.5, bin widths 1) at x >= 0, split linearly between the two nearest
/// bin centres so that the histogram moves continuously with x (x beyond
/// the last centre goes to the last bin).
void add_to_histogram(double* h, int bins, double x, double weight) {
  const double y = std::clamp(x - 0.5, 0.0, bins - 1.0);
  const int b = std::min(static_cast<int>(y), bins - 2);
  h[b] += weight * (b + 1 - y);
  h[b + 1] += weight * (y - b);
}

/// Geodesic extent and geodesic histogram of every region (see the file
/// comment); `vertex_area` and `node_area` weigh the vertices and the regions.
RegionGeodesics region_geodesics(GeodesicSolver& solver, const std::vector<double>& f, const ReebGraph& reeb,
                                 const std::vector<double>& vertex_area, const std::vector<double>& node_area) {
  const MeshGraph& graph = solver.graph();
  const Index n = graph.num_vertices();
  // Vertices grouped by region (counting sort), ascending ids within a region.
  std::vector<Index> first(reeb.nodes.size() + 1, 0);
  for (const Index node : reeb.vertex_node) ++first[at(node) + 1];
  for (std::size_t k = 1; k < first.size(); ++k) first[k] += first[k - 1];
  std::vector<Index> members(at(n));
  std::vector<Index> fill(first.begin(), first.end() - 1);
  for (Index v = 0; v < n; ++v) members[at(fill[at(reeb.vertex_node[at(v)])]++)] = v;

  RegionGeodesics out;
  std::vector<double>& extent = out.extent;
  extent.assign(reeb.nodes.size(), 0.0);
  out.histogram.assign(reeb.nodes.size() * kShapeBins, 0.0);
  std::vector<std::uint8_t> done(at(n), 0);
  // stamp[v] == node: v is in the region of node or next to it, where the
  // searches for node may go.
  std::vector<Index> stamp(at(n), kInvalidIndex);
  std::vector<Index> source(1);
  GeodesicOptions options;
  options.labels = &stamp;
  for (Index node = 0; node < reeb.num_nodes(); ++node) {
    options.label = node;
    double* histogram = out.histogram.data() + at(node) * kShapeBins;
    const double area = node_area[at(node)];
    const double bin = area > 0.0 ? 1.0 / (kGeodesicBinWidth * std::sqrt(area)) : 0.0;
    const Index* begin = members.data() + first[at(node)];
    const Index* end = members.data() + first[at(node) + 1];
    for (const Index* v = begin; v != end; ++v) {
      stamp[at(*v)] = node;
      for (Index i = graph.offset[at(*v)]; i < graph.offset[at(*v) + 1]; ++i) stamp[at(graph.neighbor[at(i)])] = node;
    }
    while (true) {
      // A piece of the region not measured yet, from its highest vertex.
      source[0] = kInvalidIndex;
      for (const Index* v = begin; v != end; ++v)
        if (!done[at(*v)] && (source[0] == kInvalidIndex || f[at(*v)] >= f[at(source[0])])) source[0] = *v;
      if (source[0] == kInvalidIndex) break;
      const DistanceField& field = solver.run(source, options);
      // Vertices settle by distance: the last region vertex is the farthest.
      const auto& settled = solver.settled();
      const auto far =
          std::find_if(settled.rbegin(), settled.rend(), [&](Index w) { return reeb.vertex_node[at(w)] == node; });
      extent[at(node)] = std::max(extent[at(node)], field.distance[at(*far)]);
      for (const Index w : settled)
        if (reeb.vertex_node[at(w)] == node) {
          done[at(w)] = 1;
          if (area > 0.0)
            add_to_histogram(histogram, kShapeBins, field.distance[at(w)] * bin, vertex_area[at(w)] / area);
        }
    }
  }
  return out;
}

TriangleSums triangle_sums(const Mesh& mesh, Index original_vertices, const std::vector<double>& f,
                           const ReebGraph& reeb) {
  TriangleSums sums;
  sums.vertex_area.assign(at(mesh.num_vertices()), 0.0);
  sums.node_area.assign(reeb.nodes.size(), 0.0);
  sums.level_length.assign(reeb.nodes.size() * kLevels, 0.0);
  sums.border_length.assign(reeb.edges.size(), 0.0);
  const auto add_border = [&](Index a, Index b, double length) {
    const std::array<Index, 2> key = {std::min(a, b), std::max(a, b)};
    const auto it = std::lower_bound(reeb.edges.begin(), reeb.edges.end(), key);
    if (it != reeb.edges.end() && *it == key)
      sums.border_length[static_cast<std::size_t>(it - reeb.edges.begin())] += length;
  };
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const std::array<Index, 3> v = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    const std::array<Index, 3> label = triangle_labels(mesh, reeb, t);
    if (is_original(mesh, t, original_vertices)) {
      const double area = triangle_area(mesh, t);
      sums.total_area += area;
      for (const Index node : label) sums.node_area[at(node)] += area / 3.0;
      for (const Index u : v) sums.vertex_area[at(u)] += area / 3.0;
    }
    const double lo = std::min({f[at(v[0])], f[at(v[1])], f[at(v[2])]});
    const double hi = std::max({f[at(v[0])], f[at(v[1])], f[at(v[2])]});

    // Level lines: each region present in the triangle, at its levels in [lo, hi).
    for_each_region(label, [&](Index node, double share) {
      const ReebNode& region = reeb.nodes[at(node)];
      const double step = (region.fq_max - region.fq_min) / kLevels;
      if (!(step > 0.0) || hi <= lo) return;
      const int k_lo = std::max(0, static_cast<int>(std::floor((lo - region.fq_min) / step - 0.5)));
      const int k_hi = std::min(kLevels - 1, static_cast<int>(std::ceil((hi - region.fq_min) / step - 0.5)));
      for (int k = k_lo; k <= k_hi; ++k) {
        const double c = region.fq_min + (k + 0.5) * step;
        if (!(lo <= c && c < hi)) continue;  // a vertex with f = c counts as below c
        // The vertex alone on its side of c, and the other two.
        const bool above0 = f[at(v[0])] > c, above1 = f[at(v[1])] > c;
        const int lone = above0 == above1 ? 2 : (above0 == (f[at(v[2])] > c) ? 1 : 0);
        const Index a = v[at(lone)], b = v[at((lone + 1) % 3)], d = v[at((lone + 2) % 3)];
        sums.level_length[at(node) * kLevels + static_cast<std::size_t>(k)] +=
            share * (crossing(mesh, f, a, b, c) - crossing(mesh, f, a, d, c)).norm();
      }
    });

    // Borders: midpoint segments between the regions of the triangle.
    if (label[0] == label[1] && label[1] == label[2]) continue;
    if (label[0] != label[1] && label[1] != label[2] && label[0] != label[2]) {
      const Vec3 centroid = (point(mesh, v[0]) + point(mesh, v[1]) + point(mesh, v[2])) / 3.0;
      for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t j = (i + 1) % 3;
        add_border(label[i], label[j], (0.5 * (point(mesh, v[i]) + point(mesh, v[j])) - centroid).norm());
      }
      continue;
    }
    // Two regions: the segment between the midpoints of the two crossing
    // edges is half the edge opposite the lone vertex.
    const std::size_t lone = label[0] == label[1] ? 2 : (label[0] == label[2] ? 1 : 0);
    const std::size_t j = (lone + 1) % 3, k = (lone + 2) % 3;
    add_border(label[lone], label[j], 0.5 * (point(mesh, v[j]) - point(mesh, v[k])).norm());
  }
  return sums;
}

/// Adds to h (bins of `bin_width`, the first centred at bin_width / 2) the
/// Euclidean distances between all pairs of `samples` random points of
/// `from`, divided by sqrt(its total weight): the D2 shape distribution of
/// Osada et al. 2002. Each distance is split linearly between the two
/// nearest bin centres, so that the histogram moves continuously with the
/// distances (exact similarity invariance); the result sums to 1.
void shape_distribution(const Mesh& mesh, const WeightedTriangles& from, int samples, double bin_width,
                        std::uint64_t seed, double* h, int bins) {
  std::fill_n(h, bins, 0.0);
  if (!(from.total() > 0.0) || samples < 2) return;
  const std::vector<Vec3> points = sample_surface(mesh, from, samples, seed);
  const double scale = 1.0 / (bin_width * std::sqrt(from.total()));
  const double pair_weight = 1.0 / (samples * (samples - 1) / 2.0);
  for (int i = 0; i < samples; ++i)
    for (int j = i + 1; j < samples; ++j)
      add_to_histogram(h, bins, (points[at(i)] - points[at(j)]).norm() * scale, pair_weight);
}

/// The signature's global geodesic histogram (kSigGlobalGeodesic, see the
/// file comment) into h.
void main_axis_histogram(const FeaturePoints& features, const TriangleSums& sums, double* h) {
  std::fill_n(h, kGlobalShapeBins, 0.0);
  const std::vector<double>& d1 = features.f1;
  const std::vector<double>& d2 = features.f2;
  const double diameter = d1[at(features.source2)];
  if (!(diameter > 0.0) || !(sums.total_area > 0.0)) return;
  for (std::size_t v = 0; v < d1.size(); ++v) {
    const double weight = 0.5 * sums.vertex_area[v] / sums.total_area;  // 0 for a vertex hole filling added
    if (!(weight > 0.0)) continue;
    const double position = std::abs(d1[v] - d2[v]) / diameter;
    const double offset = std::max(0.0, d1[v] + d2[v] - diameter) / diameter;
    add_to_histogram(h, kAxisBins, position / kAxisPositionBinWidth, weight);
    add_to_histogram(h + kAxisBins, kAxisBins, offset / kAxisOffsetBinWidth, weight);
  }
}

/// kNodeShapeHistogram of every region (#nodes x kShapeBins, row-major) and
/// the whole surface's D2 (kGlobalShapeBins) into `global`.
std::vector<double> shape_histograms(const Mesh& mesh, Index original_vertices, const ReebGraph& reeb, double* global) {
  // Each region's triangles (a triangle belongs to each region of its
  // vertices, weighted by area times its share of them), as cumulative
  // weights, grouped by region; the surface as read only.
  const std::size_t nodes = reeb.nodes.size();
  std::vector<std::size_t> first(nodes + 1, 0);
  std::vector<Index> triangles;
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    if (is_original(mesh, t, original_vertices)) triangles.push_back(t);
  const TriangleAreas whole = triangle_areas(mesh, std::move(triangles));
  const std::vector<Index>& original = whole.triangle;
  shape_distribution(mesh, whole.view(), kGlobalShapeSamples, kGlobalShapeBinWidth, 2006, global, kGlobalShapeBins);

  for (const Index t : original)
    for_each_region(triangle_labels(mesh, reeb, t), [&](Index node, double) { ++first[at(node) + 1]; });
  for (std::size_t k = 1; k <= nodes; ++k) first[k] += first[k - 1];
  std::vector<Index> triangle(first[nodes]);
  std::vector<double> cumulative(first[nodes]);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  std::vector<double> total(nodes, 0.0);
  for (const Index t : original)
    for_each_region(triangle_labels(mesh, reeb, t), [&](Index node, double share) {
      total[at(node)] += share * triangle_area(mesh, t);
      triangle[fill[at(node)]] = t;
      cumulative[fill[at(node)]++] = total[at(node)];
    });
  std::vector<double> histogram(nodes * kShapeBins, 0.0);
  for (std::size_t node = 0; node < nodes; ++node)
    shape_distribution(mesh,
                       {triangle.data() + first[node], cumulative.data() + first[node], first[node + 1] - first[node]},
                       kShapeSamples, kShapeBinWidth, 2006 + node, histogram.data() + node * kShapeBins, kShapeBins);
  return histogram;
}

/// log2(1 + count) / kCountScale.
double scaled_count(Index count) { return std::log2(1.0 + static_cast<double>(count)) / kCountScale; }

/// The k largest of `values` into `out` (descending, 0 where fewer).
void largest(std::vector<double> values, double* out, int k) {
  std::sort(values.begin(), values.end(), std::greater<>());
  for (int i = 0; i < k; ++i) out[i] = at(i) < values.size() ? values[at(i)] : 0.0;
}

/// Eigenvalues 2 .. kEigenvalues + 1 of the normalized graph Laplacian
/// I - D^-1/2 A D^-1/2 (in [0, 2]), halved; 0.5 (the mean eigenvalue) where
/// the graph has fewer nodes.
void laplacian_spectrum(const ReebGraph& reeb, const std::vector<double>& degree, double* out) {
  const Index n = reeb.num_nodes();
  Eigen::MatrixXd laplacian = Eigen::MatrixXd::Zero(n, n);
  for (Index i = 0; i < n; ++i) laplacian(i, i) = degree[at(i)] > 0 ? 1.0 : 0.0;
  for (const auto& [a, b] : reeb.edges) {
    const double w = -1.0 / std::sqrt(degree[at(a)] * degree[at(b)]);
    laplacian(a, b) = w;
    laplacian(b, a) = w;
  }
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(laplacian, Eigen::EigenvaluesOnly).eigenvalues();
  for (int i = 0; i < kEigenvalues; ++i) out[i] = i + 1 < n ? std::clamp(eigenvalues(i + 1), 0.0, 2.0) / 2.0 : 0.5;
}

/// The mesh's file, for error messages.
std::string where(const Mesh& mesh) { return mesh.source.empty() ? std::string("mesh in memory") : mesh.source; }

/// Throws InvalidArgument (its message starting with `caller`) unless reeb
/// has nodes and mesh, graph, f, the feature points' fields and
/// reeb.vertex_node agree in vertex count.
void check_inputs(const char* caller, const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                  const FeaturePoints& features, const ReebGraph& reeb) {
  const std::string prefix = std::string(caller) + ": " + where(mesh);
  if (reeb.nodes.empty())
    throw InvalidArgument(prefix + " has no Reeb graph (analyzed with AnalysisOptions::reeb_graph = false)");
  if (features.source1 < 0 || features.source1 >= mesh.num_vertices() || features.source2 < 0 ||
      features.source2 >= mesh.num_vertices())
    throw InvalidArgument(prefix + ": the feature points have no diameter ends in the mesh");
  if (reeb.vertex_node.size() != at(mesh.num_vertices()) || f.size() != at(mesh.num_vertices()) ||
      graph.num_vertices() != mesh.num_vertices() || features.f1.size() != at(mesh.num_vertices()) ||
      features.f2.size() != at(mesh.num_vertices()))
    throw InvalidArgument(prefix +
                          ": the mesh, its graph, f_q, the feature points' f1 and f2 and the segmentation differ in "
                          "vertex count");
}

RegionMeasures measured(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                        const FeaturePoints& features, const ReebGraph& reeb, GeodesicSolver* solver) {
  RegionMeasures out;
  const Index original_vertices = original_vertex_count(mesh);
  out.sums = triangle_sums(mesh, original_vertices, f, reeb);
  std::unique_ptr<GeodesicSolver> own;
  if (!solver) {
    own = make_geodesic_solver(graph, features.geodesic);
    solver = own.get();
  }
  out.geodesics = region_geodesics(*solver, f, reeb, out.sums.vertex_area, out.sums.node_area);
  out.global_shape.assign(kGlobalShapeBins, 0.0);
  out.shape = shape_histograms(mesh, original_vertices, reeb, out.global_shape.data());
  return out;
}

}  // namespace

RegionMeasures measure_regions(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                               const FeaturePoints& features, const ReebGraph& reeb, GeodesicSolver* solver) {
  check_inputs("measure_regions", mesh, graph, f, features, reeb);
  if (solver && (&solver->graph() != &graph || solver->method() != features.geodesic))
    throw InvalidArgument("measure_regions: " + where(mesh) +
                          ": a geodesic solver of another graph or method than the feature points'");
  return measured(mesh, graph, f, features, reeb, solver);
}

GraphAttributes compute_attributes(const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f,
                                   const FeaturePoints& features, const ReebGraph& reeb,
                                   const SpectraSurface* spectra_surface, const SpectraOptions& spectra_options,
                                   const RegionMeasures* prepared) {
  check_inputs("compute_attributes", mesh, graph, f, features, reeb);
  if (prepared && (prepared->sums.node_area.size() != reeb.nodes.size() ||
                   prepared->sums.border_length.size() != reeb.edges.size() ||
                   prepared->sums.vertex_area.size() != at(mesh.num_vertices())))
    throw InvalidArgument("compute_attributes: " + where(mesh) + ": region measures of another graph or mesh");
  const double geodesic_diameter = features.diameter;
  const Index original_vertices = original_vertex_count(mesh);
  // The spectra beside the region measures, unless these come prepared.
  RegionMeasures measures;
  SurfaceSpectra spectra;
  const auto spectra_of_regions = [&] {
    spectra = spectra_surface
                  ? surface_spectra(mesh, *spectra_surface, reeb.vertex_node, reeb.num_nodes(), spectra_options)
                  : surface_spectra(mesh, reeb.vertex_node, reeb.num_nodes(), spectra_options);
  };
  if (prepared)
    spectra_of_regions();
  else
    run_side_by_side(spectra_of_regions, [&] { measures = measured(mesh, graph, f, features, reeb, nullptr); });
  const RegionMeasures& m = prepared ? *prepared : measures;
  const TriangleSums& sums = m.sums;
  const RegionGeodesics& regions = m.geodesics;
  const std::vector<double>& shape = m.shape;
  const double length_unit = sums.total_area > 0.0 ? std::sqrt(sums.total_area) : 1.0;
  const double diameter = geodesic_diameter > 0.0 ? geodesic_diameter : 1.0;
  const auto relative = [](double value, double whole) { return whole > 0.0 ? value / whole : 0.0; };

  std::vector<Index> vertices(reeb.nodes.size(), 0);
  for (Index v = 0; v < original_vertices; ++v) ++vertices[at(reeb.vertex_node[at(v)])];
  std::vector<double> degree(reeb.nodes.size(), 0.0);
  for (const auto& [a, b] : reeb.edges) {
    ++degree[at(a)];
    ++degree[at(b)];
  }

  GraphAttributes out;
  out.node.resize(reeb.nodes.size() * kNodeAttributeCount);
  for (std::size_t i = 0; i < reeb.nodes.size(); ++i) {
    const ReebNode& node = reeb.nodes[i];
    double* row = out.node.data() + i * kNodeAttributeCount;
    double level_sum = 0.0;
    for (int k = 0; k < kLevels; ++k) level_sum += sums.level_length[i * kLevels + static_cast<std::size_t>(k)];
    row[kNodeRelativeArea] = relative(sums.node_area[i], sums.total_area);
    row[kNodeFqMin] = node.fq_min;
    row[kNodeFqMax] = node.fq_max;
    row[kNodeFqSpan] = node.fq_max - node.fq_min;
    row[kNodeGeodesicExtent] = regions.extent[i] / diameter;
    row[kNodeMeanRadius] = level_sum / kLevels / (2.0 * static_cast<double>(EIGEN_PI)) / length_unit;
    row[kNodeVertexShare] = relative(vertices[i], original_vertices);
    row[kNodeDegree] = degree[i];
    row[kNodeStartType] = static_cast<double>(node.type);
    row[kNodeEndType] = static_cast<double>(node.end);
    for (int k = 0; k < kLevels; ++k)
      row[kNodeRadiusProfile + k] = sums.level_length[i * kLevels + static_cast<std::size_t>(k)] /
                                    (2.0 * static_cast<double>(EIGEN_PI)) / length_unit;
    std::copy_n(shape.data() + i * kShapeBins, kShapeBins, row + kNodeShapeHistogram);
    std::copy_n(regions.histogram.data() + i * kShapeBins, kShapeBins, row + kNodeGeodesicHistogram);
    std::copy_n(spectra.region.data() + i * kRegionSpectrumLength, kRegionSpectrumLength, row + kNodeSpectrum);
  }
  out.edge.resize(reeb.edges.size() * kEdgeAttributeCount);
  for (std::size_t e = 0; e < reeb.edges.size(); ++e) {
    double* row = out.edge.data() + e * kEdgeAttributeCount;
    row[kEdgeBoundaryLength] = sums.border_length[e] / length_unit;
    row[kEdgeEventFq] = f[at(reeb.nodes[at(reeb.edges[e][1])].birth_vertex)];
  }

  // Signature.
  out.signature.assign(kSignatureLength, 0.0);
  double* sig = out.signature.data();
  const auto count_if = [&](auto predicate) {
    return static_cast<Index>(std::count_if(reeb.nodes.begin(), reeb.nodes.end(), predicate));
  };
  sig[kSigCounts + 0] = scaled_count(reeb.num_nodes());
  sig[kSigCounts + 1] = scaled_count(reeb.leaf_count());
  sig[kSigCounts + 2] = scaled_count(count_if([](const ReebNode& n) { return n.type == NodeType::Bifurcation; }));
  sig[kSigCounts + 3] = scaled_count(count_if([](const ReebNode& n) { return n.type == NodeType::Junction; }));
  sig[kSigCounts + 4] = scaled_count(reeb.independent_cycles());
  sig[kSigRootArea] = out.node[kNodeRelativeArea];
  std::vector<double> leaf_area, leaf_extent;
  for (std::size_t i = 0; i < reeb.nodes.size(); ++i) {
    const double* row = out.node.data() + i * kNodeAttributeCount;
    if (reeb.nodes[i].end == NodeType::Termination) {
      leaf_area.push_back(std::sqrt(row[kNodeRelativeArea]));
      leaf_extent.push_back(row[kNodeGeodesicExtent]);
    }
    const auto bin = std::upper_bound(kAreaBinEnds.begin(), kAreaBinEnds.end(), row[kNodeRelativeArea]);
    sig[kSigAreaHistogram + (bin - kAreaBinEnds.begin())] += 1.0 / static_cast<double>(reeb.nodes.size());
  }
  largest(std::move(leaf_area), sig + kSigLeafArea, kLeafSlots);
  largest(std::move(leaf_extent), sig + kSigLeafExtent, kLeafSlots);
  laplacian_spectrum(reeb, degree, sig + kSigEigenvalues);
  std::copy(m.global_shape.begin(), m.global_shape.end(), sig + kSigGlobalShape);
  main_axis_histogram(features, sums, sig + kSigGlobalGeodesic);
  std::copy(spectra.global.begin(), spectra.global.end(), sig + kSigGlobalSpectrum);
  return out;
}

}  // namespace reebkit

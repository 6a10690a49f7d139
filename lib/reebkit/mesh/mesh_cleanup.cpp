#include "reebkit/mesh/mesh_cleanup.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/mesh_topology.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <tuple>
#include <utility>

namespace reebkit {

namespace {

Vec3 point(const Points& points, Index v) { return points.row(v).transpose(); }

std::string source_label(const std::string& source) { return source.empty() ? "<memory>" : source; }

std::string count_of(Index n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

std::string percent(double part, double whole) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", whole > 0 ? 100.0 * part / whole : 0.0);
  return text;
}

/// Throws InvalidMeshError unless the soup has vertices, polygons, finite
/// coordinates and in-range indices (InvalidArgument for a malformed CSR).
void check_soup(const PolygonSoup& soup) {
  if (soup.face_offset.empty() || soup.face_offset.front() != 0 ||
      soup.face_offset.back() != static_cast<Index>(soup.face_vertex.size()) ||
      !std::is_sorted(soup.face_offset.begin(), soup.face_offset.end()))
    throw InvalidArgument("clean_mesh(" + source_label(soup.source) +
                          "): face_offset is not a CSR offset array over face_vertex");
  const Index num_vertices = soup.num_vertices();
  if (num_vertices == 0) throw InvalidMeshError(soup.source, "no vertices: the file holds no vertices");
  if (soup.num_polygons() == 0)
    throw InvalidMeshError(soup.source, "no faces: the file holds " + count_of(num_vertices, "vertex", "vertices") +
                                            " and no polygons (a point cloud?)");
  // Each check one flat pass, then the search for what failed, where one did.
  bool finite = true;
  for (Eigen::Index i = 0; i < soup.vertices.size(); ++i) finite &= std::isfinite(soup.vertices.data()[i]);
  if (!finite)
    for (Index v = 0; v < num_vertices; ++v) {
      if (soup.vertices.row(v).allFinite()) continue;
      std::ostringstream problem;
      problem << "vertex " << v << " has a non-finite coordinate (" << soup.vertices(v, 0) << ", "
              << soup.vertices(v, 1) << ", " << soup.vertices(v, 2) << ")";
      throw InvalidMeshError(soup.source, problem.str());
    }
  bool in_range = true;
  for (const Index v : soup.face_vertex) in_range &= v >= 0 && v < num_vertices;
  if (in_range) return;
  for (Index p = 0; p < soup.num_polygons(); ++p) {
    for (Index i = soup.face_offset[p]; i < soup.face_offset[p + 1]; ++i) {
      const Index v = soup.face_vertex[i];
      if (v < 0 || v >= num_vertices)
        throw InvalidMeshError(soup.source, "polygon " + std::to_string(p) + " refers to vertex " + std::to_string(v) +
                                                ", but there are " + count_of(num_vertices, "vertex", "vertices"));
    }
  }
}

/// representative[v] = smallest vertex at exactly v's position (== on each
/// coordinate). Returns the number of vertices mapped to another one.
Index merge_coincident(const Points& vertices, std::vector<Index>& representative) {
  std::vector<Index> order(representative.size());
  std::iota(order.begin(), order.end(), Index{0});
  const auto position = [&](Index v) { return std::make_tuple(vertices(v, 0), vertices(v, 1), vertices(v, 2)); };
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return std::make_pair(position(a), a) < std::make_pair(position(b), b); });
  Index merged = 0;
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (position(order[i]) != position(order[i - 1])) continue;
    representative[order[i]] = representative[order[i - 1]];
    ++merged;
  }
  return merged;
}

/// Triangles added row by row to storage sized once for the most a soup can
/// give (n - 2 per polygon of n corners), so that the mesh takes them without
/// a copy.
class TriangleRows {
 public:
  explicit TriangleRows(Index capacity) : rows_(capacity, 3) {}
  void add(Index a, Index b, Index c) {
    Index* row = rows_.data() + 3 * static_cast<std::size_t>(size_++);
    row[0] = a;
    row[1] = b;
    row[2] = c;
  }
  /// The rows added; the storage shrinks to them.
  Triangles take() {
    rows_.conservativeResize(size_, 3);
    return std::move(rows_);
  }

 private:
  Triangles rows_;
  Index size_ = 0;
};

/// Ear clipping of one polygon in the plane of its Newell normal. Scratch
/// buffers are members so that a soup of many polygons allocates once.
class PolygonTriangulator {
 public:
  /// Appends the n - 2 triangles of `polygon` (n >= 3 distinct vertices) to
  /// `out`, each in the polygon's orientation.
  void triangulate(const std::vector<Index>& polygon, const Points& points, TriangleRows& out) {
    const auto n = static_cast<Index>(polygon.size());
    if (n == 3 || !project(polygon, points) || is_strictly_convex()) {
      for (Index i = 1; i + 1 < n; ++i) out.add(polygon[0], polygon[i], polygon[i + 1]);
      return;
    }
    next_.resize(polygon.size());
    prev_.resize(polygon.size());
    for (Index i = 0; i < n; ++i) {
      next_[i] = (i + 1) % n;
      prev_[i] = (i + n - 1) % n;
    }
    Index corner = 0;
    Index misses = 0;  // consecutive corners that were not ears
    for (Index remaining = n; remaining > 3;) {
      // No ear in a whole round (a self-overlapping projection): clip anyway.
      if (is_ear(corner) || misses > remaining) {
        out.add(polygon[prev_[corner]], polygon[corner], polygon[next_[corner]]);
        next_[prev_[corner]] = next_[corner];
        prev_[next_[corner]] = prev_[corner];
        corner = next_[corner];
        --remaining;
        misses = 0;
      } else {
        corner = next_[corner];
        ++misses;
      }
    }
    out.add(polygon[prev_[corner]], polygon[corner], polygon[next_[corner]]);
  }

 private:
  /// 2D coordinates in the plane most orthogonal to the Newell normal,
  /// oriented so that the polygon turns counter-clockwise. False when the
  /// polygon has no area (any triangulation is as good as any other).
  bool project(const std::vector<Index>& polygon, const Points& points) {
    Vec3 normal = Vec3::Zero();
    for (std::size_t i = 0; i < polygon.size(); ++i)
      normal += point(points, polygon[i]).cross(point(points, polygon[(i + 1) % polygon.size()]));
    Eigen::Index axis = 0;
    if (normal.cwiseAbs().maxCoeff(&axis) == 0) return false;
    int u = static_cast<int>(axis + 1) % 3;
    int v = static_cast<int>(axis + 2) % 3;
    if (normal[axis] < 0) std::swap(u, v);
    xy_.resize(polygon.size());
    for (std::size_t i = 0; i < polygon.size(); ++i) xy_[i] = {points(polygon[i], u), points(polygon[i], v)};
    return true;
  }

  /// Twice the signed area of the 2D triangle (a, b, c); > 0 when counter-clockwise.
  double turn(Index a, Index b, Index c) const {
    return (xy_[b][0] - xy_[a][0]) * (xy_[c][1] - xy_[a][1]) - (xy_[b][1] - xy_[a][1]) * (xy_[c][0] - xy_[a][0]);
  }

  /// Every corner turns left, so a fan has no flipped or flat triangle.
  bool is_strictly_convex() const {
    const auto n = static_cast<Index>(xy_.size());
    for (Index i = 0; i < n; ++i)
      if (turn((i + n - 1) % n, i, (i + 1) % n) <= 0) return false;
    return true;
  }

  /// A strictly convex corner whose triangle holds no other remaining corner
  /// (on its border counts as inside).
  bool is_ear(Index corner) const {
    const Index a = prev_[corner];
    const Index c = next_[corner];
    if (turn(a, corner, c) <= 0) return false;
    for (Index r = next_[c]; r != a; r = next_[r])
      if (turn(a, corner, r) >= 0 && turn(corner, c, r) >= 0 && turn(c, a, r) >= 0) return false;
    return true;
  }

  std::vector<std::array<double, 2>> xy_;
  std::vector<Index> next_;
  std::vector<Index> prev_;
};

/// Triangles of the soup after welding, collapsing and degenerate removal, in
/// file order.
Triangles triangulate_soup(const PolygonSoup& soup, const std::vector<Index>& representative, CleanupReport& report) {
  Index most = 0;  // n - 2 per polygon of n >= 3 corners
  for (Index p = 0; p < soup.num_polygons(); ++p)
    most += std::max<Index>(soup.face_offset[p + 1] - soup.face_offset[p] - 2, 0);
  TriangleRows triangles(most);
  std::vector<Index> polygon;
  std::vector<Index> sorted;
  PolygonTriangulator triangulator;
  for (Index p = 0; p < soup.num_polygons(); ++p) {
    if (soup.face_offset[p + 1] - soup.face_offset[p] == 3) {
      // A triangle needs no collapsing, sorting or clipping: any repeat makes it degenerate.
      const Index* corner = soup.face_vertex.data() + soup.face_offset[p];
      const Index a = representative[corner[0]], b = representative[corner[1]], c = representative[corner[2]];
      if (a == b || b == c || a == c) {
        ++report.degenerate_faces_dropped;
      } else {
        triangles.add(a, b, c);
      }
      continue;
    }
    polygon.clear();
    for (Index i = soup.face_offset[p]; i < soup.face_offset[p + 1]; ++i) {
      const Index v = representative[soup.face_vertex[i]];
      if (polygon.empty() || polygon.back() != v) polygon.push_back(v);
    }
    while (polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
    sorted.assign(polygon.begin(), polygon.end());
    std::sort(sorted.begin(), sorted.end());
    if (polygon.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      ++report.degenerate_faces_dropped;
      continue;
    }
    if (polygon.size() > 3) {
      ++report.polygons_triangulated;
      report.triangles_created += static_cast<Index>(polygon.size()) - 2;
    }
    triangulator.triangulate(polygon, soup.vertices, triangles);
  }
  return triangles.take();
}

/// Removes every triangle whose vertex set equals that of an earlier one.
/// Returns how many were removed. The triangles are bucketed by their
/// smallest vertex (a counting sort, in file order within a bucket), and each
/// is compared with the earlier ones of its bucket only: a handful on a
/// manifold mesh (the triangles around one vertex), so linear time; a large
/// bucket is sorted instead.
Index drop_duplicate_triangles(Triangles& triangles, Index num_vertices) {
  const auto count = static_cast<std::size_t>(triangles.rows());
  std::vector<std::array<Index, 3>> sorted(count);
  std::vector<Index> start(static_cast<std::size_t>(num_vertices) + 1, 0);
  for (std::size_t t = 0; t < count; ++t) {
    Index a = triangles(static_cast<Index>(t), 0), b = triangles(static_cast<Index>(t), 1),
          c = triangles(static_cast<Index>(t), 2);
    if (a > b) std::swap(a, b);  // a sorting network of three
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    sorted[t] = {a, b, c};
    ++start[static_cast<std::size_t>(a) + 1];
  }
  for (std::size_t v = 0; v < static_cast<std::size_t>(num_vertices); ++v) start[v + 1] += start[v];
  std::vector<Index> bucket(count), fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < count; ++t)
    bucket[static_cast<std::size_t>(fill[static_cast<std::size_t>(sorted[t][0])]++)] = static_cast<Index>(t);
  const auto triple = [&](Index t) { return sorted[static_cast<std::size_t>(t)]; };
  std::vector<std::uint8_t> duplicate(count, 0);
  for (std::size_t v = 0; v < static_cast<std::size_t>(num_vertices); ++v) {
    const auto first = bucket.begin() + start[v], last = bucket.begin() + start[v + 1];
    if (last - first > 16) {  // a large fan (a disk triangulated around its centre): sorted, not pairwise
      std::sort(first, last,
                [&](Index a, Index b) { return std::make_pair(triple(a), a) < std::make_pair(triple(b), b); });
      for (auto it = first + 1; it < last; ++it)
        duplicate[static_cast<std::size_t>(*it)] = triple(*it) == triple(*(it - 1));
      continue;
    }
    for (auto it = first + 1; it < last; ++it)
      for (auto earlier = first; earlier < it && !duplicate[static_cast<std::size_t>(*it)]; ++earlier)
        duplicate[static_cast<std::size_t>(*it)] = triple(*earlier) == triple(*it);
  }
  Index kept = 0;
  for (std::size_t t = 0; t < count; ++t)
    if (!duplicate[t]) triangles.row(kept++) = triangles.row(static_cast<Index>(t));
  triangles.conservativeResize(kept, 3);
  return static_cast<Index>(count) - kept;
}

/// The mesh on the referenced soup vertices (in soup order) of `triangles`.
/// When every vertex is referenced (the usual case) the numbering is the
/// soup's, and the vertices are taken whole: from `owned_vertices`, the
/// soup's own array, where the caller gave the soup away, or copied.
Mesh compact_mesh(const PolygonSoup& soup, Points* owned_vertices, Triangles triangles) {
  std::vector<Index> new_index(static_cast<std::size_t>(soup.num_vertices()), kInvalidIndex);
  // Over the row-major array itself (Eigen's reshaped() walks it column by
  // column, a division per entry).
  const auto corners = static_cast<std::size_t>(triangles.size());
  for (std::size_t c = 0; c < corners; ++c) new_index[static_cast<std::size_t>(triangles.data()[c])] = 0;
  Mesh mesh;
  mesh.source = soup.source;
  mesh.source_vertex.reserve(new_index.size());
  for (Index v = 0; v < soup.num_vertices(); ++v) {
    if (new_index[v] == kInvalidIndex) continue;
    new_index[v] = static_cast<Index>(mesh.source_vertex.size());
    mesh.source_vertex.push_back(v);
  }
  mesh.triangles = std::move(triangles);
  if (mesh.source_vertex.size() == new_index.size()) {
    mesh.vertices = owned_vertices != nullptr ? std::move(*owned_vertices) : soup.vertices;
    return mesh;
  }
  mesh.vertices.resize(static_cast<Eigen::Index>(mesh.source_vertex.size()), 3);
  for (Index v = 0; v < mesh.num_vertices(); ++v) mesh.vertices.row(v) = soup.vertices.row(mesh.source_vertex[v]);
  for (std::size_t c = 0; c < corners; ++c)
    mesh.triangles.data()[c] = new_index[static_cast<std::size_t>(mesh.triangles.data()[c])];
  return mesh;
}

/// Splits `mesh` by `labels` into the components listed in `keep`, in that order.
std::vector<Mesh> split_components(const Mesh& mesh, const ComponentLabels& labels, const std::vector<Index>& keep) {
  std::vector<Index> part_of_component(static_cast<std::size_t>(labels.count), kInvalidIndex);
  for (std::size_t i = 0; i < keep.size(); ++i) part_of_component[keep[i]] = static_cast<Index>(i);
  const auto part_of_vertex = [&](Index v) { return part_of_component[labels.vertex_component[v]]; };

  std::vector<Mesh> parts(keep.size());
  std::vector<Index> local(static_cast<std::size_t>(mesh.num_vertices()), kInvalidIndex);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Index s = part_of_vertex(v);
    if (s == kInvalidIndex) continue;
    local[v] = static_cast<Index>(parts[s].source_vertex.size());
    parts[s].source_vertex.push_back(mesh.source_vertex[v]);
  }
  std::vector<Index> triangle_count(keep.size(), 0);
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const Index s = part_of_vertex(mesh.triangles(t, 0));
    if (s != kInvalidIndex) ++triangle_count[s];
  }
  for (std::size_t s = 0; s < parts.size(); ++s) {
    parts[s].source = mesh.source;
    parts[s].vertices.resize(static_cast<Eigen::Index>(parts[s].source_vertex.size()), 3);
    parts[s].triangles.resize(triangle_count[s], 3);
  }
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Index s = part_of_vertex(v);
    if (s != kInvalidIndex) parts[s].vertices.row(local[v]) = mesh.vertices.row(v);
  }
  std::vector<Index> filled(keep.size(), 0);
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const Index s = part_of_vertex(mesh.triangles(t, 0));
    if (s == kInvalidIndex) continue;
    for (int k = 0; k < 3; ++k) parts[s].triangles(filled[s], k) = local[mesh.triangles(t, k)];
    ++filled[s];
  }
  return parts;
}

/// clean_mesh, taking the vertex array from `owned_vertices` (the soup's own,
/// or nullptr to copy it).
CleanedMesh clean(const PolygonSoup& soup, Points* owned_vertices, const CleanupOptions& options) {
  check_soup(soup);
  CleanedMesh result;
  CleanupReport& report = result.report;
  const std::string where = source_label(soup.source) + ": ";
  report.input_vertices = soup.num_vertices();
  report.input_polygons = soup.num_polygons();

  std::vector<Index> representative(static_cast<std::size_t>(soup.num_vertices()));
  std::iota(representative.begin(), representative.end(), Index{0});
  if (options.merge_coincident_vertices)
    report.coincident_vertices_merged = merge_coincident(soup.vertices, representative);

  Triangles triangles = triangulate_soup(soup, representative, report);
  if (triangles.rows() == 0)
    throw InvalidMeshError(soup.source, "no usable triangle: all " +
                                            count_of(soup.num_polygons(), "polygon is", "polygons are") +
                                            " degenerate (fewer than 3 distinct vertices, or a repeated vertex)");
  if (report.degenerate_faces_dropped > 0)
    report.warnings.push_back(where + "dropped " +
                              count_of(report.degenerate_faces_dropped, "degenerate polygon", "degenerate polygons") +
                              " (fewer than 3 distinct vertices, or a repeated vertex)");
  Mesh mesh = compact_mesh(soup, owned_vertices, std::move(triangles));
  // The areas are >= 0, so the surface has area as soon as one triangle has: on a
  // usual mesh the first.
  bool has_area = false;
  for (Index t = 0; t < mesh.num_triangles() && !has_area; ++t) has_area = triangle_area(mesh, t) > 0.0;
  if (!has_area)
    throw InvalidMeshError(soup.source, "no surface: the vertices of every one of its " +
                                            count_of(mesh.num_triangles(), "triangle are", "triangles are") +
                                            " collinear (zero area, degenerate)");
  report.unreferenced_vertices_dropped =
      report.input_vertices - report.coincident_vertices_merged - mesh.num_vertices();

  MeshTopology topology = analyze_topology(mesh);
  // Two triangles on the same three vertices share their three edges: an edge
  // of theirs has more than two triangles, or the two close on each other, a
  // fan of their own at each of their vertices; a vertex that other triangles
  // share then has two fans, and one that none share makes the two a
  // component (the whole mesh when it has two triangles). Only such a mesh is
  // searched for duplicates, and its topology taken again without them (they
  // leave no vertex unreferenced: the first of each stays).
  if (!topology.manifold || topology.components > 1 || mesh.num_triangles() == 2) {
    report.duplicate_faces_dropped = drop_duplicate_triangles(mesh.triangles, mesh.num_vertices());
    if (report.duplicate_faces_dropped > 0) {
      report.warnings.push_back(where + "dropped " +
                                count_of(report.duplicate_faces_dropped, "duplicate triangle", "duplicate triangles") +
                                " (same vertices as an earlier triangle)");
      topology = analyze_topology(mesh);
    }
  }
  report.boundary_edges = topology.boundary_edges;
  report.boundary_loops = topology.boundary_loops;
  report.non_manifold_edges = topology.non_manifold_edges;
  report.non_manifold_vertices = topology.non_manifold_vertices;
  report.components = topology.components;
  if (topology.non_manifold_edges > 0)
    report.warnings.push_back(where + count_of(topology.non_manifold_edges, "non-manifold edge", "non-manifold edges") +
                              " (used by more than 2 triangles), kept as is");
  if (topology.non_manifold_vertices > 0)
    report.warnings.push_back(where +
                              count_of(topology.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices") +
                              " (incident triangles form more than one fan), kept as is");

  if (topology.components == 1) {
    result.components.push_back(std::move(mesh));
    return result;
  }

  // Order components by area, then triangle count, then smallest source
  // vertex (component ids already follow it).
  const ComponentLabels labels = connected_components(mesh.triangles, mesh.num_vertices());
  std::vector<double> area(static_cast<std::size_t>(labels.count), 0.0);
  std::vector<Index> size(static_cast<std::size_t>(labels.count), 0);
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const Index c = labels.vertex_component[mesh.triangles(t, 0)];
    area[c] += triangle_area(mesh, t);
    ++size[c];
  }
  std::vector<Index> order(static_cast<std::size_t>(labels.count));
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    return std::make_tuple(-area[a], -size[a], a) < std::make_tuple(-area[b], -size[b], b);
  });
  if (!options.keep_all_components) {
    const double total_area = std::accumulate(area.begin(), area.end(), 0.0);
    const Index kept = order.front();
    report.components_dropped = labels.count - 1;
    report.warnings.push_back(where + "kept the largest of " + std::to_string(labels.count) +
                              " connected components (" + count_of(size[kept], "triangle", "triangles") + ", " +
                              percent(area[kept], total_area) + " of the area); dropped " +
                              count_of(report.components_dropped, "component", "components") + " with " +
                              count_of(mesh.num_triangles() - size[kept], "triangle", "triangles") + " (" +
                              percent(total_area - area[kept], total_area) +
                              " of the area); the reeb commands keep them with --all-components");
    order.resize(1);
  }
  result.components = split_components(mesh, labels, order);
  return result;
}

}  // namespace

CleanedMesh clean_mesh(const PolygonSoup& soup, const CleanupOptions& options) { return clean(soup, nullptr, options); }

CleanedMesh clean_mesh(PolygonSoup&& soup, const CleanupOptions& options) {
  return clean(soup, &soup.vertices, options);
}

}  // namespace reebkit

#include "reebkit/mesh/degenerate_triangles.h"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <vector>

namespace reebkit {

namespace {

using Corners = std::array<Index, 3>;

/// The largest area a triangle of `mesh` may have and still be degenerate.
double degenerate_area(double total_area, Index triangles, double min_area_fraction) {
  return triangles > 0 ? min_area_fraction * total_area / static_cast<double>(triangles) : 0.0;
}

/// A triangle mesh with vertex stars, edited by flips and collapses.
class EditableMesh {
 public:
  explicit EditableMesh(const Mesh& mesh)
      : points_(mesh.vertices),
        star_(static_cast<std::size_t>(mesh.num_vertices())),
        vertex_alive_(static_cast<std::size_t>(mesh.num_vertices()), 1) {
    for (Index t = 0; t < mesh.num_triangles(); ++t) {
      triangles_.push_back({mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)});
      triangle_alive_.push_back(1);
      for (int k = 0; k < 3; ++k) star_[static_cast<std::size_t>(mesh.triangles(t, k))].push_back(t);
    }
  }

  Index num_triangles() const { return static_cast<Index>(triangles_.size()); }
  bool alive(Index t) const { return triangle_alive_[static_cast<std::size_t>(t)] != 0; }
  const Corners& corners(Index t) const { return triangles_[static_cast<std::size_t>(t)]; }
  Vec3 point(Index v) const { return points_.row(v).transpose(); }

  /// Twice the area times the unit normal of the triangle (a, b, c).
  Vec3 normal(Index a, Index b, Index c) const { return (point(b) - point(a)).cross(point(c) - point(a)); }
  double area(Index a, Index b, Index c) const { return 0.5 * normal(a, b, c).norm(); }
  double area(Index t) const { return area(corners(t)[0], corners(t)[1], corners(t)[2]); }

  /// The largest degenerate area at the current mean area.
  double limit(double min_area_fraction) const {
    double total = 0;
    Index count = 0;
    for (Index t = 0; t < num_triangles(); ++t)
      if (alive(t)) total += area(t), ++count;
    return degenerate_area(total, count, min_area_fraction);
  }

  /// The live triangles of area at most `limit`, in increasing order.
  std::vector<Index> degenerate(double limit) const {
    std::vector<Index> out;
    for (Index t = 0; t < num_triangles(); ++t)
      if (alive(t) && !(area(t) > limit)) out.push_back(t);
    return out;
  }

  /// The triangles on the edge (u, v).
  std::vector<Index> on_edge(Index u, Index v) const {
    std::vector<Index> out;
    for (const Index t : star(u))
      if (contains(t, v)) out.push_back(t);
    return out;
  }

  /// The vertices joined to u by an edge, sorted.
  std::vector<Index> neighbours(Index u) const {
    std::vector<Index> out;
    for (const Index t : star(u))
      for (const Index w : corners(t))
        if (w != u) out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  bool on_border(Index u) const {
    for (const Index w : neighbours(u))
      if (on_edge(u, w).size() == 1) return true;
    return false;
  }

  /// Flips the edge opposite corner k of triangle t, if allowed: the smallest
  /// area of the two new triangles, or nothing.
  std::optional<double> flip_quality(Index t, int k, double limit) const {
    const auto [c, a, b, n, d] = flip_parts(t, k);
    if (n == kInvalidIndex || c == d) return std::nullopt;
    const std::vector<Index> around_c = neighbours(c);
    if (std::binary_search(around_c.begin(), around_c.end(), d)) return std::nullopt;  // (c, d) is an edge already
    const Vec3 before = normal(a, b, c) + normal(b, a, d);
    const Vec3 first = normal(c, a, d), second = normal(c, d, b);
    if (!(first.dot(before) > 0 && second.dot(before) > 0 && first.dot(second) > 0)) return std::nullopt;
    const double smallest = 0.5 * std::min(first.norm(), second.norm());
    if (!(smallest > limit)) return std::nullopt;
    return smallest;
  }

  void flip(Index t, int k) {
    const auto [c, a, b, n, d] = flip_parts(t, k);
    triangles_[static_cast<std::size_t>(t)] = {c, a, d};
    triangles_[static_cast<std::size_t>(n)] = {c, d, b};
    erase(a, n);
    erase(b, t);
    star_[static_cast<std::size_t>(c)].push_back(n);
    star_[static_cast<std::size_t>(d)].push_back(t);
  }

  /// Moves u onto v (the edge (u, v) disappears), if allowed: the smallest
  /// area of the triangles that change (infinity when none does), or nothing.
  /// Each collapse removes at least one degenerate triangle and makes none.
  std::optional<double> collapse_quality(Index u, Index v, double limit) const {
    const std::vector<Index> removed = on_edge(u, v);
    if (removed.empty() || removed.size() > 2) return std::nullopt;
    if (on_border(u) && removed.size() != 1) return std::nullopt;  // a border vertex moves along its border only
    std::vector<Index> opposite;
    for (const Index t : removed)
      for (const Index w : corners(t))
        if (w != u && w != v) opposite.push_back(w);
    std::sort(opposite.begin(), opposite.end());
    // Link condition: u and v share no neighbour but the corners of their
    // common triangles, so no edge doubles and the topology stays.
    const std::vector<Index> around_u = neighbours(u), around_v = neighbours(v);
    std::vector<Index> common, merged;
    std::set_intersection(around_u.begin(), around_u.end(), around_v.begin(), around_v.end(),
                          std::back_inserter(common));
    if (common != opposite) return std::nullopt;
    for (const Index w : opposite)
      if (neighbours(w).size() < 4) return std::nullopt;  // would be left with 2 neighbours
    std::set_union(around_u.begin(), around_u.end(), around_v.begin(), around_v.end(), std::back_inserter(merged));
    if (merged.size() < 5) return std::nullopt;  // v would be left with fewer than 3 (merged holds u and v)
    Vec3 around = Vec3::Zero();                  // u's area-weighted normal
    for (const Index t : star(u)) around += normal(corners(t)[0], corners(t)[1], corners(t)[2]);
    double smallest = std::numeric_limits<double>::infinity();
    for (const Index t : star(u)) {
      if (contains(t, v)) continue;
      Corners moved = corners(t);
      std::replace(moved.begin(), moved.end(), u, v);
      const Vec3 before = normal(corners(t)[0], corners(t)[1], corners(t)[2]);
      const Vec3 after = normal(moved[0], moved[1], moved[2]);
      const bool was_degenerate = !(0.5 * before.norm() > limit);
      smallest = std::min(smallest, 0.5 * after.norm());
      // No triangle becomes degenerate. One that was (in a cluster of small
      // triangles, or on a line of the original) may stay so, for a later
      // flip or collapse; its normal means nothing.
      if (!(0.5 * after.norm() > limit)) {
        if (was_degenerate) continue;
        return std::nullopt;
      }
      if (!(after.dot(around) > 0) || (!was_degenerate && !(after.dot(before) > 0))) return std::nullopt;
    }
    return smallest;
  }

  void collapse(Index u, Index v) {
    for (const Index t : std::vector<Index>(star(u))) {
      if (contains(t, v)) {
        triangle_alive_[static_cast<std::size_t>(t)] = 0;
        for (const Index w : corners(t)) erase(w, t);
        continue;
      }
      std::replace(triangles_[static_cast<std::size_t>(t)].begin(), triangles_[static_cast<std::size_t>(t)].end(), u,
                   v);
      star_[static_cast<std::size_t>(v)].push_back(t);
    }
    star_[static_cast<std::size_t>(u)].clear();
    vertex_alive_[static_cast<std::size_t>(u)] = 0;
  }

  /// The four triangles of a closed tetrahedron on u, when u has three
  /// neighbours that a fourth triangle joins, and the tetrahedron hangs on
  /// the rest of the mesh (a pocket that a collapse folded, on a
  /// non-manifold edge); else nothing.
  std::optional<std::array<Index, 4>> pocket(Index u) const {
    if (star(u).size() != 3) return std::nullopt;
    const std::vector<Index> around = neighbours(u);
    if (around.size() != 3) return std::nullopt;
    for (const Index t : star(around[0])) {
      Corners c = corners(t);
      std::sort(c.begin(), c.end());
      if (!std::equal(c.begin(), c.end(), around.begin())) continue;
      const std::array<Index, 4> out{star(u)[0], star(u)[1], star(u)[2], t};
      for (const Index w : around)
        if (star(w).size() > 3) return out;  // not a tetrahedron of its own
      return std::nullopt;
    }
    return std::nullopt;
  }

  void remove(const std::array<Index, 4>& triangles) {
    for (const Index t : triangles) {
      triangle_alive_[static_cast<std::size_t>(t)] = 0;
      for (const Index w : corners(t)) erase(w, t);
    }
    for (const Index t : triangles)
      for (const Index w : corners(t))
        if (star(w).empty()) vertex_alive_[static_cast<std::size_t>(w)] = 0;
  }

  /// The mesh of the live vertices and triangles, in their order.
  TriangleRepair result(const Mesh& input) const {
    TriangleRepair out;
    std::vector<Index> new_id(vertex_alive_.size(), kInvalidIndex);
    for (std::size_t v = 0; v < vertex_alive_.size(); ++v)
      if (vertex_alive_[v]) {
        new_id[v] = static_cast<Index>(out.input_vertex.size());
        out.input_vertex.push_back(static_cast<Index>(v));
      }
    out.mesh.source = input.source;
    out.mesh.vertices.resize(static_cast<Index>(out.input_vertex.size()), 3);
    for (std::size_t i = 0; i < out.input_vertex.size(); ++i) {
      out.mesh.vertices.row(static_cast<Index>(i)) = points_.row(out.input_vertex[i]);
      if (!input.source_vertex.empty())
        out.mesh.source_vertex.push_back(input.source_vertex[static_cast<std::size_t>(out.input_vertex[i])]);
    }
    Index live = 0;
    for (Index t = 0; t < num_triangles(); ++t) live += alive(t);
    out.mesh.triangles.resize(live, 3);
    Index row = 0;
    for (Index t = 0; t < num_triangles(); ++t) {
      if (!alive(t)) continue;
      for (int k = 0; k < 3; ++k)
        out.mesh.triangles(row, k) = new_id[static_cast<std::size_t>(corners(t)[static_cast<std::size_t>(k)])];
      ++row;
    }
    return out;
  }

 private:
  struct FlipParts {
    Index c, a, b;  ///< t = (a, b, c), the edge (a, b) flips
    Index n, d;     ///< the triangle (b, a, d) across it; n = kInvalidIndex when there is none (or several)
  };

  FlipParts flip_parts(Index t, int k) const {
    const Corners& tc = corners(t);
    FlipParts p{tc[static_cast<std::size_t>(k)], tc[static_cast<std::size_t>((k + 1) % 3)],
                tc[static_cast<std::size_t>((k + 2) % 3)], kInvalidIndex, kInvalidIndex};
    const std::vector<Index> across = on_edge(p.a, p.b);
    if (across.size() != 2) return p;
    const Index n = across[0] == t ? across[1] : across[0];
    const Corners& nc = corners(n);
    for (std::size_t i = 0; i < 3; ++i)
      if (nc[i] == p.b && nc[(i + 1) % 3] == p.a) {  // consistently oriented: (b, a, d)
        p.n = n;
        p.d = nc[(i + 2) % 3];
      }
    return p;
  }

  const std::vector<Index>& star(Index u) const { return star_[static_cast<std::size_t>(u)]; }
  bool contains(Index t, Index v) const {
    const Corners& c = corners(t);
    return c[0] == v || c[1] == v || c[2] == v;
  }
  void erase(Index v, Index t) {
    std::vector<Index>& s = star_[static_cast<std::size_t>(v)];
    s.erase(std::remove(s.begin(), s.end(), t), s.end());
  }

  Points points_;
  std::vector<Corners> triangles_;
  std::vector<char> triangle_alive_;
  std::vector<std::vector<Index>> star_;
  std::vector<char> vertex_alive_;
};

}  // namespace

std::vector<Index> degenerate_triangles(const Mesh& mesh, double min_area_fraction) {
  const EditableMesh editable(mesh);
  return editable.degenerate(editable.limit(min_area_fraction));
}

TriangleRepair repair_degenerate_triangles(const Mesh& mesh, double min_area_fraction) {
  EditableMesh editable(mesh);
  TriangleRepair out;
  // Each operation removes at least one degenerate triangle at the round's
  // limit; the limit moves with the mean area, hence the rounds.
  double limit = editable.limit(min_area_fraction);
  std::vector<Index> bad = editable.degenerate(limit);
  for (int round = 0; round < 100 && !bad.empty(); ++round) {
    bool progress = false;
    for (const Index t : bad) {
      if (!editable.alive(t) || editable.area(t) > limit) continue;
      // A folded pocket goes whole; else flips first (they keep every
      // vertex), then collapses; the best of each kind.
      std::optional<std::array<Index, 4>> pocket;
      for (const Index u : editable.corners(t))
        if (!pocket) pocket = editable.pocket(u);
      if (pocket) {
        editable.remove(*pocket);
        ++out.pockets;
        progress = true;
        continue;
      }
      double best = -1;
      int best_flip = -1;
      for (int k = 0; k < 3; ++k)
        if (const auto q = editable.flip_quality(t, k, limit); q && *q > best) best = *q, best_flip = k;
      if (best_flip >= 0) {
        editable.flip(t, best_flip);
        ++out.flips;
        progress = true;
        continue;
      }
      Index from = kInvalidIndex, to = kInvalidIndex;
      for (int k = 0; k < 3; ++k)
        for (const int direction : {1, 2}) {
          const Index u = editable.corners(t)[static_cast<std::size_t>(k)];
          const Index v = editable.corners(t)[static_cast<std::size_t>((k + direction) % 3)];
          if (const auto q = editable.collapse_quality(u, v, limit); q && *q > best) best = *q, from = u, to = v;
        }
      if (from != kInvalidIndex) {
        editable.collapse(from, to);
        ++out.collapses;
        progress = true;
      }
    }
    limit = editable.limit(min_area_fraction);
    bad = editable.degenerate(limit);
    if (!progress) break;
  }
  const Index flips = out.flips, collapses = out.collapses, pockets = out.pockets;
  out = editable.result(mesh);
  out.flips = flips;
  out.collapses = collapses;
  out.pockets = pockets;
  out.remaining = static_cast<Index>(bad.size());
  return out;
}

}  // namespace reebkit

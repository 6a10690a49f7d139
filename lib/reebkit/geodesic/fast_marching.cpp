#include "reebkit/geodesic/fast_marching.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace reebkit {

namespace {

using Vec2 = Eigen::Vector2d;

// Corners are split from about 90.6 degrees on (cosine -0.01). Below, the
// directions the real triangle cannot take causally are within 0.6 degrees
// of an edge, where the edge update is at most 5e-5 too long; and the
// nearly right corners of regular meshes (every vertex of a generated torus
// has one) would cost more to split than a whole pass.
constexpr double kSplitCosine = -0.01;

// An unfolded vertex must lie inside the section by more than this cosine
// to wv and to wu. Regular triangulations (the flat faces of mechanical
// parts, sheared grids) put unfolded vertices at right angles exactly, where
// the sign of the rounding, which a rotated or scaled copy changes, would
// decide; with the margin every copy unfolds on to the same vertex. (Taking
// the vertex at the right angle instead doubles the errors of the sheared
// grid in tests/geodesic/fast_marching_test.cpp.)
constexpr double kSectionSlack = 1e-9;

// The Kimmel-Sethian update of w in triangle (w, v, u): T(v) = a, T(u) = b,
// side lengths e1 = |wv|, e2 = |wu|, e3 = |vu|. With w at the origin and P, Q
// the positions of v and u, the plane wave T(x) = t + g.x (|g| = 1) through
// (P, a) and (Q, b) has g = M^-1 (a - t, b - t), M = [P; Q], and |g| = 1 is
// the quadratic (A - t 1)' G^-1 (A - t 1) = 1 in t, G = M M' the Gram matrix
// (entries e1^2, p = P.Q, e2^2). The wave comes from inside the triangle when
// -g = alpha P + beta Q with alpha, beta >= 0, i.e. G^-1 (t 1 - A) >= 0.
// Values are shifted by a, so that large distances cost no precision.
// Returns false when the update is not causal or cannot go below `best`;
// else sets t and whether the wave crosses the side vu nearer v (alpha >=
// beta).
inline bool triangle_update(double a, double b, double e1, double e2, double e3, double best, double& t,
                            bool& nearer_v) {
  const double e1s = e1 * e1, e2s = e2 * e2, e3s = e3 * e3;
  const double p = 0.5 * (e1s + e2s - e3s);
  const double det = e1s * e2s - p * p;          // |P x Q|^2: (2 area)^2
  if (!(det > 1e-12 * e1s * e2s)) return false;  // degenerate, or the link length is missing (NaN)
  // A causal wave crosses the side vu, where T >= min(a, b), and then
  // travels at least the height of w over vu: t >= min(a, b) + sqrt(det) / e3.
  const double gap = best - std::min(a, b);
  if (gap <= 0.0 || gap * gap * e3s <= det) return false;
  const double delta = b - a;
  // det (A - t 1)' G^-1 (A - t 1) = det with A = (0, delta):
  // e3^2 t^2 - 2 delta (e1^2 - p) t + e1^2 delta^2 - det = 0; the larger root.
  const double qb = delta * (e1s - p);
  const double disc = qb * qb - e3s * (e1s * delta * delta - det);
  if (disc < 0.0) return false;
  const double s = (qb + std::sqrt(disc)) / e3s;
  if (s < 0.0 || s < delta) return false;          // t below a corner's value: not causal
  const double alpha = e2s * s - p * (s - delta);  // det * alpha
  const double beta = e1s * (s - delta) - p * s;   // det * beta
  if (alpha < 0.0 || beta < 0.0) return false;     // the wave comes from outside the triangle
  t = a + s;
  nearer_v = alpha >= beta;
  return true;
}

// Ring slots of v around slot i (cyclic only for a closed ring, where
// link_next of the last slot is set; elsewhere the wrap is never a triangle).
struct RingSlots {
  Index prev, next;
};
RingSlots ring_slots(const MeshGraph& g, Index v, Index i) {
  const Index first = g.offset[static_cast<std::size_t>(v)], last = g.offset[static_cast<std::size_t>(v) + 1] - 1;
  return {i > first ? i - 1 : last, i < last ? i + 1 : first};
}

// The triangle across the edge (p, q) from the triangle (p, q, r): its third
// vertex y and the lengths |py|, |qy|. False when the edge has no other
// triangle (boundary) or q is no neighbour of p.
struct Across {
  Index y = kInvalidIndex;
  double py = 0, qy = 0;
};
bool triangle_across(const MeshGraph& g, const std::vector<double>& link_length, Index p, Index q, Index r,
                     Across& out) {
  for (Index k = g.offset[static_cast<std::size_t>(p)]; k < g.offset[static_cast<std::size_t>(p) + 1]; ++k) {
    if (g.neighbor[static_cast<std::size_t>(k)] != q) continue;
    const auto [prev, next] = ring_slots(g, p, k);
    const auto uk = static_cast<std::size_t>(k);
    if (g.link_next[static_cast<std::size_t>(prev)] && g.neighbor[static_cast<std::size_t>(prev)] != r) {
      out = {g.neighbor[static_cast<std::size_t>(prev)], g.length[static_cast<std::size_t>(prev)],
             link_length[static_cast<std::size_t>(prev)]};
      return true;
    }
    if (g.link_next[uk] && g.neighbor[static_cast<std::size_t>(next)] != r) {
      out = {g.neighbor[static_cast<std::size_t>(next)], g.length[static_cast<std::size_t>(next)], link_length[uk]};
      return true;
    }
    return false;
  }
  return false;
}

// The point at distances dp from P and dq from Q on the side of the line PQ
// away from the origin (where w sits).
Vec2 place_beyond(const Vec2& P, const Vec2& Q, double dp, double dq) {
  const Vec2 e = Q - P;
  const double len = e.norm();
  const double along = (dp * dp - dq * dq + len * len) / (2 * len);
  const double height = std::sqrt(std::max(0.0, dp * dp - along * along));
  Vec2 normal(-e.y() / len, e.x() / len);
  if (normal.dot(-P) > 0) normal = -normal;  // the origin is on the normal's side: turn away from it
  return P + along / len * e + height * normal;
}

}  // namespace

FastMarchingSolver::FastMarchingSolver(const MeshGraph& graph)
    : GeodesicSolver(graph),
      link_length_(graph.neighbor.size(), std::nan("")),
      alive_(static_cast<std::size_t>(graph.num_vertices()), 0) {
  const Index n = graph.num_vertices();
  const Index* offset = graph.offset.data();
  const Index* neighbor = graph.neighbor.data();
  for (Index v = 0; v < n; ++v)
    for (Index i = offset[v]; i < offset[v + 1]; ++i) {
      if (!graph.link_next[static_cast<std::size_t>(i)]) continue;
      const Index a = neighbor[i];
      const Index b = neighbor[ring_slots(graph, v, i).next];
      for (Index k = offset[a]; k < offset[a + 1]; ++k)
        if (neighbor[k] == b) {
          link_length_[static_cast<std::size_t>(i)] = graph.length[static_cast<std::size_t>(k)];
          break;
        }
    }

  // Split the obtuse corners (w, v, u) by a vertex y, then store each of the
  // virtual triangles (w, v, y) and (w, y, u) at both its corners other than w.
  struct Split {
    Index w, v, u, y;
    bool one_triangle;          // the unfolded strip is the triangle across vu alone
    double wv, wu, wy, vy, uy;  // side lengths in the unfolded plane
  };
  std::vector<Split> split;
  for (Index w = 0; w < n; ++w)
    for (Index i = offset[w]; i < offset[w + 1]; ++i) {
      if (!graph.link_next[static_cast<std::size_t>(i)]) continue;
      const Index j = ring_slots(graph, w, i).next;
      const Index v = neighbor[i], u = neighbor[j];
      const double e1 = graph.length[static_cast<std::size_t>(i)], e2 = graph.length[static_cast<std::size_t>(j)];
      const double e3 = link_length_[static_cast<std::size_t>(i)];
      const double dot = 0.5 * (e1 * e1 + e2 * e2 - e3 * e3);  // |wv| |wu| cos(angle at w)
      if (!(dot < kSplitCosine * e1 * e2)) continue;           // acute, nearly right, or no third side
      const double sine = std::sqrt(std::max(0.0, e1 * e1 * e2 * e2 - dot * dot));
      if (!(sine > 0.0)) continue;  // degenerate
      // w at the origin, v on the x axis, u above it; the section is every
      // direction d with d.V >= 0 and d.U >= 0.
      const Vec2 V(e1, 0.0), U(dot / e1, sine / e1);
      Index p = v, q = u, r = w;
      Vec2 P = V, Q = U;
      for (int step = 0; step < kMaxUnfoldings; ++step) {
        Across across;
        if (!triangle_across(graph, link_length_, p, q, r, across) || across.y == w) break;
        const Vec2 Y = place_beyond(P, Q, across.py, across.qy);
        const double slack = kSectionSlack * Y.norm();
        const bool beyond_v_side = Y.dot(V) < slack * e1, beyond_u_side = Y.dot(U) < slack * e2;
        if (!beyond_v_side && !beyond_u_side) {
          split.push_back({w, v, u, across.y, step == 0, e1, e2, Y.norm(), (Y - V).norm(), (Y - U).norm()});
          break;
        }
        // The section lies between P's direction and Y's, or Y's and Q's.
        if (beyond_v_side) {
          r = q, q = across.y, Q = Y;
        } else {
          r = p, p = across.y, P = Y;
        }
      }
    }
  virtual_offset_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const Split& c : split)
    for (const Index trigger : {c.v, c.y, c.y, c.u}) ++virtual_offset_[static_cast<std::size_t>(trigger) + 1];
  for (Index v = 0; v < n; ++v)
    virtual_offset_[static_cast<std::size_t>(v) + 1] += virtual_offset_[static_cast<std::size_t>(v)];
  virtual_.resize(4 * split.size());
  std::vector<Index> fill(virtual_offset_.begin(), virtual_offset_.end() - 1);
  const auto put = [&](Index trigger, const VirtualTriangle& t) {
    virtual_[static_cast<std::size_t>(fill[static_cast<std::size_t>(trigger)]++)] = t;
  };
  for (const Split& c : split) {
    const Index strip_u = c.one_triangle ? c.u : kInvalidIndex, strip_v = c.one_triangle ? c.v : kInvalidIndex;
    put(c.v, {c.w, c.y, strip_u, c.wv, c.wy, c.vy});  // (w, v, y)
    put(c.y, {c.w, c.v, strip_u, c.wy, c.wv, c.vy});
    put(c.y, {c.w, c.u, strip_v, c.wy, c.wu, c.uy});  // (w, y, u)
    put(c.u, {c.w, c.y, strip_v, c.wu, c.wy, c.uy});
  }
}

const DistanceField& FastMarchingSolver::run(const std::vector<Index>& sources, const GeodesicOptions& options) {
  for (const Index v : settled_) alive_[static_cast<std::size_t>(v)] = 0;
  const auto [labels, dist, nearest, offset, neighbor, length, bound] = start(sources, options, "fast_marching");
  const std::uint8_t* link_next = graph_.link_next.data();
  const double* link_length = link_length_.data();
  std::uint8_t* alive = alive_.data();
  const bool separate = options.separate_sources;
  while (!heap_.empty()) {
    const auto [d, v] = heap_.pop();
    if (alive[v] || d > dist[v]) continue;  // stale entry
    alive[v] = 1;
    settle(v, d);
    const Index first = offset[v], last = offset[v + 1] - 1;
    for (Index i = first; i <= last; ++i) {
      const Index w = neighbor[i];
      if (alive[w] || (labels && labels[w] != options.label)) continue;
      double best = std::min(d + length[i], dist[w]);
      Index source = best < dist[w] ? nearest[v] : kInvalidIndex;
      // The triangles (v, w, u) on either side of the edge vw, u settled
      // (from the same source, for separate sources: a plane wave through
      // the fronts of two would cut the corner between them). Settled
      // vertices carry the label, so the restriction holds as is.
      const Index prev = i > first ? i - 1 : last, next = i < last ? i + 1 : first;
      const Index sides[2][2] = {{prev, prev}, {next, i}};  // (slot of u, link slot)
      for (const auto& [j, link] : sides) {
        if (!link_next[link]) continue;
        const Index u = neighbor[j];
        if (!alive[u] || (separate && nearest[u] != nearest[v])) continue;
        double t;
        bool nearer_v;
        if (triangle_update(d, dist[u], length[i], link_length[link], length[j], best, t, nearer_v) && t < best) {
          best = t;
          source = nearer_v ? nearest[v] : nearest[u];
        }
      }
      if (source != kInvalidIndex && within(best, w, options.radius, bound)) improve(w, best, source);
    }
    for (Index k = virtual_offset_[static_cast<std::size_t>(v)]; k < virtual_offset_[static_cast<std::size_t>(v) + 1];
         ++k) {
      const VirtualTriangle& vt = virtual_[static_cast<std::size_t>(k)];
      const Index w = vt.target, u = vt.other;
      if (alive[w] || !alive[u] || (separate && nearest[u] != nearest[v])) continue;
      if (labels &&
          (labels[w] != options.label || vt.strip_vertex == kInvalidIndex || labels[vt.strip_vertex] != options.label))
        continue;
      double t;
      bool nearer_v;
      if (triangle_update(d, dist[u], vt.to_target, vt.other_to_target, vt.to_other, dist[w], t, nearer_v) &&
          t < dist[w] && within(t, w, options.radius, bound))
        improve(w, t, nearer_v ? nearest[v] : nearest[u]);
    }
  }
  return finish();
}

}  // namespace reebkit

#include "reebkit/mesh/intrinsic_delaunay.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace reebkit {

namespace {

constexpr Index kNoTwin = -1;

/// The cotangent of the angle opposite side c in a triangle of sides a, b,
/// c, or NaN where the triangle has (nearly) no area.
double cot_opposite(double a, double b, double c) {
  const double area2 = intrinsic_twice_area(a, b, c);
  const double longest = std::max({a, b, c});
  if (!(area2 > 1e-12 * longest * longest)) return std::nan("");
  return (a * a + b * b - c * c) / (2 * area2);
}

/// Half-edge h = 3 t + k: the side of triangle t opposite its corner k, from
/// corner k + 1 to corner k + 2. twin[h] runs the other way in the other
/// triangle on that edge; kNoTwin on a boundary or non-manifold edge.
std::vector<Index> twins(const Triangles& triangles) {
  const auto halfedges = static_cast<std::size_t>(3 * triangles.rows());
  std::vector<std::pair<std::uint64_t, Index>> keys(halfedges);
  for (std::size_t h = 0; h < halfedges; ++h) {
    const Index t = static_cast<Index>(h / 3), k = static_cast<Index>(h % 3);
    auto a = static_cast<std::uint32_t>(triangles(t, (k + 1) % 3)),
         b = static_cast<std::uint32_t>(triangles(t, (k + 2) % 3));
    if (a > b) std::swap(a, b);
    keys[h] = {(std::uint64_t{a} << 32) | b, static_cast<Index>(h)};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<Index> twin(halfedges, kNoTwin);
  for (std::size_t i = 0; i < halfedges;) {
    std::size_t j = i;
    while (j < halfedges && keys[j].first == keys[i].first) ++j;
    if (j - i == 2) {
      const Index g = keys[i].second, h = keys[i + 1].second;
      // Opposite orientation: g's start is h's end.
      if (triangles(g / 3, (g % 3 + 1) % 3) == triangles(h / 3, (h % 3 + 2) % 3)) {
        twin[static_cast<std::size_t>(g)] = h;
        twin[static_cast<std::size_t>(h)] = g;
      }
    }
    i = j;
  }
  return twin;
}

}  // namespace

double intrinsic_twice_area(double a, double b, double c) {
  std::array<double, 3> s{a, b, c};
  std::sort(s.begin(), s.end(), std::greater<>());
  const double x = s[0], y = s[1], z = s[2];
  const double p = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
  return p > 0 ? 0.5 * std::sqrt(p) : 0.0;
}

IntrinsicTriangulation intrinsic_delaunay(const Mesh& mesh) {
  IntrinsicTriangulation out;
  out.triangles = mesh.triangles;
  out.num_vertices = mesh.num_vertices();
  const Index nt = mesh.num_triangles();
  out.lengths.resize(nt, 3);
  for (Index t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      out.lengths(t, k) =
          (mesh.vertices.row(mesh.triangles(t, (k + 1) % 3)) - mesh.vertices.row(mesh.triangles(t, (k + 2) % 3)))
              .norm();
  std::vector<Index> twin = twins(mesh.triangles);
  Triangles& tri = out.triangles;
  auto& len = out.lengths;
  // The half-edges still to check, each once at a time; popped from the back,
  // so pushed in reverse to check them in the triangles' order.
  std::vector<Index> stack;
  std::vector<char> queued(twin.size(), 0);
  for (auto h = static_cast<Index>(twin.size()); h-- > 0;)
    if (twin[static_cast<std::size_t>(h)] != kNoTwin && h < twin[static_cast<std::size_t>(h)]) {
      stack.push_back(h);
      queued[static_cast<std::size_t>(h)] = 1;
    }
  const auto push = [&](Index h) {
    const Index g = twin[static_cast<std::size_t>(h)];
    if (g == kNoTwin || queued[static_cast<std::size_t>(h)] || queued[static_cast<std::size_t>(g)]) return;
    queued[static_cast<std::size_t>(h)] = 1;
    stack.push_back(h);
  };
  while (!stack.empty()) {
    const Index h = stack.back();
    stack.pop_back();
    queued[static_cast<std::size_t>(h)] = 0;
    const Index g = twin[static_cast<std::size_t>(h)];
    if (g == kNoTwin) continue;
    // h = side a -> b of t1 = (p, a, b) from its corner k1; g = b -> a of
    // t2 = (q, b, a) from its corner k2.
    const Index t1 = h / 3, k1 = h % 3, t2 = g / 3, k2 = g % 3;
    const Index p = tri(t1, k1), a = tri(t1, (k1 + 1) % 3), b = tri(t1, (k1 + 2) % 3), q = tri(t2, k2);
    const double ab = len(t1, k1), bp = len(t1, (k1 + 1) % 3), pa = len(t1, (k1 + 2) % 3);
    const double aq = len(t2, (k2 + 1) % 3), qb = len(t2, (k2 + 2) % 3);
    const double cot_p = cot_opposite(pa, bp, ab), cot_q = cot_opposite(aq, qb, ab);
    // Locally Delaunay (or undefined): kept. The tolerance keeps four nearly
    // cocircular corners from flipping back and forth.
    if (!(cot_p + cot_q < -1e-12) || p == q) continue;
    // The quad p, a, q, b laid out in the plane with a at the origin and b
    // on the x axis, p above it and q below: the new diagonal's length.
    const double xp = (ab * ab + pa * pa - bp * bp) / (2 * ab), yp = std::sqrt(std::max(0.0, pa * pa - xp * xp));
    const double xq = (ab * ab + aq * aq - qb * qb) / (2 * ab), yq = -std::sqrt(std::max(0.0, aq * aq - xq * xq));
    const double pq = std::hypot(xp - xq, yp - yq);
    // The four outer half-edges: a -> q, q -> b (t2), b -> p, p -> a (t1).
    const Index out_aq = twin[static_cast<std::size_t>(3 * t2 + (k2 + 1) % 3)];
    const Index out_qb = twin[static_cast<std::size_t>(3 * t2 + (k2 + 2) % 3)];
    const Index out_bp = twin[static_cast<std::size_t>(3 * t1 + (k1 + 1) % 3)];
    const Index out_pa = twin[static_cast<std::size_t>(3 * t1 + (k1 + 2) % 3)];
    // t1 = (p, a, q), t2 = (q, b, p): side k opposite corner k.
    tri.row(t1) << p, a, q;
    len.row(t1) << aq, pq, pa;
    tri.row(t2) << q, b, p;
    len.row(t2) << bp, pq, qb;
    const auto link = [&](Index x, Index y) {
      twin[static_cast<std::size_t>(x)] = y;
      if (y != kNoTwin) twin[static_cast<std::size_t>(y)] = x;
    };
    link(3 * t1, out_aq);
    link(3 * t1 + 1, 3 * t2 + 1);
    link(3 * t1 + 2, out_pa);
    link(3 * t2, out_bp);
    link(3 * t2 + 2, out_qb);
    for (const Index x : {3 * t1, 3 * t1 + 2, 3 * t2, 3 * t2 + 2}) {
      queued[static_cast<std::size_t>(x)] = 0;
      push(x);
    }
    ++out.flips;
  }
  return out;
}

}  // namespace reebkit

#include "reebkit/features/persistence.h"

#include "reebkit/core/error.h"
#include "reebkit/features/critical_points.h"

#include <algorithm>
#include <string>

namespace reebkit {

namespace {

// One sweep of the union-find. `order` lists the vertices by increasing
// (f, id); `sign` = +1 walks it from the top (maxima: superlevel sets), -1
// from the bottom (minima: sublevel sets). A component is kept under the root
// it was born with, its extremum, so the elder of two roots is the one met
// first by the sweep.
std::vector<PersistencePair> sweep(const MeshGraph& graph, const std::vector<double>& f,
                                   const std::vector<Index>& order, const std::vector<Index>& position, int sign) {
  const std::size_t n = order.size();
  std::vector<Index> parent(n, kInvalidIndex);  // kInvalidIndex: not swept yet
  const auto find = [&parent](Index x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      const Index up = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
      parent[static_cast<std::size_t>(x)] = up;  // path halving
      x = up;
    }
    return x;
  };
  // Met first: larger position from the top, smaller from the bottom.
  const auto elder = [&](Index a, Index b) {
    return sign * position[static_cast<std::size_t>(a)] > sign * position[static_cast<std::size_t>(b)];
  };
  std::vector<PersistencePair> pairs;
  for (std::size_t k = 0; k < n; ++k) {
    const Index v = order[sign > 0 ? n - 1 - k : k];
    Index root = kInvalidIndex;  // v's component so far
    for (Index i = graph.offset[static_cast<std::size_t>(v)]; i < graph.offset[static_cast<std::size_t>(v) + 1]; ++i) {
      const Index u = graph.neighbor[static_cast<std::size_t>(i)];
      if (parent[static_cast<std::size_t>(u)] == kInvalidIndex) continue;
      const Index r = find(u);
      if (root == kInvalidIndex || r == root) {
        root = r;
        continue;
      }
      // Two components meet at v: the younger extremum dies here.
      const Index old = elder(r, root) ? r : root;
      const Index young = old == r ? root : r;
      pairs.push_back({young, v, sign * (f[static_cast<std::size_t>(young)] - f[static_cast<std::size_t>(v)])});
      parent[static_cast<std::size_t>(young)] = old;
      root = old;
    }
    parent[static_cast<std::size_t>(v)] = root == kInvalidIndex ? v : root;  // no swept neighbour: born
  }
  for (std::size_t v = 0; v < n; ++v)
    if (parent[v] == static_cast<Index>(v))
      pairs.push_back({static_cast<Index>(v), kInvalidIndex, PersistencePair{}.persistence});
  std::sort(pairs.begin(), pairs.end(),
            [](const PersistencePair& a, const PersistencePair& b) { return a.extremum < b.extremum; });
  return pairs;
}

}  // namespace

ExtremaPersistence extrema_persistence(const MeshGraph& graph, const std::vector<double>& f) {
  const Index n = graph.num_vertices();
  if (static_cast<Index>(f.size()) != n)
    throw InvalidArgument("extrema_persistence: f has " + std::to_string(f.size()) + " values for " +
                          std::to_string(n) + " vertices");
  // Sorting (value, id) pairs keeps the comparisons in cache; the order is sos_less's.
  std::vector<std::pair<double, Index>> keyed(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) keyed[static_cast<std::size_t>(v)] = {f[static_cast<std::size_t>(v)], v};
  std::sort(keyed.begin(), keyed.end());
  std::vector<Index> order(keyed.size()), position(keyed.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    order[k] = keyed[k].second;
    position[static_cast<std::size_t>(keyed[k].second)] = static_cast<Index>(k);
  }
  return {sweep(graph, f, order, position, +1), sweep(graph, f, order, position, -1)};
}

std::vector<Index> persistent_extrema(const MeshGraph& graph, const std::vector<double>& f, double min_persistence) {
  if (!(min_persistence >= 0.0))
    throw InvalidArgument("persistent_extrema: min_persistence must be >= 0, got " + std::to_string(min_persistence));
  const Index n = graph.num_vertices();
  if (static_cast<Index>(f.size()) != n)
    throw InvalidArgument("persistent_extrema: f has " + std::to_string(f.size()) + " values for " + std::to_string(n) +
                          " vertices");
  // No sort of the whole mesh: an extremum e persists less than the threshold
  // exactly when a vertex beyond it (sos order) can be reached from it
  // through vertices w with |f(e) - f(w)| < min_persistence (the path's
  // lowest vertex is then above e's saddle, and the other way round). A
  // best-first search from e (most extreme first) answers that; it visits
  // only the component of e above its saddle or the band below e, which is
  // small for all but a few extrema. Same answers as extrema_persistence
  // (tested), at a fraction of its cost.
  std::vector<Index> mark(static_cast<std::size_t>(n), kInvalidIndex);  // search that reached a vertex
  std::vector<Index> heap;
  const auto at = [&f](Index v) { return f[static_cast<std::size_t>(v)]; };
  const auto persists = [&](Index e, int sign, Index search) {
    const auto beyond = [&](Index a, Index b) { return sign > 0 ? sos_less(f, b, a) : sos_less(f, a, b); };
    const auto heap_order = [&](Index a, Index b) { return beyond(b, a); };  // most extreme on top
    heap.assign(1, e);
    mark[static_cast<std::size_t>(e)] = search;
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), heap_order);
      const Index v = heap.back();
      heap.pop_back();
      for (Index i = graph.offset[static_cast<std::size_t>(v)]; i < graph.offset[static_cast<std::size_t>(v) + 1];
           ++i) {
        const Index w = graph.neighbor[static_cast<std::size_t>(i)];
        if (mark[static_cast<std::size_t>(w)] == search || !(sign * (at(e) - at(w)) < min_persistence)) continue;
        if (beyond(w, e)) return false;
        mark[static_cast<std::size_t>(w)] = search;
        heap.push_back(w);
        std::push_heap(heap.begin(), heap.end(), heap_order);
      }
    }
    return true;
  };
  std::vector<Index> out;
  Index search = 0;
  for (const Index e : local_extrema(graph, f)) {
    bool any_above = false, any_below = false;
    for (Index i = graph.offset[static_cast<std::size_t>(e)]; i < graph.offset[static_cast<std::size_t>(e) + 1]; ++i)
      (sos_less(f, graph.neighbor[static_cast<std::size_t>(i)], e) ? any_below : any_above) = true;
    const bool kept = (!any_above && persists(e, +1, search++)) || (!any_below && persists(e, -1, search++));
    if (kept) out.push_back(e);
  }
  return out;
}

}  // namespace reebkit

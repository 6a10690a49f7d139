#include "reebkit/features/critical_points.h"

namespace reebkit {

LinkCount count_link_components(const MeshGraph& graph, const std::vector<double>& f, Index v) {
  const Index begin = graph.offset[static_cast<std::size_t>(v)];
  const Index end = graph.offset[static_cast<std::size_t>(v) + 1];
  LinkCount count;
  if (begin == end) return count;
  // A run starts at slot i when its sign differs from the slot linked before it
  // (or nothing is linked before it). Slot i-1 links to i when link_next[i-1];
  // slot 0 is preceded by the last slot exactly when the ring is closed.
  const auto upper = [&](Index i) { return sos_less(f, v, graph.neighbor[static_cast<std::size_t>(i)]); };
  bool all_upper = true, all_lower = true;
  for (Index i = begin; i < end; ++i) {
    const bool up = upper(i);
    all_upper = all_upper && up;
    all_lower = all_lower && !up;
    const Index prev = i == begin ? end - 1 : i - 1;
    const bool linked = graph.link_next[static_cast<std::size_t>(prev)] != 0 && (i != begin || end - begin > 1);
    if (!linked || upper(prev) != up) (up ? count.upper : count.lower) += 1;
  }
  // A closed ring entirely above (below) v has one component and no run start.
  if (all_upper && count.upper == 0) count.upper = 1;
  if (all_lower && count.lower == 0) count.lower = 1;
  return count;
}

CriticalType classify_vertex(const MeshGraph& graph, const std::vector<double>& f, Index v) {
  const LinkCount c = count_link_components(graph, f, v);
  if (c.lower == 0) return CriticalType::Minimum;
  if (c.upper == 0) return CriticalType::Maximum;
  const bool interior = graph.ring[static_cast<std::size_t>(v)] == RingKind::Closed;
  if (interior ? (c.upper >= 2 || c.lower >= 2) : (c.upper + c.lower >= 3)) return CriticalType::Saddle;
  return CriticalType::Regular;
}

std::vector<Index> local_extrema(const MeshGraph& graph, const std::vector<double>& f) {
  // L- = 0 (L+ = 0) exactly when no neighbour is below (above) v, so extrema
  // need no walk around the ring.
  std::vector<Index> out;
  for (Index v = 0; v < graph.num_vertices(); ++v) {
    bool any_lower = false, any_upper = false;
    for (Index i = graph.offset[static_cast<std::size_t>(v)]; i < graph.offset[static_cast<std::size_t>(v) + 1]; ++i) {
      (sos_less(f, graph.neighbor[static_cast<std::size_t>(i)], v) ? any_lower : any_upper) = true;
      if (any_lower && any_upper) break;
    }
    if (!any_lower || !any_upper) out.push_back(v);
  }
  return out;
}

}  // namespace reebkit

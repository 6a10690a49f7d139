#include "reebkit/mesh/mesh_graph.h"

#include "reebkit/mesh/mesh_topology.h"

#include <algorithm>
#include <array>

namespace reebkit {

namespace {

// The link of one vertex as a tiny graph over its neighbours: each incident
// triangle (v, b, c) contributes the link edge b-c. Walking it yields the ring.
class LinkWalker {
 public:
  // Appends the ring of one vertex to the graph, from its link edges
  // [first, last): one (b, c) per incident triangle read as (v, b, c) in the
  // mesh's orientation.
  void walk(const std::array<Index, 2>* first, const std::array<Index, 2>* last, MeshGraph& g) {
    nodes_.clear();
    for (const std::array<Index, 2>* edge = first; edge != last; ++edge) {
      const auto [b, c] = *edge;
      const std::size_t ib = node(b), ic = node(c);
      add_partner(ib, ic, true);
      add_partner(ic, ib, false);
    }
    bool regular = true;
    std::size_t ends = 0;
    for (const Node& n : nodes_) {
      if (n.count > 2) regular = false;
      if (n.count == 1) ++ends;
    }
    // Fans are walked from path ends first, then around the remaining cycles.
    std::size_t fans = 0;
    std::size_t closed_fans = 0;
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t start = 0; start < nodes_.size(); ++start) {
        if (nodes_[start].visited || (pass == 0 && nodes_[start].count != 1)) continue;
        ++fans;
        closed_fans += walk_fan(start, g) ? 1 : 0;
      }
    }
    const bool closed = regular && fans == 1 && closed_fans == 1;
    const bool open = regular && fans == 1 && ends == 2;
    g.ring.push_back(closed ? RingKind::Closed : open ? RingKind::Open : RingKind::Irregular);
    if (closed) g.link_next.back() = 1;  // the last neighbour links back to the first
  }

 private:
  struct Node {
    Index vertex;
    std::array<std::size_t, 2> partner{};
    std::array<bool, 2> forward{};  // partner reached along the triangle orientation
    int count = 0;                  // link-degree (may exceed 2 when non-manifold)
    bool visited = false;
  };

  std::size_t node(Index v) {
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      if (nodes_[i].vertex == v) return i;
    nodes_.push_back(Node{v});
    return nodes_.size() - 1;
  }

  void add_partner(std::size_t a, std::size_t b, bool forward) {
    Node& n = nodes_[a];
    if (n.count < 2) {
      n.partner[static_cast<std::size_t>(n.count)] = b;
      n.forward[static_cast<std::size_t>(n.count)] = forward;
    }
    ++n.count;
  }

  // Walks one fan from `start`; returns true when it closes into a cycle.
  bool walk_fan(std::size_t start, MeshGraph& g) {
    std::size_t current = start;
    std::size_t previous = nodes_.size();
    // On a cycle, leave along the orientation so that rings come out
    // counter-clockwise on consistently oriented meshes.
    if (nodes_[start].count == 2 && !nodes_[start].forward[0] && nodes_[start].forward[1])
      std::swap(nodes_[start].partner[0], nodes_[start].partner[1]);
    while (true) {
      Node& n = nodes_[current];
      n.visited = true;
      g.neighbor.push_back(n.vertex);
      g.link_next.push_back(0);
      const int usable = std::min(n.count, 2);
      std::size_t next = nodes_.size();
      for (int k = 0; k < usable; ++k) {
        const std::size_t p = n.partner[static_cast<std::size_t>(k)];
        if (p != previous && !nodes_[p].visited && nodes_[p].count <= 2) {
          next = p;
          break;
        }
      }
      if (next == nodes_.size()) {
        // Closed if the fan returns to its start.
        for (int k = 0; k < usable; ++k)
          if (n.partner[static_cast<std::size_t>(k)] == start && current != start && previous != start) return true;
        return false;
      }
      g.link_next.back() = 1;
      previous = current;
      current = next;
    }
  }

  std::vector<Node> nodes_;
};

}  // namespace

MeshGraph build_mesh_graph(const Mesh& mesh) {
  const Index nv = mesh.num_vertices();
  const Index nf = mesh.num_triangles();
  // The incident triangles of each vertex, as the links of its corners.
  const VertexCorners corners = corners_by_vertex(mesh.triangles, nv, CornerParts::Links);

  MeshGraph g;
  g.offset.reserve(static_cast<std::size_t>(nv) + 1);
  g.offset.push_back(0);
  g.ring.reserve(static_cast<std::size_t>(nv));
  g.neighbor.reserve(static_cast<std::size_t>(nf) * 3 + 64);
  g.link_next.reserve(g.neighbor.capacity());
  LinkWalker walker;
  for (Index v = 0; v < nv; ++v) {
    walker.walk(corners.link.data() + corners.start[static_cast<std::size_t>(v)],
                corners.link.data() + corners.start[static_cast<std::size_t>(v) + 1], g);
    g.offset.push_back(static_cast<Index>(g.neighbor.size()));
  }
  g.length.resize(g.neighbor.size());
  for (Index v = 0; v < nv; ++v)
    for (Index i = g.offset[static_cast<std::size_t>(v)]; i < g.offset[static_cast<std::size_t>(v) + 1]; ++i)
      g.length[static_cast<std::size_t>(i)] =
          (mesh.vertices.row(v) - mesh.vertices.row(g.neighbor[static_cast<std::size_t>(i)])).norm();
  return g;
}

}  // namespace reebkit

#include "reebkit/reeb/reeb_graph.h"

#include <numeric>

namespace reebkit {

Index ReebGraph::connected_components() const {
  std::vector<Index> parent(nodes.size());
  std::iota(parent.begin(), parent.end(), Index{0});
  const auto find = [&parent](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  Index components = num_nodes();
  for (const auto& [a, b] : edges) {
    const Index ra = find(a);
    const Index rb = find(b);
    if (ra != rb) {
      parent[ra] = rb;
      --components;
    }
  }
  return components;
}

Index ReebGraph::independent_cycles() const { return num_edges() - num_nodes() + connected_components(); }

}  // namespace reebkit

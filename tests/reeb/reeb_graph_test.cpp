#include "reebkit/reeb/reeb_graph.h"

#include <gtest/gtest.h>

namespace reebkit {
namespace {

ReebGraph graph_with(Index nodes, std::vector<std::array<Index, 2>> edges) {
  ReebGraph g;
  g.nodes.resize(static_cast<std::size_t>(nodes));
  g.edges = std::move(edges);
  return g;
}

TEST(ReebGraph, CyclesAreEdgesMinusNodesPlusComponents) {
  EXPECT_EQ(graph_with(0, {}).independent_cycles(), 0);
  EXPECT_EQ(graph_with(1, {}).independent_cycles(), 0);
  const ReebGraph tree = graph_with(4, {{0, 1}, {0, 2}, {2, 3}});
  EXPECT_EQ(tree.connected_components(), 1);
  EXPECT_EQ(tree.independent_cycles(), 0);
  // Root, bifurcation into 1 and 2, junction 3: the graph of a torus.
  const ReebGraph torus = graph_with(5, {{0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 4}});
  EXPECT_EQ(torus.independent_cycles(), 1);
  // Two disjoint cycles and an isolated node.
  const ReebGraph two = graph_with(7, {{0, 1}, {0, 2}, {1, 2}, {3, 4}, {3, 5}, {4, 5}});
  EXPECT_EQ(two.connected_components(), 3);
  EXPECT_EQ(two.independent_cycles(), 2);
}

}  // namespace
}  // namespace reebkit

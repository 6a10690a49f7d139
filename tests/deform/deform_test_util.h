// Helpers shared by the deform tests: a five-armed star and its analysis,
// whose arms are the leaves of its Reeb graph.
#pragma once

#include "reebkit/mesh/shapes.h"
#include "reebkit/pipeline/analyze_mesh.h"

namespace reebkit::test {

inline StarOptions five_arms() {
  StarOptions star;
  star.arms = 5;
  star.levels = 4;
  star.twist = 0.3;
  return star;
}

inline const MeshAnalysis& star_analysis() {
  static const MeshAnalysis a = analyze_mesh(make_star(five_arms()));
  return a;
}

/// The leaf region holding feature point `k` (the tip of an arm).
inline Index leaf_of_feature(const MeshAnalysis& a, std::size_t k) {
  return a.reeb.vertex_node[static_cast<std::size_t>(a.features.vertices[k])];
}

inline Vec3 row(const Mesh& m, Index v) { return m.vertices.row(v).transpose(); }

}  // namespace reebkit::test

// The entries the collection-file tests write and check: deterministic
// from their index, shared by tests/store/collection_file_test.cpp and the
// writer it crashes (tests/store/crash_writer.cpp).
#pragma once

#include "reebkit/store/collection_file.h"

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

namespace reebkit::test {

/// A deterministic entry for index i: graphs of 0 to 49 nodes, some failed
/// entries (i % 11 == 5), UTF-8 names (i % 7 == 3), missing classes, feature
/// points on added vertices (-1), nodes without skeleton points.
inline GraphRecord make_entry(std::int64_t i) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ULL + 1);
  std::uniform_real_distribution<double> real(-1e3, 1e3);
  const auto below = [&](std::int32_t n) { return static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(n)); };
  GraphRecord e;
  e.name = (i % 7 == 3 ? "Ünïcødé/蛇 " : "shrec/") + std::to_string(i) + ".off";
  e.class_label = i % 3 == 0 ? "" : "class " + std::to_string(i % 5);
  e.content_hash = rng();
  for (double& t : e.timings) t = std::abs(real(rng));
  if (i % 11 == 5) {
    e.error = "mesh " + std::to_string(i) + ".off:3: vertex «x» is not a number";
    return e;
  }
  e.ok = true;
  e.vertices = below(100000);
  e.faces = 2 * e.vertices - 4;
  const std::int32_t n = i % 13 == 0 ? 0 : 1 + below(49);
  e.skeleton_offset.push_back(0);
  for (std::int32_t k = 0; k < n; ++k) {
    e.nodes.insert(e.nodes.end(), {k % 5, (k + 1) % 5, below(100000), 1 + below(5000)});
    for (int c = 0; c < kGeomColumnCount; ++c) e.node_geometry.push_back(real(rng));
    for (int c = 0; c < kNodeAttributeCount; ++c) e.node_attributes.push_back(real(rng));
    const std::int32_t points = below(4);
    for (std::int32_t p = 0; p < 3 * points; ++p) e.skeleton_points.push_back(real(rng));
    e.skeleton_offset.push_back(e.skeleton_offset.back() + points);
  }
  const std::int32_t m = n < 2 ? 0 : n - 1 + below(3);
  for (std::int32_t k = 0; k < m; ++k) {
    const std::int32_t a = below(n - 1);
    e.edges.insert(e.edges.end(), {a, a + 1 + below(n - 1 - a)});
    for (int c = 0; c < kEdgeAttributeCount; ++c) e.edge_attributes.push_back(real(rng));
  }
  for (std::int32_t k = below(12); k > 0; --k) e.feature_points.push_back(below(100001) - 1);
  for (int c = 0; c < kSignatureLength; ++c) e.signature.push_back(real(rng));
  return e;
}

inline Provenance test_provenance() {
  Provenance p;
  p.options = R"({"reeb_graph": true})";
  p.analysis_options = {{"epsilon", 0.05}, {"geodesic", std::string("fmm")}, {"start_vertex", std::int64_t{-7}}};
  p.command = "reeb index «meshes» -o c.h5";
  p.classes = {{"star", "0", {"m2", "m10", "m1"}}, {"empty", "star", {}}, {"torus «ring»", "0", {"m6"}}};
  p.classes_file = "classes/«c».cla";
  return p;
}

/// The crash child checkpoints after entry i when this holds: irregular gaps
/// of 1 to 5 entries, so that kills land in writes, flushes and commits.
inline bool checkpoint_after(std::int64_t i) { return (i * 2654435761LL) % 5 == 0 || i % 5 == 4; }

}  // namespace reebkit::test

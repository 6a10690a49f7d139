// Helpers of the collection tests: a small collection on disk, extraction
// options, and comparisons of entries and files.
#pragma once

#include "io/io_test_util.h"
#include "reebkit/collection/extract_collection.h"
#include "reebkit/io/off.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/store/collection_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

namespace reebkit::test {

/// Seven small meshes (stars with 1-5 arms, two tori) and a broken file, in a
/// folder: the input order is broken.off, m1.off ... m7.off.
inline std::vector<MeshInput> write_collection(const TempDir& dir) {
  std::filesystem::create_directories(dir / "meshes");
  for (int arms = 1; arms <= 5; ++arms)
    write_off(dir / ("meshes/m" + std::to_string(arms) + ".off"), make_star(StarOptions{arms, 2}));
  write_off(dir / "meshes/m6.off", make_torus(24, 10));
  write_off(dir / "meshes/m7.off", make_torus(30, 8, 1.0, 0.25));
  std::ofstream(dir / "meshes/broken.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n";
  return list_mesh_inputs({(dir / "meshes").string()});
}

inline ExtractionOptions with_threads(int threads) {
  ExtractionOptions options;
  options.threads = threads;
  options.batch_size = 2;  // workers wait for the writer: the ring wraps around
  return options;
}

/// Every field but the timings.
inline void expect_same(const GraphRecord& a, const GraphRecord& b) {
  SCOPED_TRACE(a.name);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.class_label, b.class_label);
  EXPECT_EQ(a.content_hash, b.content_hash);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.ok, b.ok);
  EXPECT_EQ(a.error, b.error);
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.node_geometry, b.node_geometry);
  EXPECT_EQ(a.node_attributes, b.node_attributes);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_attributes, b.edge_attributes);
  EXPECT_EQ(a.feature_points, b.feature_points);
  EXPECT_EQ(a.skeleton_offset, b.skeleton_offset);
  EXPECT_EQ(a.skeleton_points, b.skeleton_points);
  ASSERT_EQ(a.signature.size(), b.signature.size());
  for (std::size_t k = 0; k < a.signature.size(); ++k)  // NaN == NaN for failed entries
    EXPECT_TRUE(a.signature[k] == b.signature[k] || (std::isnan(a.signature[k]) && std::isnan(b.signature[k]))) << k;
}

inline void expect_same_files(const std::filesystem::path& a, const std::filesystem::path& b) {
  const CollectionReader ra(a), rb(b);
  ASSERT_EQ(ra.size(), rb.size());
  for (std::int64_t i = 0; i < ra.size(); ++i) expect_same(ra.entry(i), rb.entry(i));
}

}  // namespace reebkit::test

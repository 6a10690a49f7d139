// What the mesh readers share: the wording of the problems every format can
// have (so that an error reads the same whether it came from an OFF, OBJ, PLY
// or STL file), and small helpers for the data they collect.
#pragma once

#include "reebkit/core/types.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace reebkit {

/// The largest element count a reader accepts: every index must fit reebkit::Index.
inline constexpr std::int64_t kMaxFileCount = std::numeric_limits<Index>::max();

/// How many of `declared` items to reserve room for when each takes at least
/// `least_bytes` of the `bytes_left`: a lying header cannot make a reader
/// reserve more memory than the file could fill.
inline std::size_t reservable(std::int64_t declared, std::size_t bytes_left, std::size_t least_bytes) {
  return std::min(static_cast<std::size_t>(std::max<std::int64_t>(declared, 0)), bytes_left / least_bytes + 1);
}

inline bool all_finite(double x, double y, double z) {
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

/// Rows of x y z as a #V x 3 array.
inline Points points_from(const std::vector<double>& xyz) {
  return Eigen::Map<const Points>(xyz.data(), static_cast<Eigen::Index>(xyz.size() / 3), 3);
}

/// The problem texts of MeshFileError.
namespace read_problem {

/// "truncated: file ends after 5 of 8 vertices"
inline std::string truncated(std::int64_t read, std::int64_t declared, const std::string& items) {
  return "truncated: file ends after " + std::to_string(read) + " of " + std::to_string(declared) + " " + items;
}

/// "bad vertex count -3"
inline std::string bad_count(const std::string& items, std::int64_t count) {
  return "bad " + items + " count " + std::to_string(count);
}

/// "face 3 has 2 vertices; a polygon needs at least 3"
inline std::string polygon_too_small(std::int64_t face, std::int64_t size) {
  return "face " + std::to_string(face) + " has " + std::to_string(size) + " vertices; a polygon needs at least 3";
}

/// "face 3 refers to vertex 12, but there are 8 vertices"
inline std::string index_out_of_range(std::int64_t face, std::int64_t index, std::int64_t num_vertices) {
  return "face " + std::to_string(face) + " refers to vertex " + std::to_string(index) + ", but there are " +
         std::to_string(num_vertices) + " vertices";
}

/// "vertex 4 has a non-finite coordinate"
inline std::string non_finite(std::int64_t vertex) {
  return "vertex " + std::to_string(vertex) + " has a non-finite coordinate";
}

}  // namespace read_problem
}  // namespace reebkit

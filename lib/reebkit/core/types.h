// Basic types shared by every step of the reebkit pipeline.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace reebkit {

/// The one index type for vertices, faces, edges and graph nodes.
using Index = std::int32_t;

/// #V x 3 vertex positions, row-major so that a vertex is contiguous.
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// #F x 3 vertex indices of triangles, row-major.
using Triangles = Eigen::Matrix<Index, Eigen::Dynamic, 3, Eigen::RowMajor>;

using Vec3 = Eigen::Vector3d;

/// Marks "no vertex / no node".
inline constexpr Index kInvalidIndex = -1;

}  // namespace reebkit

// Wavefront OBJ reader (geometry only).
//
// Reads "v x y z [w]" and "v x y z r g b" (colors in [0,1]; kept only when every
// vertex has them), "f" with "a", "a/b", "a/b/c" and "a//c" corners, negative
// (relative) indices and polygons of any size, '#' comments and '\' line
// continuation. Texture coordinates, normals, groups, objects, smoothing,
// materials, lines and every other statement are skipped.
#pragma once

#include "reebkit/core/mesh.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace reebkit {

/// Reads an OBJ file into a polygon soup (0-based indices).
/// Throws MeshFileError naming the file, the line and the problem.
PolygonSoup read_obj(const std::filesystem::path& path);

/// Parses OBJ text; `source` names it in the soup and in error messages.
PolygonSoup parse_obj(std::string_view text, std::string source);

}  // namespace reebkit

// Reading and writing meshes by file name: the format follows the extension.
#pragma once

#include "reebkit/core/mesh.h"

#include <filesystem>
#include <string_view>

namespace reebkit {

/// Reads a .off, .obj, .ply or .stl file (extension in any case) into a
/// polygon soup; see off.h, obj.h, ply.h and stl.h for what each reader accepts.
/// Throws MeshFileError naming the file and the problem, also for an
/// extension it does not know.
PolygonSoup read_polygon_soup(const std::filesystem::path& path);

/// The same on the bytes of the file `path`, already read (the extension of
/// `path` picks the format; errors name `path`).
PolygonSoup parse_polygon_soup(std::string_view bytes, const std::filesystem::path& path);

/// Writes `mesh` as .off or .ply (binary little-endian), after the extension
/// in any case. Throws MeshFileError for another extension or a failed write.
void write_mesh(const std::filesystem::path& path, const Mesh& mesh);

}  // namespace reebkit

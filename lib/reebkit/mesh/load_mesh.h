// Reading a mesh file into clean triangle meshes: read_polygon_soup followed
// by clean_mesh.
#pragma once

#include "reebkit/mesh/mesh_cleanup.h"

#include <filesystem>
#include <string_view>

namespace reebkit {

/// Reads `path` (OFF, OBJ, PLY or STL) and cleans it with `options`.
/// Throws MeshFileError when the file cannot be read or parsed and
/// InvalidMeshError when it holds no usable mesh; both name the file.
CleanedMesh load_mesh(const std::filesystem::path& path, const CleanupOptions& options = {});

/// The same on the bytes of the file `path`, already read (to hash them and
/// parse them from one read).
CleanedMesh load_mesh_bytes(std::string_view bytes, const std::filesystem::path& path,
                            const CleanupOptions& options = {});

}  // namespace reebkit

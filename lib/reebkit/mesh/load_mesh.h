// Reading a mesh file into clean triangle meshes: read_polygon_soup followed
// by clean_mesh.
#pragma once

#include "reebkit/mesh/mesh_cleanup.h"

#include <filesystem>

namespace reebkit {

/// Reads `path` (OFF, OBJ, PLY or STL) and cleans it with `options`.
/// Throws MeshFileError when the file cannot be read or parsed and
/// InvalidMeshError when it holds no usable mesh; both name the file.
CleanedMesh load_mesh(const std::filesystem::path& path, const CleanupOptions& options = {});

}  // namespace reebkit

// SHREC 2007 feature-point files (features/<id>.vts of the watertight
// track): the hand-picked points of a model, one a line, "VERTEX_ID X Y Z",
// VERTEX_ID numbering the vertices of the model's OFF file.
#pragma once

#include "reebkit/core/types.h"

#include <filesystem>
#include <vector>

namespace reebkit {

/// The vertex ids of a .vts file, in file order (blank lines skipped).
/// Throws MeshFileError naming the file (and line) when it cannot be read or
/// a line is not an id >= 0 followed by three numbers.
std::vector<Index> read_vts(const std::filesystem::path& path);

}  // namespace reebkit

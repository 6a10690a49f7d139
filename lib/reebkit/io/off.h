// Object File Format (Geomview OFF) reader and writer.
//
// Reads the text variants met in practice: OFF, COFF (per-vertex colors),
// NOFF (per-vertex normals, skipped), CNOFF/NCOFF (both), with the counts on
// the header line ("OFF 8 6 0") or on the next one, with or without the edge
// count, '#' comments anywhere, blank lines, CRLF line endings, and face lines
// that carry a face color (ignored). Binary OFF is not supported.
#pragma once

#include "reebkit/core/mesh.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace reebkit {

/// Reads an OFF file into a polygon soup (0-based indices, polygons of any size).
/// Vertex colors, given as 0-255 integers or 0-1 floats, end up in
/// soup.vertex_colors in [0,1]: a file whose color values all lie in [0,1] is
/// read as floats, any other as 0-255.
/// Throws MeshFileError naming the file, the line and the problem.
PolygonSoup read_off(const std::filesystem::path& path);

/// Parses OFF text; `source` names it in the soup and in error messages.
PolygonSoup parse_off(std::string_view text, std::string source);

/// Writes `mesh` as an OFF file, coordinates in their shortest exact form
/// (they read back bit for bit). Throws MeshFileError when the file cannot be written.
void write_off(const std::filesystem::path& path, const Mesh& mesh);

}  // namespace reebkit

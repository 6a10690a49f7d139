// STL (stereolithography) reader, ASCII and binary.
//
// A file is read as binary when its size is exactly 84 + 50 n bytes for the
// triangle count n stored at byte 80 (binary files whose 80-byte header starts
// with "solid" exist), as ASCII when it starts with "solid", and otherwise as a
// binary file that may carry trailing bytes.
//
// STL stores every triangle with its own three corners and no shared
// vertices, so the reader welds corners with bit-identical coordinates
// (-0 and +0 count as equal) into one vertex: the soup then has the real
// connectivity of the surface. Nothing else is merged: corners that differ in
// the last bit stay apart.
#pragma once

#include "reebkit/core/mesh.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace reebkit {

/// Reads an STL file into a polygon soup of welded vertices and triangles
/// (ASCII facets with more than three corners become polygons).
/// Throws MeshFileError naming the file, the problem and, for ASCII, the line.
PolygonSoup read_stl(const std::filesystem::path& path);

/// Parses the bytes of an STL file; `source` names it in the soup and in errors.
PolygonSoup parse_stl(std::string_view bytes, std::string source);

}  // namespace reebkit

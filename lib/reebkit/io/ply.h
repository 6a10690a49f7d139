// Stanford PLY reader and writer.
//
// Reads the ascii (one element item per line), binary_little_endian and
// binary_big_endian encodings.
// Vertex positions x y z may have any scalar type (char uchar short ushort int
// uint float double, or the int8 ... float64 aliases); faces come from the list
// property "vertex_indices" (or "vertex_index") of any integer count and item
// types; vertex "red green blue" (integers 0-255 or floats 0-1) become
// vertex colors in [0,1]. Every other property and element (normals, "edge",
// "material", list properties on vertices, ...) is skipped, wherever it sits.
#pragma once

#include "reebkit/core/mesh.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace reebkit {

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

/// Per-vertex data written next to the positions.
struct PlyVertexData {
  Points colors;  ///< #V x 3 in [0,1], written as uchar red/green/blue; or empty
  /// Named per-vertex values (#V each), written as double properties.
  std::vector<std::pair<std::string, std::vector<double>>> scalars;
};

/// Reads a PLY file into a polygon soup (0-based indices, polygons of any
/// size); a file without faces (a point cloud) gives a soup without polygons.
/// Throws MeshFileError naming the file, the problem and, in ascii files, the line.
PolygonSoup read_ply(const std::filesystem::path& path);

/// Parses the bytes of a PLY file; `source` names it in the soup and in errors.
PolygonSoup parse_ply(std::string_view bytes, std::string source);

/// Writes `mesh` with positions as double (they read back bit for bit) and
/// triangles as "list uchar int vertex_indices", plus `data`.
/// Throws InvalidArgument when `data` does not have one row/value per vertex or
/// a scalar name is empty, holds a blank or repeats a property name, and
/// MeshFileError when the file cannot be written.
void write_ply(const std::filesystem::path& path, const Mesh& mesh, const PlyVertexData& data = {},
               PlyEncoding encoding = PlyEncoding::BinaryLittleEndian);

}  // namespace reebkit

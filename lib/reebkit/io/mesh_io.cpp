#include "reebkit/io/mesh_io.h"

#include "reebkit/core/error.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/obj.h"
#include "reebkit/io/off.h"
#include "reebkit/io/ply.h"
#include "reebkit/io/stl.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace reebkit {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

/// "<problem> '<extension>' (supported: <list>)", or "no file extension (supported: <list>)".
std::string unsupported(const std::string& extension, const std::string& problem, const std::string& supported) {
  return (extension.empty() ? "no file extension" : problem + " '" + extension + "'") + " (supported: " + supported +
         ")";
}

/// The reader of `path`'s format, after its extension; throws MeshFileError
/// for an extension it does not know.
using Parser = PolygonSoup (*)(std::string_view, std::string);
Parser parser_of(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".off") return parse_off;
  if (extension == ".obj") return parse_obj;
  if (extension == ".ply") return parse_ply;
  if (extension == ".stl") return parse_stl;
  throw MeshFileError(path.string(), unsupported(extension, "unknown mesh format", ".off, .obj, .ply, .stl"));
}

}  // namespace

PolygonSoup parse_polygon_soup(std::string_view bytes, const std::filesystem::path& path) {
  return parser_of(path)(bytes, path.string());
}

PolygonSoup read_polygon_soup(const std::filesystem::path& path) {
  const Parser parse = parser_of(path);  // an unknown extension is an error before the file is read
  return parse(read_file_bytes(path), path.string());
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh) {
  const std::string extension = lower_extension(path);
  if (extension == ".off") return write_off(path, mesh);
  if (extension == ".ply") return write_ply(path, mesh);
  throw MeshFileError(path.string(), unsupported(extension, "cannot write format", ".off, .ply"));
}

}  // namespace reebkit

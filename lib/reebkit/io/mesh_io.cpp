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
  return (extension.empty() ? "no file extension" : problem + " '" + extension + "'") + " (supported: " + supported + ")";
}

}  // namespace

PolygonSoup parse_polygon_soup(std::string_view bytes, const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".off") return parse_off(bytes, path.string());
  if (extension == ".obj") return parse_obj(bytes, path.string());
  if (extension == ".ply") return parse_ply(bytes, path.string());
  if (extension == ".stl") return parse_stl(bytes, path.string());
  throw MeshFileError(path.string(), unsupported(extension, "unknown mesh format", ".off, .obj, .ply, .stl"));
}

PolygonSoup read_polygon_soup(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl")
    return parse_polygon_soup({}, path);  // the error, before the file is read
  return parse_polygon_soup(read_file_bytes(path), path);
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh) {
  const std::string extension = lower_extension(path);
  if (extension == ".off") return write_off(path, mesh);
  if (extension == ".ply") return write_ply(path, mesh);
  throw MeshFileError(path.string(), unsupported(extension, "cannot write format", ".off, .ply"));
}

}  // namespace reebkit

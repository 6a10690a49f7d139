#include "reebkit/io/mesh_io.h"

#include "reebkit/core/error.h"
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

PolygonSoup read_polygon_soup(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".off") return read_off(path);
  if (extension == ".obj") return read_obj(path);
  if (extension == ".ply") return read_ply(path);
  if (extension == ".stl") return read_stl(path);
  throw MeshFileError(path.string(), unsupported(extension, "unknown mesh format", ".off, .obj, .ply, .stl"));
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh) {
  const std::string extension = lower_extension(path);
  if (extension == ".off") return write_off(path, mesh);
  if (extension == ".ply") return write_ply(path, mesh);
  throw MeshFileError(path.string(), unsupported(extension, "cannot write format", ".off, .ply"));
}

}  // namespace reebkit

#include "reebkit/mesh/load_mesh.h"

#include "reebkit/io/mesh_io.h"

#include <utility>

namespace reebkit {

namespace {

CleanedMesh cleaned(PolygonSoup soup, const std::filesystem::path& path, const CleanupOptions& options) {
  if (soup.source.empty()) soup.source = path.string();  // so that cleanup errors name the file
  return clean_mesh(std::move(soup), options);
}

}  // namespace

CleanedMesh load_mesh(const std::filesystem::path& path, const CleanupOptions& options) {
  return cleaned(read_polygon_soup(path), path, options);
}

CleanedMesh load_mesh_bytes(std::string_view bytes, const std::filesystem::path& path, const CleanupOptions& options) {
  return cleaned(parse_polygon_soup(bytes, path), path, options);
}

}  // namespace reebkit

#include "reebkit/mesh/load_mesh.h"

#include "reebkit/io/mesh_io.h"

namespace reebkit {

CleanedMesh load_mesh(const std::filesystem::path& path, const CleanupOptions& options) {
  PolygonSoup soup = read_polygon_soup(path);
  if (soup.source.empty()) soup.source = path.string();  // so that cleanup errors name the file
  return clean_mesh(soup, options);
}

}  // namespace reebkit

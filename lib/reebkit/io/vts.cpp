#include "reebkit/io/vts.h"

#include "reebkit/core/error.h"
#include "reebkit/io/file_bytes.h"

#include <limits>
#include <sstream>
#include <string>

namespace reebkit {

std::vector<Index> read_vts(const std::filesystem::path& path) {
  std::istringstream in(read_file_bytes(path));
  std::vector<Index> ids;
  std::uint64_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    long long id = -1;
    double x = 0, y = 0, z = 0;
    if (!(fields >> id >> x >> y >> z) || !(fields >> std::ws).eof() || id < 0 ||
        id > std::numeric_limits<Index>::max())
      throw MeshFileError(path.string(), number, "expected VERTEX_ID X Y Z, got '" + line + "'");
    ids.push_back(static_cast<Index>(id));
  }
  return ids;
}

}  // namespace reebkit

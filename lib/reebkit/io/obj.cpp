#include "reebkit/io/obj.h"

#include "reebkit/io/file_bytes.h"
#include "reebkit/io/reader_common.h"
#include "reebkit/io/text_scanner.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <vector>

namespace reebkit {

namespace {

/// A face corner that names a vertex not read yet; valid only if the file
/// defines that vertex further down, which is known at the end.
struct ForwardReference {
  std::int64_t face;
  std::uint64_t line;
  std::int64_t written;  ///< the index as the file writes it (1-based)
};

/// The vertices and faces read so far.
struct ObjContent {
  std::vector<double> positions;  ///< x y z per vertex
  std::vector<double> colors;     ///< r g b per colored vertex
  std::vector<ForwardReference> forward;
  PolygonSoup soup;

  std::int64_t num_vertices() const { return static_cast<std::int64_t>(positions.size() / 3); }
};

/// Statement keywords are lower-case words ("vt", "usemtl", "c_interp").
bool is_keyword(std::string_view token) {
  if (!std::islower(static_cast<unsigned char>(token.front()))) return false;
  for (const char c : token) {
    if (!std::islower(static_cast<unsigned char>(c)) && !std::isdigit(static_cast<unsigned char>(c)) && c != '_') {
      return false;
    }
  }
  return true;
}

/// "v x y z", "v x y z w" or "v x y z r g b".
void read_vertex(TextScanner& in, ObjContent& obj) {
  double xyz[3];
  for (double& x : xyz) x = in.number_on_line("a vertex coordinate");
  if (!all_finite(xyz[0], xyz[1], xyz[2])) in.fail(read_problem::non_finite(obj.num_vertices()));
  obj.positions.insert(obj.positions.end(), xyz, xyz + 3);

  const std::string_view first = in.token_on_line();
  const std::string_view second = first.empty() ? first : in.token_on_line();
  if (second.empty()) return;  // no extra value, or the weight w
  obj.colors.push_back(in.to_number(first, "a color component"));
  obj.colors.push_back(in.to_number(second, "a color component"));
  obj.colors.push_back(in.number_on_line("a color component"));
}

/// "f a b c ...", each corner "a", "a/b", "a/b/c" or "a//c"; a < 0 counts back
/// from the latest vertex.
void read_face(TextScanner& in, ObjContent& obj) {
  PolygonSoup& soup = obj.soup;
  const std::int64_t face = soup.num_polygons();
  const std::int64_t num_vertices = obj.num_vertices();
  std::int64_t size = 0;
  for (std::string_view corner = in.token_on_line(); !corner.empty(); corner = in.token_on_line(), ++size) {
    const std::string_view written = corner.substr(0, corner.find('/'));
    if (written.empty()) in.fail("expected a vertex index, found " + quoted(corner));
    const std::int64_t index = in.to_integer(written, "a vertex index");
    if (index == 0) in.fail("face " + std::to_string(face) + " refers to vertex 0, but OBJ indices start at 1");
    const std::int64_t resolved = index > 0 ? index - 1 : num_vertices + index;
    if (resolved < 0) in.fail(read_problem::index_out_of_range(face, index, num_vertices));
    if (resolved >= num_vertices) obj.forward.push_back({face, in.line(), index});
    soup.face_vertex.push_back(static_cast<Index>(std::min(resolved, kMaxFileCount)));
  }
  if (size < 3) in.fail(read_problem::polygon_too_small(face, size));
  soup.face_offset.push_back(static_cast<Index>(soup.face_vertex.size()));
}

}  // namespace

PolygonSoup parse_obj(std::string_view text, std::string source) {
  TextScanner in(text, source, {'#', true});
  if (!in.skip_to_token()) in.fail("empty file");
  ObjContent obj;
  do {
    const std::string_view keyword = in.token_on_line();
    if (keyword == "v") {
      read_vertex(in, obj);
    } else if (keyword == "f") {
      read_face(in, obj);
    } else if (!is_keyword(keyword)) {
      in.fail("expected an OBJ statement, found " + quoted(keyword));
    }
    in.next_line();
  } while (in.skip_to_token());

  const std::int64_t num_vertices = obj.num_vertices();
  for (const ForwardReference& ref : obj.forward) {
    if (ref.written > num_vertices) {
      throw MeshFileError(source, ref.line, read_problem::index_out_of_range(ref.face, ref.written, num_vertices));
    }
  }

  PolygonSoup soup = std::move(obj.soup);
  soup.source = std::move(source);
  soup.vertices = Eigen::Map<const Points>(obj.positions.data(), static_cast<Eigen::Index>(num_vertices), 3);
  if (static_cast<std::int64_t>(obj.colors.size()) == 3 * num_vertices && num_vertices > 0) {
    soup.vertex_colors = Eigen::Map<const Points>(obj.colors.data(), static_cast<Eigen::Index>(num_vertices), 3);
  }
  return soup;
}

PolygonSoup read_obj(const std::filesystem::path& path) { return parse_obj(read_file_bytes(path), path.string()); }

}  // namespace reebkit

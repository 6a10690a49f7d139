#include "reebkit/io/off.h"

#include "reebkit/io/file_bytes.h"
#include "reebkit/io/number_text.h"
#include "reebkit/io/reader_common.h"
#include "reebkit/io/text_scanner.h"

#include <cstdint>
#include <vector>

namespace reebkit {

namespace {

/// What the header keyword says each vertex line holds after x y z.
struct VertexLayout {
  bool normals = false;
  bool colors = false;
};

/// "OFF", "COFF", "NOFF", "CNOFF", "NCOFF" (and "ST" texture coordinates,
/// which trail the line and are skipped with it).
VertexLayout parse_keyword(std::string_view keyword, const TextScanner& in) {
  constexpr std::string_view kOff = "OFF";
  if (keyword.size() < kOff.size() || keyword.substr(keyword.size() - kOff.size()) != kOff) {
    in.fail("expected an OFF header, found " + quoted(keyword));
  }
  VertexLayout layout;
  for (const char c : keyword.substr(0, keyword.size() - kOff.size())) {
    if (c == 'C') {
      layout.colors = true;
    } else if (c == 'N') {
      layout.normals = true;
    } else if (c != 'S' && c != 'T') {
      in.fail("unsupported OFF variant " + quoted(keyword));
    }
  }
  return layout;
}

std::int64_t to_count(const TextScanner& in, std::string_view token, const std::string& items) {
  const std::int64_t count = in.to_integer(token, ("the " + items + " count").c_str());
  if (count < 0 || count > kMaxFileCount) in.fail(read_problem::bad_count(items, count));
  return count;
}

void read_vertices(TextScanner& in, std::int64_t num_vertices, const VertexLayout& layout, PolygonSoup& soup) {
  std::vector<double> xyz;
  std::vector<double> rgb;
  const std::size_t expected = reservable(num_vertices, in.bytes_left(), 6);  // "0 0 0\n"
  xyz.reserve(3 * expected);
  if (layout.colors) rgb.reserve(3 * expected);
  for (std::int64_t v = 0; v < num_vertices; ++v) {
    if (!in.skip_to_token()) in.fail(read_problem::truncated(v, num_vertices, "vertices"));
    const double x = in.number_on_line("a vertex coordinate");
    const double y = in.number_on_line("a vertex coordinate");
    const double z = in.number_on_line("a vertex coordinate");
    if (!all_finite(x, y, z)) in.fail(read_problem::non_finite(v));
    xyz.insert(xyz.end(), {x, y, z});
    if (layout.normals) {
      for (int k = 0; k < 3; ++k) in.number_on_line("a normal component");
    }
    if (layout.colors) {
      for (int k = 0; k < 3; ++k) rgb.push_back(in.number_on_line("a color component"));
    }
    in.next_line();  // drops an alpha value, texture coordinates and comments
  }
  soup.vertices = points_from(xyz);
  soup.vertex_colors = points_from(rgb);
  if (!rgb.empty() && soup.vertex_colors.maxCoeff() > 1.0) soup.vertex_colors /= 255.0;
}

void read_faces(TextScanner& in, std::int64_t num_faces, PolygonSoup& soup) {
  const Index num_vertices = soup.num_vertices();
  const std::size_t expected = reservable(num_faces, in.bytes_left(), 8);  // "3 0 1 2\n"
  soup.face_offset.reserve(expected + 1);
  soup.face_vertex.reserve(3 * expected);
  for (std::int64_t f = 0; f < num_faces; ++f) {
    if (!in.skip_to_token()) in.fail(read_problem::truncated(f, num_faces, "faces"));
    const std::int64_t size = in.integer_on_line("a polygon size");
    if (size < 3) in.fail(read_problem::polygon_too_small(f, size));
    for (std::int64_t i = 0; i < size; ++i) {
      const std::int64_t index = in.integer_on_line("a vertex index");
      if (index < 0 || index >= num_vertices) in.fail(read_problem::index_out_of_range(f, index, num_vertices));
      soup.face_vertex.push_back(static_cast<Index>(index));
    }
    soup.face_offset.push_back(static_cast<Index>(soup.face_vertex.size()));
    in.next_line();  // drops a face color and comments
  }
}

}  // namespace

PolygonSoup parse_off(std::string_view text, std::string source) {
  TextScanner in(text, source, {'#', false});
  const std::string_view keyword = in.token();
  if (keyword.empty()) in.fail("empty file");
  const VertexLayout layout = parse_keyword(keyword, in);
  // The counts follow the keyword on its line or on the next one; the edge
  // count is optional and not used.
  std::string_view token = in.token_on_line();
  if (token == "BINARY") in.fail("binary OFF is not supported");
  if (token.empty()) token = in.token();
  const std::int64_t num_vertices = to_count(in, token, "vertex");
  const std::int64_t num_faces = to_count(in, in.token(), "face");
  token = in.token_on_line();
  if (!token.empty()) to_count(in, token, "edge");
  in.next_line();

  PolygonSoup soup;
  soup.source = std::move(source);
  read_vertices(in, num_vertices, layout, soup);
  read_faces(in, num_faces, soup);
  return soup;
}

PolygonSoup read_off(const std::filesystem::path& path) { return parse_off(read_file_bytes(path), path.string()); }

void write_off(const std::filesystem::path& path, const Mesh& mesh) {
  std::string out = "OFF\n";
  append_number(out, mesh.num_vertices());
  out += ' ';
  append_number(out, mesh.num_triangles());
  out += " 0\n";
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) {
      append_number(out, mesh.vertices(v, k));
      out += k < 2 ? ' ' : '\n';
    }
  }
  for (Index f = 0; f < mesh.num_triangles(); ++f) {
    out += '3';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_number(out, mesh.triangles(f, k));
    }
    out += '\n';
  }
  write_file_bytes(path, out);
}

}  // namespace reebkit

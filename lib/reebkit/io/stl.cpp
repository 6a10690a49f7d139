#include "reebkit/io/stl.h"

#include "reebkit/core/error.h"
#include "reebkit/io/binary_bytes.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/reader_common.h"
#include "reebkit/io/text_scanner.h"

#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace reebkit {

namespace {

constexpr std::size_t kHeaderBytes = 84;    // 80-byte comment + uint32 triangle count
constexpr std::size_t kTriangleBytes = 50;  // normal, 3 corners (12 floats), uint16 attribute

/// Merges corners with bit-identical coordinates into one vertex.
class Welder {
 public:
  explicit Welder(std::size_t expected_corners) { index_.reserve(expected_corners / 2); }

  Index add(double x, double y, double z) {
    // + 0.0 turns -0.0 into +0.0, so that the two zeros weld.
    x += 0.0;
    y += 0.0;
    z += 0.0;
    const auto [it, inserted] =
        index_.try_emplace(Key{bits(x), bits(y), bits(z)}, static_cast<Index>(positions_.size() / 3));
    if (inserted) positions_.insert(positions_.end(), {x, y, z});
    return it->second;
  }

  Points vertices() const {
    return Eigen::Map<const Points>(positions_.data(), static_cast<Eigen::Index>(positions_.size() / 3), 3);
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      std::uint64_t h = key[0] * 0x9E3779B97F4A7C15ull;
      h = (h ^ (h >> 29) ^ key[1]) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 32) ^ key[2]) * 0x94D049BB133111EBull;
      return static_cast<std::size_t>(h ^ (h >> 31));
    }
  };
  static std::uint64_t bits(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }

  std::unordered_map<Key, Index, KeyHash> index_;
  std::vector<double> positions_;
};

std::string non_finite_corner(std::int64_t facet, int corner) {
  return "facet " + std::to_string(facet) + ", corner " + std::to_string(corner) + " has a non-finite coordinate";
}

std::uint32_t binary_count(std::string_view bytes) {
  ByteReader header(bytes.substr(80, 4), false);
  return header.read<std::uint32_t>();
}

std::uint64_t binary_size(std::uint32_t count) { return kHeaderBytes + kTriangleBytes * std::uint64_t{count}; }

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

bool starts_with_solid(std::string_view bytes) {
  const std::size_t start = bytes.find_first_not_of(" \t\r\n");
  return start != std::string_view::npos && iequals(bytes.substr(start, 5), "solid");
}

/// Precondition: the caller checked that `bytes` holds `count` triangles.
PolygonSoup read_binary(std::string_view bytes, std::uint32_t count, std::string source) {
  ByteReader in(bytes.substr(kHeaderBytes), false);
  Welder welder(3 * std::size_t{count});
  PolygonSoup soup;
  soup.face_offset.reserve(std::size_t{count} + 1);
  soup.face_vertex.reserve(3 * std::size_t{count});
  for (std::uint32_t t = 0; t < count; ++t) {
    in.skip(12);  // the normal
    for (int corner = 0; corner < 3; ++corner) {
      const double x = in.read<float>();
      const double y = in.read<float>();
      const double z = in.read<float>();
      if (!all_finite(x, y, z)) throw MeshFileError(source, non_finite_corner(t, corner));
      soup.face_vertex.push_back(welder.add(x, y, z));
    }
    soup.face_offset.push_back(static_cast<Index>(soup.face_vertex.size()));
    in.skip(2);  // the attribute byte count
  }
  soup.vertices = welder.vertices();
  soup.source = std::move(source);
  return soup;
}

/// Reads the next token and fails unless it is `keyword` (in any case).
void expect(TextScanner& in, std::string_view keyword) {
  const std::string_view token = in.token();
  if (iequals(token, keyword)) return;
  const std::string found = token.empty() ? "the end of the file" : quoted(token);
  in.fail((token.empty() ? "truncated: expected '" : "expected '") + std::string(keyword) + "', found " + found);
}

/// "facet normal ... outer loop vertex x y z ... endloop endfacet", the
/// "facet" already read.
void read_facet(TextScanner& in, std::int64_t facet, Welder& welder, PolygonSoup& soup) {
  in.next_line();  // the normal
  expect(in, "outer");
  expect(in, "loop");
  int corner = 0;
  std::string_view token = in.token();
  for (; iequals(token, "vertex"); token = in.token(), ++corner) {
    const double x = in.number_on_line("a vertex coordinate");
    const double y = in.number_on_line("a vertex coordinate");
    const double z = in.number_on_line("a vertex coordinate");
    if (!all_finite(x, y, z)) in.fail(non_finite_corner(facet, corner));
    soup.face_vertex.push_back(welder.add(x, y, z));
  }
  if (!iequals(token, "endloop")) {
    in.fail("expected 'vertex' or 'endloop', found " + (token.empty() ? "the end of the file" : quoted(token)));
  }
  if (corner < 3) in.fail(read_problem::polygon_too_small(facet, corner));
  soup.face_offset.push_back(static_cast<Index>(soup.face_vertex.size()));
  expect(in, "endfacet");
}

/// One or more "solid ... endsolid" blocks.
PolygonSoup read_ascii(std::string_view text, std::string source) {
  TextScanner in(text, source, {});
  Welder welder(text.size() / 64);  // an ASCII facet takes more than 3 * 64 bytes
  PolygonSoup soup;
  std::int64_t facet = 0;
  expect(in, "solid");
  in.next_line();  // the name
  for (;;) {
    const std::string_view token = in.token();
    if (iequals(token, "facet")) {
      read_facet(in, facet++, welder, soup);
    } else if (iequals(token, "endsolid")) {
      in.next_line();
      if (!in.skip_to_token()) break;
      expect(in, "solid");
      in.next_line();
    } else {
      in.fail((token.empty() ? "truncated: expected 'facet' or 'endsolid', found the end of the file"
                             : "expected 'facet' or 'endsolid', found " + quoted(token)));
    }
  }
  soup.vertices = welder.vertices();
  soup.source = std::move(source);
  return soup;
}

}  // namespace

PolygonSoup parse_stl(std::string_view bytes, std::string source) {
  if (bytes.empty()) throw MeshFileError(source, "empty file");
  const bool has_count = bytes.size() >= kHeaderBytes;
  const std::uint32_t count = has_count ? binary_count(bytes) : 0;
  if (has_count && bytes.size() == binary_size(count)) return read_binary(bytes, count, std::move(source));
  if (starts_with_solid(bytes)) return read_ascii(bytes, std::move(source));
  if (!has_count) {
    throw MeshFileError(source, "truncated: not ASCII STL, and a binary STL needs " + std::to_string(kHeaderBytes) +
                                    " header bytes, the file has " + std::to_string(bytes.size()));
  }
  if (bytes.size() < binary_size(count)) {
    throw MeshFileError(source, "truncated: the binary header declares " + std::to_string(count) +
                                    " triangles, which take " + std::to_string(binary_size(count)) +
                                    " bytes, the file has " + std::to_string(bytes.size()));
  }
  return read_binary(bytes, count, std::move(source));  // with trailing bytes
}

PolygonSoup read_stl(const std::filesystem::path& path) { return parse_stl(read_file_bytes(path), path.string()); }

}  // namespace reebkit

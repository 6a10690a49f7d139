#include "reebkit/io/ply.h"

#include "reebkit/core/error.h"
#include "reebkit/io/binary_bytes.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/number_text.h"
#include "reebkit/io/reader_common.h"
#include "reebkit/io/text_scanner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <optional>
#include <utility>

namespace reebkit {

namespace {

enum class Type : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct TypeInfo {
  std::string_view name;
  std::string_view alias;
  std::size_t size;
  bool integer;
};

/// Indexed by Type.
constexpr TypeInfo kTypes[] = {
    {"char", "int8", 1, true},      {"uchar", "uint8", 1, true},     {"short", "int16", 2, true},
    {"ushort", "uint16", 2, true},  {"int", "int32", 4, true},       {"uint", "uint32", 4, true},
    {"float", "float32", 4, false}, {"double", "float64", 8, false},
};

const TypeInfo& info(Type type) { return kTypes[static_cast<std::size_t>(type)]; }

std::optional<Type> parse_type(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kTypes); ++i) {
    if (name == kTypes[i].name || name == kTypes[i].alias) return static_cast<Type>(i);
  }
  return std::nullopt;
}

/// What the reader does with the values of a property.
enum class Role : std::uint8_t { Skip, X, Y, Z, Red, Green, Blue, Corners };

/// Where a vertex value goes in the per-item buffer: x y z r g b.
std::size_t slot(Role role) { return static_cast<std::size_t>(role) - static_cast<std::size_t>(Role::X); }

struct Property {
  std::string name;
  Type type = Type::Float32;
  bool is_list = false;
  Type count_type = Type::UInt8;
  Role role = Role::Skip;
  double factor = 1.0;  ///< scales the value (0-255 colors to [0,1])
};

enum class Kind : std::uint8_t { Vertex, Face, Other };

struct Element {
  std::string name;
  std::int64_t count = 0;
  std::vector<Property> properties;
  Kind kind = Kind::Other;

  const Property* find(std::string_view property) const {
    for (const Property& p : properties) {
      if (p.name == property) return &p;
    }
    return nullptr;
  }
  /// "vertices", "faces", "'edge' elements": for truncation messages.
  std::string items() const {
    return kind == Kind::Vertex ? "vertices" : kind == Kind::Face ? "faces" : "'" + name + "' elements";
  }
};

struct Header {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<Element> elements;
  std::int64_t num_vertices = 0;
  bool has_colors = false;
};

// ---------------------------------------------------------------------------
// Header

Type to_type(const TextScanner& in, std::string_view name) {
  const std::optional<Type> type = parse_type(name);
  if (!type) in.fail("unsupported PLY type " + quoted(name));
  return *type;
}

PlyEncoding read_format(TextScanner& in) {
  const std::string_view format = in.token_on_line();
  if (format == "ascii") return PlyEncoding::Ascii;
  if (format == "binary_little_endian") return PlyEncoding::BinaryLittleEndian;
  if (format == "binary_big_endian") return PlyEncoding::BinaryBigEndian;
  in.fail("unsupported PLY format " + quoted(format));
}

/// "property <type> <name>" or "property list <count type> <item type> <name>".
Property read_property(TextScanner& in) {
  Property property;
  std::string_view type = in.token_on_line();
  if (type == "list") {
    property.is_list = true;
    property.count_type = to_type(in, in.token_on_line());
    if (!info(property.count_type).integer) in.fail("the size of a list must have an integer type");
    type = in.token_on_line();
  }
  property.type = to_type(in, type);
  property.name = in.token_on_line();
  if (property.name.empty()) in.fail("a property without a name");
  return property;
}

Element read_element(TextScanner& in) {
  Element element;
  element.name = in.token_on_line();
  if (element.name.empty()) in.fail("an element without a name");
  element.count = in.integer_on_line("an element count");
  if (element.count < 0 || element.count > kMaxFileCount) {
    in.fail(read_problem::bad_count("'" + element.name + "' element", element.count));
  }
  return element;
}

/// Marks x y z (and red green blue when all three are there) for the reader.
void assign_vertex_roles(const TextScanner& in, Element& vertex, Header& header) {
  constexpr std::string_view kPosition[] = {"x", "y", "z"};
  constexpr std::string_view kColor[] = {"red", "green", "blue"};
  const bool has_colors = vertex.find("red") && vertex.find("green") && vertex.find("blue");
  for (Property& p : vertex.properties) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (p.name == kPosition[k]) p.role = static_cast<Role>(static_cast<std::size_t>(Role::X) + k);
      if (p.name == kColor[k] && has_colors) {
        p.role = static_cast<Role>(static_cast<std::size_t>(Role::Red) + k);
        p.factor = info(p.type).integer ? 1.0 / 255.0 : 1.0;
      }
    }
    if (p.role != Role::Skip && p.is_list) in.fail("the vertex property '" + p.name + "' is a list");
  }
  for (const std::string_view name : kPosition) {
    if (!vertex.find(name)) in.fail("the vertex element has no '" + std::string(name) + "' property");
  }
  header.num_vertices = vertex.count;
  header.has_colors = has_colors;
}

/// Marks the list of vertex indices of a face for the reader.
void assign_face_roles(const TextScanner& in, Element& face) {
  for (Property& p : face.properties) {
    if (p.name == "vertex_indices" || p.name == "vertex_index") {
      if (!p.is_list || !info(p.type).integer) in.fail("'" + p.name + "' must be a list of integers");
      p.role = Role::Corners;
      return;
    }
  }
  in.fail("the face element has no 'vertex_indices' list");
}

/// Gives every property its role, once the whole header is known.
void assign_roles(const TextScanner& in, Header& header) {
  bool seen[2] = {false, false};  // a vertex element, a face element
  for (Element& element : header.elements) {
    element.kind = element.name == "vertex" ? Kind::Vertex : element.name == "face" ? Kind::Face : Kind::Other;
    if (element.kind == Kind::Other) continue;
    bool& seen_kind = seen[static_cast<std::size_t>(element.kind)];
    if (seen_kind) in.fail("a second '" + element.name + "' element");
    seen_kind = true;
    if (element.kind == Kind::Vertex) {
      assign_vertex_roles(in, element, header);
    } else {
      assign_face_roles(in, element);
    }
  }
  if (!seen[static_cast<std::size_t>(Kind::Vertex)]) in.fail("the header declares no vertex element");
}

/// Reads the header and leaves `in` at the first byte of the body.
Header read_header(TextScanner& in) {
  const std::string_view magic = in.token();
  if (magic.empty()) in.fail("empty file");
  if (magic != "ply") in.fail("not a PLY file: expected 'ply', found " + quoted(magic));
  in.next_line();
  Header header;
  bool has_format = false;
  for (std::string_view keyword = in.token(); keyword != "end_header"; keyword = in.token()) {
    if (keyword.empty()) in.fail("truncated: the header has no 'end_header' line");
    if (keyword == "format") {
      header.encoding = read_format(in);
      has_format = true;
    } else if (keyword == "element") {
      header.elements.push_back(read_element(in));
    } else if (keyword == "property") {
      if (header.elements.empty()) in.fail("a property before the first element");
      header.elements.back().properties.push_back(read_property(in));
    } else if (keyword != "comment" && keyword != "obj_info") {
      in.fail("unexpected header line " + quoted(keyword));
    }
    in.next_line();
  }
  if (!has_format) in.fail("the header has no 'format' line");
  assign_roles(in, header);
  in.next_line();
  return header;
}

/// The fewest bytes an item of `element` can take: an ascii value takes at
/// least a digit and a separator, a binary one its size (a list: its size field).
std::size_t least_item_bytes(const Element& element, PlyEncoding encoding) {
  std::size_t bytes = 0;
  for (const Property& p : element.properties) {
    bytes += encoding == PlyEncoding::Ascii ? 2 : info(p.is_list ? p.count_type : p.type).size;
  }
  return std::max<std::size_t>(bytes, 1);
}

// ---------------------------------------------------------------------------
// Body: the same item loop reads all three encodings through a value source.

/// Thrown by a value source when the data ends before an item does.
struct EndOfData {};

/// Ascii body: one element item per line.
class AsciiValues {
 public:
  explicit AsciiValues(TextScanner& in) : in_(in) {}

  void begin_item() {
    if (!in_.skip_to_token()) throw EndOfData{};
  }
  void end_item() { in_.next_line(); }
  double number(Type) { return in_.number_on_line("a number"); }
  std::int64_t integer(Type) { return in_.integer_on_line("an integer"); }
  void skip(Type) {
    if (in_.token_on_line().empty()) in_.fail("expected a value, found the end of the line");
  }
  [[noreturn]] void fail(const std::string& problem) const { in_.fail(problem); }

 private:
  TextScanner& in_;
};

/// Binary body in either byte order.
class BinaryValues {
 public:
  BinaryValues(std::string_view body, bool big_endian, std::string source)
      : bytes_(body, big_endian), source_(std::move(source)) {}

  void begin_item() {}
  void end_item() {}
  double number(Type type) { return read_as<double>(type); }
  std::int64_t integer(Type type) { return read_as<std::int64_t>(type); }
  void skip(Type type) {
    require(info(type).size);
    bytes_.skip(info(type).size);
  }
  [[noreturn]] void fail(const std::string& problem) const { throw MeshFileError(source_, problem); }

 private:
  void require(std::size_t size) const {
    if (bytes_.remaining() < size) throw EndOfData{};
  }

  template <typename R>
  R read_as(Type type) {
    require(info(type).size);
    switch (type) {
      case Type::Int8: return static_cast<R>(bytes_.read<std::int8_t>());
      case Type::UInt8: return static_cast<R>(bytes_.read<std::uint8_t>());
      case Type::Int16: return static_cast<R>(bytes_.read<std::int16_t>());
      case Type::UInt16: return static_cast<R>(bytes_.read<std::uint16_t>());
      case Type::Int32: return static_cast<R>(bytes_.read<std::int32_t>());
      case Type::UInt32: return static_cast<R>(bytes_.read<std::uint32_t>());
      case Type::Float32: return static_cast<R>(bytes_.read<float>());
      case Type::Float64: return static_cast<R>(bytes_.read<double>());
    }
    return R{};
  }

  ByteReader bytes_;
  std::string source_;
};

template <typename Values>
void read_corners(Values& in, const Property& p, std::int64_t face, std::int64_t num_vertices, PolygonSoup& soup) {
  const std::int64_t size = in.integer(p.count_type);
  if (size < 3) in.fail(read_problem::polygon_too_small(face, size));
  for (std::int64_t i = 0; i < size; ++i) {
    const std::int64_t index = in.integer(p.type);
    if (index < 0 || index >= num_vertices) in.fail(read_problem::index_out_of_range(face, index, num_vertices));
    soup.face_vertex.push_back(static_cast<Index>(index));
  }
  soup.face_offset.push_back(static_cast<Index>(soup.face_vertex.size()));
}

template <typename Values>
void skip_list(Values& in, const Property& p) {
  const std::int64_t size = in.integer(p.count_type);
  if (size < 0) in.fail(read_problem::bad_count("list", size));
  for (std::int64_t i = 0; i < size; ++i) in.skip(p.type);
}

/// What the body holds for the soup.
struct Collected {
  std::vector<double> xyz;  ///< x y z per vertex
  std::vector<double> rgb;  ///< r g b per vertex, when the file has colors
  PolygonSoup soup;
};

/// Reads item `item` of `element`.
template <typename Values>
void read_item(Values& in, const Element& element, std::int64_t item, const Header& header, Collected& out) {
  in.begin_item();
  double vertex[6] = {};  // x y z r g b
  for (const Property& p : element.properties) {
    if (p.role == Role::Corners) {
      read_corners(in, p, item, header.num_vertices, out.soup);
    } else if (p.is_list) {
      skip_list(in, p);
    } else if (p.role == Role::Skip) {
      in.skip(p.type);
    } else {
      vertex[slot(p.role)] = in.number(p.type) * p.factor;
    }
  }
  in.end_item();
  if (element.kind != Kind::Vertex) return;
  if (!all_finite(vertex[0], vertex[1], vertex[2])) in.fail(read_problem::non_finite(item));
  out.xyz.insert(out.xyz.end(), vertex, vertex + 3);
  if (header.has_colors) out.rgb.insert(out.rgb.end(), vertex + 3, vertex + 6);
}

/// Reserves room for the vertices and faces of `element`, as far as the body can hold them.
void reserve(const Element& element, const Header& header, std::size_t body_bytes, Collected& out) {
  const std::size_t expected = reservable(element.count, body_bytes, least_item_bytes(element, header.encoding));
  if (element.kind == Kind::Vertex) {
    out.xyz.reserve(3 * expected);
    if (header.has_colors) out.rgb.reserve(3 * expected);
  } else if (element.kind == Kind::Face) {
    out.soup.face_offset.reserve(expected + 1);
    out.soup.face_vertex.reserve(3 * expected);
  }
}

template <typename Values>
PolygonSoup read_body(Values& in, const Header& header, std::size_t body_bytes, std::string source) {
  Collected out;
  for (const Element& element : header.elements) {
    // A binary element without properties holds no bytes, whatever its count.
    if (element.properties.empty() && header.encoding != PlyEncoding::Ascii) continue;
    reserve(element, header, body_bytes, out);
    std::int64_t item = 0;
    try {
      for (; item < element.count; ++item) read_item(in, element, item, header, out);
    } catch (const EndOfData&) {
      in.fail(read_problem::truncated(item, element.count, element.items()));
    }
  }
  out.soup.vertices = points_from(out.xyz);
  out.soup.vertex_colors = points_from(out.rgb);
  out.soup.source = std::move(source);
  return std::move(out.soup);
}

// ---------------------------------------------------------------------------
// Writer

/// Appends item values in the chosen encoding.
class ValueWriter {
 public:
  ValueWriter(std::string& out, PlyEncoding encoding) : out_(out), encoding_(encoding) {}

  template <typename T>
  void value(T x) {
    if (encoding_ == PlyEncoding::Ascii) {
      append_number(out_, x);
      out_ += ' ';
    } else {
      append_bytes(out_, x, encoding_ == PlyEncoding::BinaryBigEndian);
    }
  }
  void end_item() {
    if (encoding_ == PlyEncoding::Ascii) out_.back() = '\n';
  }

 private:
  std::string& out_;
  PlyEncoding encoding_;
};

void check_vertex_data(const Mesh& mesh, const PlyVertexData& data) {
  const auto num_vertices = static_cast<std::size_t>(mesh.num_vertices());
  if (data.colors.rows() != 0 && static_cast<std::size_t>(data.colors.rows()) != num_vertices) {
    throw InvalidArgument("write_ply: " + std::to_string(data.colors.rows()) + " colors for " +
                          std::to_string(num_vertices) + " vertices");
  }
  std::vector<std::string_view> names = {"x", "y", "z", "red", "green", "blue"};
  for (const auto& [name, values] : data.scalars) {
    if (values.size() != num_vertices) {
      throw InvalidArgument("write_ply: scalar '" + name + "' has " + std::to_string(values.size()) + " values for " +
                            std::to_string(num_vertices) + " vertices");
    }
    if (name.empty() || name.find_first_of(" \t\r\n") != std::string::npos) {
      throw InvalidArgument("write_ply: bad scalar name '" + name + "'");
    }
    if (std::find(names.begin(), names.end(), name) != names.end()) {
      throw InvalidArgument("write_ply: scalar name '" + name + "' repeats a property name");
    }
    names.push_back(name);
  }
}

std::string header_text(const Mesh& mesh, const PlyVertexData& data, PlyEncoding encoding) {
  constexpr std::string_view kFormat[] = {"ascii", "binary_little_endian", "binary_big_endian"};
  std::string out = "ply\nformat ";
  out += kFormat[static_cast<std::size_t>(encoding)];
  out += " 1.0\ncomment written by reebkit\nelement vertex " + std::to_string(mesh.num_vertices()) +
         "\nproperty double x\nproperty double y\nproperty double z\n";
  if (data.colors.rows() > 0) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  for (const auto& scalar : data.scalars) out += "property double " + scalar.first + "\n";
  out +=
      "element face " + std::to_string(mesh.num_triangles()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  return out;
}

/// [0,1] to 0-255; out-of-range values clamp, NaN gives 0.
std::uint8_t color_byte(double c) {
  const double clamped = c >= 0.0 ? (c <= 1.0 ? c : 1.0) : 0.0;
  return static_cast<std::uint8_t>(std::lround(clamped * 255.0));
}

}  // namespace

PolygonSoup parse_ply(std::string_view bytes, std::string source) {
  TextScanner in(bytes, source, {});
  const Header header = read_header(in);
  const std::size_t body_bytes = in.bytes_left();
  if (header.encoding == PlyEncoding::Ascii) {
    AsciiValues values(in);
    return read_body(values, header, body_bytes, std::move(source));
  }
  BinaryValues values(bytes.substr(bytes.size() - body_bytes), header.encoding == PlyEncoding::BinaryBigEndian, source);
  return read_body(values, header, body_bytes, std::move(source));
}

PolygonSoup read_ply(const std::filesystem::path& path) { return parse_ply(read_file_bytes(path), path.string()); }

void write_ply(const std::filesystem::path& path, const Mesh& mesh, const PlyVertexData& data, PlyEncoding encoding) {
  check_vertex_data(mesh, data);
  std::string out = header_text(mesh, data, encoding);
  ValueWriter write(out, encoding);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) write.value(mesh.vertices(v, k));
    if (data.colors.rows() > 0) {
      for (int k = 0; k < 3; ++k) write.value(color_byte(data.colors(v, k)));
    }
    for (const auto& scalar : data.scalars) write.value(scalar.second[static_cast<std::size_t>(v)]);
    write.end_item();
  }
  for (Index f = 0; f < mesh.num_triangles(); ++f) {
    write.value(std::uint8_t{3});
    for (int k = 0; k < 3; ++k) write.value(std::int32_t{mesh.triangles(f, k)});
    write.end_item();
  }
  write_file_bytes(path, out);
}

}  // namespace reebkit

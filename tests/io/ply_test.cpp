#include "reebkit/io/ply.h"

#include "reebkit/io/off.h"

#include "io/io_test_util.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>

namespace reebkit::test {
namespace {

constexpr PlyEncoding kEncodings[] = {PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian,
                                      PlyEncoding::BinaryBigEndian};
const char* const kFormatNames[] = {"ascii", "binary_little_endian", "binary_big_endian"};
const char* format_name(PlyEncoding e) { return kFormatNames[static_cast<int>(e)]; }

// --- a small PLY writer for the tests, independent of write_ply --------------

struct Prop {
  std::string type;
  std::string name;
  std::string count_type = {};  ///< non-empty: a list with this size type
};

struct Elem {
  std::string name;
  std::vector<Prop> props;
  /// One row per item: the property values in order; a list gives its size, then its items.
  std::vector<std::vector<double>> rows;
};

template <typename T>
void put(std::string& out, double value, bool big_endian) {
  auto x = static_cast<T>(value);
  char raw[sizeof(T)];
  std::memcpy(raw, &x, sizeof(T));
  if (big_endian) std::reverse(raw, raw + sizeof(T));  // the tests run on little-endian machines
  out.append(raw, sizeof(T));
}

void put_typed(std::string& out, const std::string& type, double value, bool big_endian) {
  if (type == "char" || type == "int8") return put<std::int8_t>(out, value, big_endian);
  if (type == "uchar" || type == "uint8") return put<std::uint8_t>(out, value, big_endian);
  if (type == "short" || type == "int16") return put<std::int16_t>(out, value, big_endian);
  if (type == "ushort" || type == "uint16") return put<std::uint16_t>(out, value, big_endian);
  if (type == "int" || type == "int32") return put<std::int32_t>(out, value, big_endian);
  if (type == "uint" || type == "uint32") return put<std::uint32_t>(out, value, big_endian);
  if (type == "float" || type == "float32") return put<float>(out, value, big_endian);
  if (type == "double" || type == "float64") return put<double>(out, value, big_endian);
  ADD_FAILURE() << "test writer: unknown type " << type;
}

void put_value(std::string& out, PlyEncoding encoding, const std::string& type, double value) {
  if (encoding != PlyEncoding::Ascii) return put_typed(out, type, value, encoding == PlyEncoding::BinaryBigEndian);
  char digits[32];
  out.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
  out += ' ';
}

std::string build_ply(PlyEncoding encoding, const std::vector<Elem>& elements, const std::string& extra_header = "") {
  std::string out = std::string("ply\nformat ") + format_name(encoding) + " 1.0\n" + extra_header;
  for (const Elem& e : elements) {
    out += "element " + e.name + " " + std::to_string(e.rows.size()) + "\n";
    for (const Prop& p : e.props) {
      out += "property " + (p.count_type.empty() ? "" : "list " + p.count_type + " ") + p.type + " " + p.name + "\n";
    }
  }
  out += "end_header\n";
  for (const Elem& e : elements) {
    for (const auto& row : e.rows) {
      std::size_t next = 0;
      for (const Prop& p : e.props) {
        if (!p.count_type.empty()) {
          const auto size = static_cast<std::size_t>(row.at(next));
          put_value(out, encoding, p.count_type, row.at(next++));
          for (std::size_t i = 0; i < size; ++i) put_value(out, encoding, p.type, row.at(next++));
        } else {
          put_value(out, encoding, p.type, row.at(next++));
        }
      }
      if (encoding == PlyEncoding::Ascii) out.back() = '\n';
    }
  }
  return out;
}

Elem xyz_vertices(const std::string& type) {
  return {"vertex", {{type, "x"}, {type, "y"}, {type, "z"}}, {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {-1, 0, 10}}};
}

Elem triangle_faces(const std::string& count_type = "uchar", const std::string& index_type = "int",
                    const std::string& name = "vertex_indices") {
  return {"face", {{index_type, name, count_type}}, {{3, 0, 1, 2}, {4, 0, 2, 3, 1}}};
}

const Polygons kFaces = {{0, 1, 2}, {0, 2, 3, 1}};

Points expected_xyz() {
  Points p(4, 3);
  p << 1, 2, 3, 4, 5, 6, 7, 8, 9, -1, 0, 10;
  return p;
}

// --- reading -----------------------------------------------------------------

TEST(Ply, EveryScalarTypeForPositionsInEveryEncoding) {
  for (const char* type : {"char", "uchar", "short", "ushort", "int", "uint", "float", "double", "int8", "uint8",
                           "int16", "uint16", "int32", "uint32", "float32", "float64"}) {
    for (const PlyEncoding encoding : kEncodings) {
      SCOPED_TRACE(std::string(type) + " " + format_name(encoding));
      Elem vertices = xyz_vertices(type);
      if (type[0] == 'u') vertices.rows[3] = {0, 0, 10};  // no negative values in unsigned types
      const PolygonSoup soup = parse_ply(build_ply(encoding, {vertices, triangle_faces()}), "t.ply");
      ASSERT_EQ(soup.num_vertices(), 4);
      EXPECT_EQ(soup.vertices.topRows(3), expected_xyz().topRows(3));
      EXPECT_EQ(polygons(soup), kFaces);
    }
  }
}

TEST(Ply, EveryIntegerTypeForFaceLists) {
  const char* const types[] = {"char", "uchar", "short", "ushort", "int", "uint", "int8", "uint16", "int32"};
  for (const char* count_type : types) {
    for (const char* index_type : types) {
      for (const PlyEncoding encoding : kEncodings) {
        SCOPED_TRACE(std::string(count_type) + " " + index_type + " " + format_name(encoding));
        const std::string bytes = build_ply(encoding, {xyz_vertices("float"), triangle_faces(count_type, index_type)});
        EXPECT_EQ(polygons(parse_ply(bytes, "t.ply")), kFaces);
      }
    }
  }
}

TEST(Ply, FaceListNamedVertexIndex) {
  for (const PlyEncoding encoding : kEncodings) {
    const std::string bytes =
        build_ply(encoding, {xyz_vertices("float"), triangle_faces("uchar", "int", "vertex_index")});
    EXPECT_EQ(polygons(parse_ply(bytes, "t.ply")), kFaces) << format_name(encoding);
  }
}

TEST(Ply, ExtraPropertiesAndElementsAreSkippedInEveryEncoding) {
  const Elem material = {"material",
                         {{"uchar", "red"}, {"float", "shininess"}, {"int", "ids", "uchar"}},
                         {{255, 0.5, 2, 7, 8}, {0, 1.5, 0}}};
  const Elem vertices = {"vertex",
                         {{"float", "nx"},
                          {"double", "x"},
                          {"float", "uv", "uchar"},
                          {"double", "y"},
                          {"int", "id"},
                          {"double", "z"},
                          {"short", "neighbors", "int"}},
                         {{0, 1, 2, 0.5, 0.25, 2, 0, 3, 0},
                          {0, 4, 0, 5, 1, 6, 3, 1, 2, 3},
                          {0, 7, 1, 0, 8, 2, 9, 1, 5},
                          {1, -1, 3, 1, 2, 3, 0, 3, 10, 0}}};
  const Elem faces = {"face",
                      {{"float", "quality"},
                       {"uint", "tags", "ushort"},
                       {"uint", "vertex_indices", "uchar"},
                       {"uchar", "red"},
                       {"double", "weights", "uchar"}},
                      {{0.5, 2, 1, 2, 3, 0, 1, 2, 9, 1, 0.1}, {1, 0, 4, 0, 2, 3, 1, 255, 0}}};
  const Elem edges = {"edge",
                      {{"int", "vertex1"}, {"int", "vertex2"}, {"float", "confidence"}},
                      {{0, 1, 0.5}, {1, 2, 1}}};
  for (const PlyEncoding encoding : kEncodings) {
    SCOPED_TRACE(format_name(encoding));
    const PolygonSoup soup = parse_ply(build_ply(encoding, {material, vertices, faces, edges}), "x.ply");
    EXPECT_EQ(soup.vertices, expected_xyz());
    EXPECT_EQ(polygons(soup), kFaces);
    EXPECT_EQ(soup.vertex_colors.rows(), 0);  // "red" of another element is no vertex color
  }
}

TEST(Ply, ElementsAfterFacesAndBeforeVertices) {
  const Elem extra = {"extra", {{"int", "a"}, {"int", "b", "int"}}, {{1, 2, 5, 6}}};
  for (const PlyEncoding encoding : kEncodings) {
    const PolygonSoup soup =
        parse_ply(build_ply(encoding, {extra, triangle_faces(), xyz_vertices("float"), extra}), "o.ply");
    EXPECT_EQ(soup.vertices, expected_xyz()) << format_name(encoding);
    EXPECT_EQ(polygons(soup), kFaces) << format_name(encoding);
  }
}

TEST(Ply, ABinaryElementWithoutPropertiesHoldsNoBytesWhateverItsCount) {
  // Found by fuzz_ply (fuzz/corpus/ply/zero_byte_element_timeout.ply, which
  // the fuzz run replays with its 10 s limit per input): 10^9 items of zero
  // bytes each were read one by one. Here: the file reads whole.
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement junk 1142632412\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  bytes.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const std::int32_t corners[3] = {0, 1, 2};
  bytes.push_back(3);
  bytes.append(reinterpret_cast<const char*>(corners), sizeof corners);
  const PolygonSoup soup = parse_ply(bytes, "junk.ply");
  EXPECT_EQ(soup.vertices.rows(), 3);
  EXPECT_EQ(soup.face_offset.size(), 2u);
}

TEST(Ply, ColorsAsBytesAndAsFloats) {
  const Elem bytes =
      {"vertex",
       {{"float", "x"}, {"float", "y"}, {"float", "z"}, {"uchar", "red"}, {"uchar", "green"}, {"uchar", "blue"}},
       {{0, 0, 0, 255, 0, 51}, {1, 0, 0, 0, 255, 0}, {0, 1, 0, 0, 0, 0}}};
  Elem floats = bytes;
  for (auto& p : floats.props) p.type = "float";
  floats.rows = {{0, 0, 0, 1, 0, 0.25}, {1, 0, 0, 0, 1, 0}, {0, 1, 0, 0, 0, 0}};
  const Elem face = {"face", {{"int", "vertex_indices", "uchar"}}, {{3, 0, 1, 2}}};
  for (const PlyEncoding encoding : kEncodings) {
    SCOPED_TRACE(format_name(encoding));
    const PolygonSoup from_bytes = parse_ply(build_ply(encoding, {bytes, face}), "b.ply");
    ASSERT_EQ(from_bytes.vertex_colors.rows(), 3);
    EXPECT_EQ(from_bytes.vertex_colors.row(1), Vec3(0, 1, 0).transpose());
    EXPECT_DOUBLE_EQ(from_bytes.vertex_colors(0, 2), 0.2);
    const PolygonSoup from_floats = parse_ply(build_ply(encoding, {floats, face}), "f.ply");
    ASSERT_EQ(from_floats.vertex_colors.rows(), 3);
    EXPECT_EQ(from_floats.vertex_colors.row(0), Vec3(1, 0, 0.25).transpose());
  }
}

TEST(Ply, CommentsObjInfoAndCrlf) {
  std::string text =
      "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info anything at all\r\n"
      "element vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "comment between properties\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\n"
      "end_header\r\n0 0 0\r\n1 0 0\r\n\r\n0 1 0\r\n3 0 1 2\r\n";
  const PolygonSoup soup = parse_ply(text, "c.ply");
  EXPECT_EQ(soup.vertices.row(1), Vec3(1, 0, 0).transpose());
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
}

TEST(Ply, PointCloud) {
  for (const PlyEncoding encoding : kEncodings) {
    const PolygonSoup soup = parse_ply(build_ply(encoding, {xyz_vertices("float")}), "cloud.ply");
    EXPECT_EQ(soup.num_vertices(), 4);
    EXPECT_EQ(soup.num_polygons(), 0);
    Elem no_faces = triangle_faces();
    no_faces.rows.clear();
    EXPECT_EQ(parse_ply(build_ply(encoding, {xyz_vertices("float"), no_faces}), "cloud.ply").num_polygons(), 0);
  }
}

// --- writing -----------------------------------------------------------------

PlyVertexData sample_data() {
  PlyVertexData data;
  data.colors.resize(4, 3);
  data.colors << 1, 0, 0, 0, 0.5, 1, 0.2, 0.4, 0.6, 0, 0, 0;
  data.scalars = {{"geodesic", {0.1, 1.0 / 3.0, 1e-300, 7}}, {"label", {0, 1, 2, 3}}};
  return data;
}

TEST(PlyWrite, RoundTripKeepsPositionsFacesAndColors) {
  const TempDir dir;
  const Mesh mesh = awkward_tetrahedron();
  const PlyVertexData data = sample_data();
  for (const PlyEncoding encoding : kEncodings) {
    SCOPED_TRACE(format_name(encoding));
    const auto path = dir / (std::string(format_name(encoding)) + ".ply");
    write_ply(path, mesh, data, encoding);
    const PolygonSoup soup = read_ply(path);
    EXPECT_TRUE(same_mesh(soup, mesh));
    ASSERT_EQ(soup.vertex_colors.rows(), 4);
    for (Index v = 0; v < 4; ++v) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(soup.vertex_colors(v, k), std::round(data.colors(v, k) * 255) / 255) << v << " " << k;
      }
    }
  }
}

TEST(PlyWrite, AsciiFileShowsColorsAndScalars) {
  const TempDir dir;
  write_ply(dir / "a.ply", awkward_tetrahedron(), sample_data(), PlyEncoding::Ascii);
  std::ifstream file(dir / "a.ply");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(contains(text, {"format ascii 1.0", "property uchar red\nproperty uchar green\nproperty uchar blue\n",
                              "property double geodesic\nproperty double label\n", "element face 4\n"}));
  EXPECT_TRUE(contains(text, {"0.1 0.3333333333333333 1e-300 255 0 0 0.1 0\n"}));
  EXPECT_TRUE(contains(text, {" 0 128 255 0.3333333333333333 1\n", " 51 102 153 1e-300 2\n", "\n3 0 1 2\n"}));
}

TEST(PlyWrite, BinaryIsCompact) {
  const TempDir dir;
  write_ply(dir / "b.ply", awkward_tetrahedron(), sample_data());
  const auto size = std::filesystem::file_size(dir / "b.ply");
  std::ifstream file(dir / "b.ply", std::ios::binary);
  std::string header;
  std::getline(file, header);
  std::getline(file, header);
  EXPECT_EQ(header, "format binary_little_endian 1.0");
  // 4 vertices * (3 doubles + 3 bytes + 2 doubles) + 4 faces * (1 + 3 * 4), after the header.
  EXPECT_GT(size, 4u * (24 + 3 + 16) + 4u * 13);
  EXPECT_LT(size, 4u * (24 + 3 + 16) + 4u * 13 + 400);
}

TEST(PlyWrite, RejectsMismatchedData) {
  const TempDir dir;
  const Mesh mesh = awkward_tetrahedron();
  PlyVertexData colors;
  colors.colors = Points::Zero(3, 3);
  EXPECT_THROW(write_ply(dir / "c.ply", mesh, colors), InvalidArgument);
  for (const auto& [name, values] :
       std::vector<std::pair<std::string, std::vector<double>>>{{"short", {1, 2}},
                                                                {"", {1, 2, 3, 4}},
                                                                {"two words", {1, 2, 3, 4}},
                                                                {"x", {1, 2, 3, 4}}}) {
    PlyVertexData data;
    data.scalars = {{name, values}};
    EXPECT_THROW(write_ply(dir / "s.ply", mesh, data), InvalidArgument) << "'" << name << "'";
  }
}

TEST(PlyWrite, UnwritablePath) {
  const TempDir dir;
  const MeshFileError e = error_of([&] { write_ply(dir / "no_such_dir" / "m.ply", awkward_tetrahedron()); });
  EXPECT_TRUE(contains(e.what(), {"m.ply", "cannot open for writing"}));
}

// --- errors ------------------------------------------------------------------

MeshFileError ply_error(const std::string& bytes) {
  return error_of([&] { parse_ply(bytes, "bad.ply"); });
}

const std::string kVertexHeader =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(PlyError, EmptyFileAndBadMagic) {
  EXPECT_TRUE(contains(ply_error("").what(), {"bad.ply", "empty file"}));
  EXPECT_TRUE(
      contains(ply_error("OFF\n3 1 0\n").what(), {"bad.ply:1:", "not a PLY file: expected 'ply', found 'OFF'"}));
}

TEST(PlyError, HeaderProblems) {
  EXPECT_TRUE(contains(ply_error("ply\nformat binary_middle_endian 1.0\n").what(),
                       {"bad.ply:2:", "unsupported PLY format 'binary_middle_endian'"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty int64 x\n").what(),
                       {"bad.ply:4:", "unsupported PLY type 'int64'"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty list float int v\n").what(),
                       {"bad.ply:4:", "the size of a list must have an integer type"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nproperty float x\n").what(),
                       {"bad.ply:3:", "a property before the first element"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex -2\n").what(),
                       {"bad.ply:3:", "bad 'vertex' element count -2"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n").what(),
                       {"bad.ply", "truncated: the header has no 'end_header' line"}));
  EXPECT_TRUE(contains(ply_error("ply\nelement vertex 0\nend_header\n").what(), {"no 'format' line"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelemnt vertex 0\nend_header\n").what(),
                       {"bad.ply:3:", "unexpected header line 'elemnt'"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement edge 0\nend_header\n").what(),
                       {"the header declares no vertex element"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                 "end_header\n")
                           .what(),
                       {"the vertex element has no 'z' property"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 0\nproperty list uchar int corners\nend_header\n")
                           .what(),
                       {"the face element has no 'vertex_indices' list"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                 "property list uchar float z\nend_header\n")
                           .what(),
                       {"the vertex property 'z' is a list"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                 "property float z\nelement vertex 0\nend_header\n")
                           .what(),
                       {"a second 'vertex' element"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 0\nproperty list uchar float vertex_indices\n"
                                 "end_header\n")
                           .what(),
                       {"'vertex_indices' must be a list of integers"}));
}

TEST(PlyError, AsciiNonNumericTokenIsQuotedWithItsLine) {
  const MeshFileError e = ply_error("ply\nformat ascii 1.0\n" + kVertexHeader + "0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n");
  EXPECT_TRUE(contains(e.what(), {"bad.ply:12:", "expected a number, found 'one'"}));
}

TEST(PlyError, AsciiTruncated) {
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\n" + kVertexHeader + "0 0 0\n1 0 0\n").what(),
                       {"bad.ply", "truncated: file ends after 2 of 3 vertices"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\n" + kVertexHeader + "0 0 0\n1 0 0\n0 1\n3 0 1 2\n").what(),
                       {"bad.ply:12:", "expected a number, found end of line"}));
  EXPECT_TRUE(contains(ply_error("ply\nformat ascii 1.0\n" + kVertexHeader + "0 0 0\n1 0 0\n0 1 0\n").what(),
                       {"bad.ply", "truncated: file ends after 0 of 1 faces"}));
}

TEST(PlyError, BinaryTruncatedNamesTheElement) {
  for (const PlyEncoding encoding : {PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian}) {
    const std::string whole = build_ply(encoding, {xyz_vertices("float"), triangle_faces()});
    const std::size_t body = whole.find("end_header\n") + 11;
    EXPECT_TRUE(contains(ply_error(whole.substr(0, body + 12 * 2 + 5)).what(),
                         {"bad.ply: truncated: file ends after 2 of 4 vertices"}));
    EXPECT_TRUE(contains(ply_error(whole.substr(0, whole.size() - 1)).what(),
                         {"bad.ply: truncated: file ends after 1 of 2 faces"}));
    EXPECT_TRUE(contains(ply_error(whole.substr(0, body)).what(), {"truncated: file ends after 0 of 4 vertices"}));
  }
}

TEST(PlyError, HugeCountsFailWithoutReservingMemory) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\n"
      "property double x\nproperty double y\nproperty double z\nend_header\n";
  EXPECT_TRUE(contains(ply_error(header + std::string(48, '\0')).what(),
                       {"truncated: file ends after 2 of 2000000000 vertices"}));
}

TEST(PlyError, IndexOutOfRangeNamesFaceAndIndex) {
  Elem faces = triangle_faces();
  faces.rows[1] = {3, 0, 4, 1};
  for (const PlyEncoding encoding : kEncodings) {
    const MeshFileError e = ply_error(build_ply(encoding, {xyz_vertices("float"), faces}));
    EXPECT_TRUE(contains(e.what(), {"bad.ply", "face 1 refers to vertex 4, but there are 4 vertices"}));
    EXPECT_EQ(e.line(), encoding == PlyEncoding::Ascii ? 15u : 0u);
  }
  faces.rows[1] = {3, 0, -1, 1};
  EXPECT_TRUE(contains(ply_error(build_ply(PlyEncoding::BinaryBigEndian, {xyz_vertices("float"), faces})).what(),
                       {"face 1 refers to vertex -1"}));
}

TEST(PlyError, PolygonWithFewerThanThreeVertices) {
  Elem faces = triangle_faces();
  faces.rows[0] = {2, 0, 1};
  for (const PlyEncoding encoding : kEncodings) {
    EXPECT_TRUE(contains(ply_error(build_ply(encoding, {xyz_vertices("float"), faces})).what(),
                         {"bad.ply", "face 0 has 2 vertices; a polygon needs at least 3"}));
  }
}

TEST(PlyError, NonFiniteCoordinateNamesTheVertex) {
  Elem vertices = xyz_vertices("float");
  vertices.rows[2][1] = std::nan("");
  for (const PlyEncoding encoding : kEncodings) {
    EXPECT_TRUE(contains(ply_error(build_ply(encoding, {vertices, triangle_faces()})).what(),
                         {"bad.ply", "vertex 2 has a non-finite coordinate"}));
  }
}

// --- real files ----------------------------------------------------------------

TEST(PlyDataset, PointCloudWithoutFaces) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  const PolygonSoup soup = read_ply(dir / "b9.ply");
  EXPECT_EQ(soup.num_vertices(), 22300);
  EXPECT_EQ(soup.num_polygons(), 0);
  EXPECT_EQ(soup.vertices.row(0), Vec3(45.375, 52.1094, -10.6268).transpose());
}

TEST(PlyFixture, ColoredTetrahedronWithFaceAndEdgeProperties) {
  const PolygonSoup soup = read_ply(fixture("io/colored_tetra.ply"));  // from CGAL, CC0
  ASSERT_EQ(soup.num_vertices(), 4);
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}}));
  EXPECT_EQ(soup.vertices.row(3), Vec3(1, 0, 0).transpose());
  ASSERT_EQ(soup.vertex_colors.rows(), 4);
  EXPECT_EQ(soup.vertex_colors.row(0), Vec3(1, 1, 0).transpose());
  EXPECT_EQ(soup.vertex_colors.row(2), Vec3(128 / 255.0, 0, 1).transpose());
}

TEST(PlyDataset, SphereEqualsItsOffTwin) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  const PolygonSoup ply = read_ply(dir / "sphere.ply");
  EXPECT_EQ(ply.num_vertices(), 162);
  EXPECT_EQ(ply.num_polygons(), 320);
  const PolygonSoup off = read_off(dir / "sphere.off");  // manifest: V 162, F 320
  EXPECT_EQ(ply.vertices, off.vertices);
  // The two files start some triangles at another corner.
  auto ply_faces = polygons(ply);
  auto off_faces = polygons(off);
  for (auto* faces : {&ply_faces, &off_faces}) {
    for (auto& f : *faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  }
  EXPECT_EQ(ply_faces, off_faces);
}

}  // namespace
}  // namespace reebkit::test

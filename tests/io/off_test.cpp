#include "reebkit/io/off.h"

#include "io/io_test_util.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace reebkit::test {
namespace {

constexpr const char* kSquare =
    "OFF\n"
    "4 2 0\n"
    "0 0 0\n"
    "1 0 0\n"
    "1 1 0\n"
    "0 1 0\n"
    "3 0 1 2\n"
    "3 0 2 3\n";

TEST(Off, ReadsPlainFile) {
  const PolygonSoup soup = parse_off(kSquare, "square.off");
  EXPECT_EQ(soup.source, "square.off");
  ASSERT_EQ(soup.num_vertices(), 4);
  EXPECT_EQ(soup.vertices.row(2), Vec3(1, 1, 0).transpose());
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(soup.vertex_colors.rows(), 0);
}

TEST(Off, CountsOnTheHeaderLine) {
  const PolygonSoup soup = parse_off("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "a.off");
  EXPECT_EQ(soup.num_vertices(), 3);
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
}

TEST(Off, HeaderWithoutEdgeCount) {
  EXPECT_EQ(parse_off("OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "a.off").num_polygons(), 1);
  EXPECT_EQ(parse_off("OFF 3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "a.off").num_polygons(), 1);
}

TEST(Off, CommentsAnywhereAndBlankLines) {
  const PolygonSoup soup = parse_off(
      "# made by hand\n"
      "\n"
      "  # indented comment\n"
      "OFF # keyword\n"
      "# counts follow\n"
      "3 1 0 # counts\n"
      "\n"
      "0 0 0#no blank before the comment\n"
      "\n"
      "# between vertices\n"
      "1 0 0\n"
      "0 1 0\n"
      "\n\n"
      "3 0 1 2 # face\n"
      "# trailing comment",
      "a.off");
  EXPECT_EQ(soup.num_vertices(), 3);
  EXPECT_EQ(soup.vertices.row(1), Vec3(1, 0, 0).transpose());
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
}

TEST(Off, CrlfLineEndings) {
  const PolygonSoup soup = parse_off("OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 2.5\r\n3 0 1 2\r\n", "a.off");
  EXPECT_EQ(soup.vertices(2, 2), 2.5);
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
}

TEST(Off, PolygonsOfAnySizeAndFaceColorsIgnored) {
  const PolygonSoup soup = parse_off(
      "OFF\n5 2 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n"
      "5 0 1 2 3 4 255 0 0\n"
      "4 0 1 2 3 0.5 0.5 0.5 1\n",
      "a.off");
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2, 3, 4}, {0, 1, 2, 3}}));
}

TEST(Off, NumbersInEveryNotation) {
  const PolygonSoup soup = parse_off("OFF\n3 1 0\n+1 -2.5e-3 .75\n1E2 0 -0\n0.0 1 3.\n3 0 1 2\n", "a.off");
  EXPECT_EQ(soup.vertices.row(0), Vec3(1, -2.5e-3, 0.75).transpose());
  EXPECT_EQ(soup.vertices(1, 0), 100.0);
  EXPECT_EQ(soup.vertices(2, 2), 3.0);
}

TEST(Off, ColorsAsFloats) {
  const PolygonSoup soup = parse_off("COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 0.5 0\n0 1 0 0 0 0.25\n3 0 1 2\n", "c.off");
  ASSERT_EQ(soup.vertex_colors.rows(), 3);
  EXPECT_EQ(soup.vertex_colors.row(0), Vec3(1, 0, 0).transpose());
  EXPECT_EQ(soup.vertex_colors.row(1), Vec3(0, 0.5, 0).transpose());
  EXPECT_EQ(soup.vertex_colors.row(2), Vec3(0, 0, 0.25).transpose());
}

TEST(Off, ColorsAsBytesWithAlpha) {
  const PolygonSoup soup =
      parse_off("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 51 0 255\n0 1 0 0 0 0 128\n3 0 1 2\n", "c.off");
  ASSERT_EQ(soup.vertex_colors.rows(), 3);
  EXPECT_EQ(soup.vertex_colors.row(0), Vec3(1, 0, 0).transpose());
  EXPECT_DOUBLE_EQ(soup.vertex_colors(1, 1), 0.2);
  EXPECT_EQ(soup.vertex_colors.row(2), Vec3(0, 0, 0).transpose());
}

TEST(Off, NormalsAreSkipped) {
  const char* const body = "3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n";
  const PolygonSoup soup = parse_off(std::string("NOFF\n") + body, "n.off");
  EXPECT_EQ(soup.vertices.row(1), Vec3(1, 0, 0).transpose());
  EXPECT_EQ(soup.vertex_colors.rows(), 0);
}

TEST(Off, NormalsThenColors) {
  for (const char* keyword : {"CNOFF", "NCOFF"}) {
    const PolygonSoup soup = parse_off(std::string(keyword) +
                                           "\n3 1 0\n0 0 0 0 0 1 0.5 0 0\n1 0 0 0 0 1 0 0.5 0 1\n"
                                           "0 1 0 0 0 1 0 0 0.5\n3 0 1 2\n",
                                       "cn.off");
    EXPECT_EQ(soup.vertices.row(1), Vec3(1, 0, 0).transpose()) << keyword;
    ASSERT_EQ(soup.vertex_colors.rows(), 3) << keyword;
    EXPECT_EQ(soup.vertex_colors.row(1), Vec3(0, 0.5, 0).transpose()) << keyword;
  }
}

TEST(Off, PointCloudHasNoPolygons) {
  const PolygonSoup soup = parse_off("OFF\n2 0 0\n0 0 0\n1 1 1\n", "cloud.off");
  EXPECT_EQ(soup.num_vertices(), 2);
  EXPECT_EQ(soup.num_polygons(), 0);
}

TEST(Off, RoundTripKeepsEveryBit) {
  const TempDir dir;
  const Mesh mesh = awkward_tetrahedron();
  write_off(dir / "t.off", mesh);
  const PolygonSoup soup = read_off(dir / "t.off");
  EXPECT_TRUE(same_mesh(soup, mesh));
  EXPECT_EQ(soup.source, (dir / "t.off").string());
}

// --- errors ----------------------------------------------------------------

TEST(OffError, EmptyFile) {
  for (const char* text : {"", "\n\n", "# only a comment\n"}) {
    const MeshFileError e = error_of([&] { parse_off(text, "e.off"); });
    EXPECT_TRUE(contains(e.what(), {"e.off", "empty file"}));
  }
}

TEST(OffError, BadHeader) {
  EXPECT_TRUE(
      contains(parse_error(parse_off, "PLY\n3 1 0\n", "h.off"), {"h.off:1:", "expected an OFF header, found 'PLY'"}));
  EXPECT_TRUE(
      contains(parse_error(parse_off, "4OFF\n3 1 0\n", "h.off"), {"h.off:1:", "unsupported OFF variant '4OFF'"}));
  EXPECT_TRUE(contains(parse_error(parse_off, "OFF BINARY\n", "h.off"), {"h.off:1:", "binary OFF is not supported"}));
}

TEST(OffError, BadCounts) {
  EXPECT_TRUE(contains(parse_error(parse_off, "OFF\n-3 1 0\n", "c.off"), {"c.off:2:", "bad vertex count -3"}));
  EXPECT_TRUE(
      contains(parse_error(parse_off, "OFF\n3 x 0\n", "c.off"), {"c.off:2:", "expected the face count, found 'x'"}));
  EXPECT_TRUE(contains(parse_error(parse_off, "OFF\n3 1 0\n", "c.off"), {"c.off", "truncated"}));
  // A huge count is rejected before any memory is reserved for it.
  EXPECT_TRUE(contains(parse_error(parse_off, "OFF\n2000000000 2000000000 0\n0 0 0\n", "c.off"),
                       {"c.off", "truncated: file ends after 1 of 2000000000 vertices"}));
  EXPECT_TRUE(
      contains(parse_error(parse_off, "OFF\n9999999999 1 0\n", "c.off"), {"c.off:2:", "bad vertex count 9999999999"}));
}

TEST(OffError, NonNumericTokenIsQuotedWithItsLine) {
  const MeshFileError e = error_of([] { parse_off("OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "n.off"); });
  EXPECT_EQ(e.file(), "n.off");
  EXPECT_EQ(e.line(), 4u);
  EXPECT_TRUE(contains(e.what(), {"n.off:4:", "expected a vertex coordinate, found 'zero'"}));
}

TEST(OffError, VertexLineTooShort) {
  const MeshFileError e = error_of([] { parse_off("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "s.off"); });
  EXPECT_TRUE(contains(e.what(), {"s.off:4:", "expected a vertex coordinate, found end of line"}));
}

TEST(OffError, TruncatedVertices) {
  const MeshFileError e = error_of([] { parse_off("OFF\n4 0 0\n0 0 0\n1 0 0\n\n", "t.off"); });
  EXPECT_TRUE(contains(e.what(), {"t.off", "truncated: file ends after 2 of 4 vertices"}));
}

TEST(OffError, TruncatedFaces) {
  const MeshFileError e = error_of([] { parse_off("OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n", "t.off"); });
  EXPECT_TRUE(contains(e.what(), {"t.off", "truncated: file ends after 2 of 3 faces"}));
}

TEST(OffError, TruncatedFaceLine) {
  const MeshFileError e = error_of([] { parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "t.off"); });
  EXPECT_TRUE(contains(e.what(), {"t.off:6:", "expected a vertex index"}));
}

TEST(OffError, IndexOutOfRangeNamesFaceAndIndex) {
  const MeshFileError e = error_of([] { parse_off("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 7\n", "r.off"); });
  EXPECT_TRUE(contains(e.what(), {"r.off:7:", "face 1 refers to vertex 7, but there are 3 vertices"}));
  EXPECT_TRUE(contains(parse_error(parse_off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "r.off"),
                       {"r.off:6:", "face 0 refers to vertex -1"}));
}

TEST(OffError, PolygonWithFewerThanThreeVertices) {
  const MeshFileError e = error_of([] { parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "p.off"); });
  EXPECT_TRUE(contains(e.what(), {"p.off:6:", "face 0 has 2 vertices; a polygon needs at least 3"}));
}

TEST(OffError, NonFiniteCoordinateNamesTheVertex) {
  for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
    const std::string text = std::string("OFF\n3 1 0\n0 0 0\n1 ") + bad + " 0\n0 1 0\n3 0 1 2\n";
    const MeshFileError e = error_of([&] { parse_off(text, "f.off"); });
    EXPECT_TRUE(contains(e.what(), {"f.off:4:", "vertex 1 has a non-finite coordinate"})) << bad;
  }
}

TEST(Off, NumbersBeyondDoubleRangeRound) {
  const PolygonSoup soup = parse_off("OFF\n3 1 0\n1e-400 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "a.off");
  EXPECT_EQ(soup.vertices(0, 0), 0.0);
}

TEST(OffError, MissingFile) {
  const TempDir dir;
  const MeshFileError e = error_of([&] { read_off(dir / "absent.off"); });
  EXPECT_TRUE(contains(e.what(), {"absent.off", "file not found"}));
}

// --- real files ------------------------------------------------------------

TEST(OffFixture, ColoredMeshWithComments) {
  const PolygonSoup soup = read_off(fixture("io/mesh_with_colors.off"));  // from CGAL, CC0
  EXPECT_EQ(soup.num_vertices(), 8);
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 7}, {1, 2, 3}, {5, 6, 7}, {1, 3, 4, 5, 7}}));
  ASSERT_EQ(soup.vertex_colors.rows(), 8);
  EXPECT_EQ(soup.vertex_colors.row(0), Vec3(0.9, 0, 0).transpose());
  EXPECT_EQ(soup.vertex_colors.row(1), Vec3(0, 0, 0.9).transpose());
}

TEST(OffDataset, FaceColorsWithoutLeadingZero) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  const PolygonSoup soup = read_off(dir / "quint_tris.off");
  EXPECT_EQ(soup.num_vertices(), 12);
  EXPECT_EQ(soup.num_polygons(), 20);
  EXPECT_EQ(polygons(soup)[19], (std::vector<Index>{5, 0, 4}));
}

TEST(OffDataset, Quads) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  const PolygonSoup soup = read_off(dir / "cube_quad.off");  // manifest: V 8, F 6, 6 non-triangles
  EXPECT_EQ(soup.num_vertices(), 8);
  ASSERT_EQ(soup.num_polygons(), 6);
  for (const auto& polygon : polygons(soup)) EXPECT_EQ(polygon.size(), 4u);
  EXPECT_EQ(polygons(soup)[0], (std::vector<Index>{0, 3, 7, 4}));
}

}  // namespace
}  // namespace reebkit::test

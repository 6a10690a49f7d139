#include "reebkit/io/stl.h"

#include "io/io_test_util.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace reebkit::test {
namespace {

using Triangle = std::array<float, 9>;  // three corners

/// A binary STL (little-endian, as the format says; the tests run on little-endian machines).
std::string binary_stl(const std::vector<Triangle>& triangles, const std::string& header = "binary test") {
  std::string out = header;
  out.resize(80, ' ');
  const auto count = static_cast<std::uint32_t>(triangles.size());
  out.append(reinterpret_cast<const char*>(&count), 4);
  for (const Triangle& t : triangles) {
    const float normal[3] = {0, 0, 1};
    out.append(reinterpret_cast<const char*>(normal), sizeof normal);
    out.append(reinterpret_cast<const char*>(t.data()), sizeof(float) * 9);
    out.append(2, '\0');
  }
  return out;
}

/// Two triangles sharing the edge (1,0,0)-(0,1,0).
const std::vector<Triangle> kTwoTriangles = {Triangle{0, 0, 0, 1, 0, 0, 0, 1, 0}, Triangle{1, 0, 0, 1, 1, 0, 0, 1, 0}};

constexpr const char* kAsciiSquare =
    "solid square\n"
    "  facet normal 0 0 1\n"
    "    outer loop\n"
    "      vertex 0 0 0\n"
    "      vertex 1 0 0\n"
    "      vertex 0 1 0\n"
    "    endloop\n"
    "  endfacet\n"
    "  facet normal 0 0 1\n"
    "    outer loop\n"
    "      vertex 1 0 0\n"
    "      vertex 1 1 0\n"
    "      vertex 0 1 0\n"
    "    endloop\n"
    "  endfacet\n"
    "endsolid square\n";

void expect_square(const PolygonSoup& soup) {
  ASSERT_EQ(soup.num_vertices(), 4);  // six corners welded into four vertices
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}, {1, 3, 2}}));
  EXPECT_EQ(soup.vertices.row(3), Vec3(1, 1, 0).transpose());
}

TEST(Stl, AsciiWeldsSharedCorners) { expect_square(parse_stl(kAsciiSquare, "sq.stl")); }

TEST(Stl, BinaryWeldsSharedCorners) {
  const PolygonSoup soup = parse_stl(binary_stl(kTwoTriangles), "sq.stl");
  EXPECT_EQ(soup.source, "sq.stl");
  expect_square(soup);
}

TEST(Stl, BinaryWhoseHeaderStartsWithSolid) {
  expect_square(parse_stl(binary_stl(kTwoTriangles, "solid but binary"), "sq.stl"));
}

TEST(Stl, BinaryWithTrailingBytes) { expect_square(parse_stl(binary_stl(kTwoTriangles) + "trailing junk", "sq.stl")); }

TEST(Stl, WeldsOnlyBitIdenticalCorners) {
  const float nudged = std::nextafter(1.0f, 2.0f);
  const PolygonSoup soup =
      parse_stl(binary_stl({Triangle{0, 0, 0, 1, 0, 0, 0, 1, 0}, Triangle{nudged, 0, 0, 1, 1, 0, 0, 1, 0}}), "n.stl");
  EXPECT_EQ(soup.num_vertices(), 5);
  const PolygonSoup zeros =
      parse_stl(binary_stl({Triangle{0, 0, 0, 1, 0, 0, 0, 1, 0}, Triangle{-0.0f, -0.0f, 0, 1, 0, 0, 0, 0, 1}}),
                "z.stl");
  EXPECT_EQ(zeros.num_vertices(), 4);  // -0 and +0 are one position
}

TEST(Stl, AsciiKeywordsInAnyCaseAndSeveralSolids) {
  const PolygonSoup soup = parse_stl(
      "SOLID part one\r\nFACET NORMAL 0 0 1\r\nOUTER LOOP\r\nVERTEX 0 0 0\r\nVERTEX 1 0 0\r\nVERTEX 0 1 0\r\n"
      "ENDLOOP\r\nENDFACET\r\nENDSOLID part one\r\n"
      "solid two\nfacet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
      "endsolid\n\n",
      "multi.stl");
  expect_square(soup);
}

TEST(Stl, AsciiFacetWithMoreCornersIsAPolygon) {
  const PolygonSoup soup = parse_stl(
      "solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid\n",
      "quad.stl");
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2, 3}}));
}

TEST(Stl, EmptySolid) {
  const PolygonSoup soup = parse_stl("solid nothing\nendsolid nothing\n", "none.stl");
  EXPECT_EQ(soup.num_vertices(), 0);
  EXPECT_EQ(soup.num_polygons(), 0);
  EXPECT_EQ(parse_stl(binary_stl({}), "none.stl").num_polygons(), 0);
}

// --- errors ------------------------------------------------------------------

TEST(StlError, EmptyFile) { EXPECT_TRUE(contains(parse_error(parse_stl, "", "e.stl"), {"e.stl", "empty file"})); }

TEST(StlError, BinaryTruncated) {
  const std::string whole = binary_stl(kTwoTriangles);
  EXPECT_TRUE(contains(parse_error(parse_stl, whole.substr(0, whole.size() - 1), "t.stl"),
                       {"t.stl: truncated: the binary header declares 2 triangles, which take 184 bytes, the file has "
                        "183"}));
  EXPECT_TRUE(contains(parse_error(parse_stl, whole.substr(0, 50), "t.stl"),
                       {"t.stl: truncated", "84 header bytes, the file has 50"}));
  std::string huge = whole;
  huge[83] = '\x7f';  // about two billion triangles
  EXPECT_TRUE(contains(parse_error(parse_stl, huge, "t.stl"), {"t.stl: truncated", "declares 2130706434"}));
}

TEST(StlError, BinaryNonFiniteCoordinate) {
  const std::string bytes = binary_stl({kTwoTriangles[0], Triangle{0, 0, 0, 1, std::nanf(""), 0, 0, 1, 0}});
  EXPECT_TRUE(
      contains(parse_error(parse_stl, bytes, "f.stl"), {"f.stl: facet 1, corner 1 has a non-finite coordinate"}));
}

TEST(StlError, AsciiProblemsNameTheLine) {
  const std::string two_corners = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n";
  EXPECT_TRUE(contains(parse_error(parse_stl, two_corners + "vertex 0 1 x\n", "a.stl"),
                       {"a.stl:6:", "expected a vertex coordinate, found 'x'"}));
  EXPECT_TRUE(contains(parse_error(parse_stl, two_corners + "endloop\nendfacet\n", "a.stl"),
                       {"a.stl:6:", "face 0 has 2 vertices; a polygon needs at least 3"}));
  EXPECT_TRUE(contains(parse_error(parse_stl, two_corners + "vertex 0 inf 0\nendloop\n", "a.stl"),
                       {"a.stl:6:", "facet 0, corner 2 has a non-finite coordinate"}));
  EXPECT_TRUE(contains(parse_error(parse_stl, two_corners, "a.stl"),
                       {"a.stl", "expected 'vertex' or 'endloop', found the end of the file"}));
  EXPECT_TRUE(contains(parse_error(parse_stl, "solid s\nfacet normal 0 0 1\nouter lop\n", "a.stl"),
                       {"a.stl:3:", "expected 'loop', found 'lop'"}));
  EXPECT_TRUE(contains(parse_error(parse_stl, kAsciiSquare + std::string("solid\nfacet normal 0 0 1\n"), "a.stl"),
                       {"a.stl", "truncated: expected 'outer', found the end of the file"}));
  const std::string one_facet = std::string(kAsciiSquare).substr(0, std::string(kAsciiSquare).find("endfacet") + 9);
  EXPECT_TRUE(contains(parse_error(parse_stl, one_facet, "a.stl"),
                       {"a.stl", "truncated: expected 'facet' or 'endsolid', found the end of the file"}));
}

// --- real files ----------------------------------------------------------------

TEST(StlDataset, BinaryPig) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  const PolygonSoup soup = read_stl(dir / "pig.stl");  // 16,848 triangles, 8,642 distinct corners
  EXPECT_EQ(soup.num_polygons(), 16848);
  EXPECT_EQ(soup.num_vertices(), 8642);
}

TEST(StlDataset, BinarySphereWeldsToTheOffVertexCount) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  const PolygonSoup soup = read_stl(dir / "sphere.stl");
  EXPECT_EQ(soup.num_polygons(), 320);  // manifest, sphere.off: V 162, F 320
  EXPECT_EQ(soup.num_vertices(), 162);
}

}  // namespace
}  // namespace reebkit::test

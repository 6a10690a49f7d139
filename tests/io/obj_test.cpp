#include "reebkit/io/obj.h"

#include "io/io_test_util.h"

#include <gtest/gtest.h>

namespace reebkit::test {
namespace {

TEST(Obj, ReadsVerticesAndFaces) {
  const PolygonSoup soup = parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n", "sq.obj");
  EXPECT_EQ(soup.source, "sq.obj");
  ASSERT_EQ(soup.num_vertices(), 4);
  EXPECT_EQ(soup.vertices.row(2), Vec3(1, 1, 0).transpose());
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(soup.vertex_colors.rows(), 0);
}

TEST(Obj, EveryCornerForm) {
  const PolygonSoup soup = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
      "f 1/1 2/2 3/3\n"
      "f 1/1/1 2/2/1 4/3/1\n"
      "f 1//1 3//1 4//1\n"
      "f 2 3/3 4//1\n",
      "c.obj");
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}));
}

TEST(Obj, NegativeIndicesCountBackFromTheLatestVertex) {
  const PolygonSoup soup = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
      "v 5 5 5\nf -4 -1/1/1 -2//1\n",
      "n.obj");
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}, {0, 3, 2}}));
}

TEST(Obj, PolygonsOfAnySize) {
  const PolygonSoup soup = parse_obj("v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\nf 1 2 3 4\n", "p.obj");
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2, 3, 4}, {0, 1, 2, 3}}));
}

TEST(Obj, WeightIsIgnored) {
  const PolygonSoup soup = parse_obj("v 1 2 3 0.5\nv 0 0 0\nv 1 1 1\nf 1 2 3\n", "w.obj");
  EXPECT_EQ(soup.vertices.row(0), Vec3(1, 2, 3).transpose());
  EXPECT_EQ(soup.vertex_colors.rows(), 0);
}

TEST(Obj, VertexColors) {
  const PolygonSoup soup = parse_obj("v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0 0 0 1\nf 1 2 3\n", "c.obj");
  ASSERT_EQ(soup.vertex_colors.rows(), 3);
  EXPECT_EQ(soup.vertex_colors.row(1), Vec3(0, 0.5, 0).transpose());
  EXPECT_EQ(soup.vertices.row(1), Vec3(1, 0, 0).transpose());
}

TEST(Obj, ColorsOnSomeVerticesOnlyAreDropped) {
  const PolygonSoup soup = parse_obj("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "c.obj");
  EXPECT_EQ(soup.num_vertices(), 3);
  EXPECT_EQ(soup.vertex_colors.rows(), 0);
}

TEST(Obj, SkipsOtherStatementsAndComments) {
  const PolygonSoup soup = parse_obj(
      "# exported by hand\n"
      "mtllib shapes.mtl\n"
      "o thing\n"
      "g group one\n"
      "v 0 0 0 # a comment after a vertex\n"
      "v 1 0 0\n"
      "v 0 1 0\n"
      "vt 0.5 0.5\n"
      "vn 0 0 1\n"
      "vp 0.1 0.2\n"
      "usemtl red\n"
      "s off\n"
      "s 1\n"
      "l 1 2\n"
      "cstype bezier\n"
      "\n"
      "f 1 2 3#comment\n",
      "s.obj");
  EXPECT_EQ(soup.num_vertices(), 3);
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
}

TEST(Obj, LineContinuation) {
  const PolygonSoup soup =
      parse_obj("v 0 \\\n 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 \\\r\n 4 3\nvt 1 \\\n 2\n", "l.obj");
  EXPECT_EQ(soup.num_vertices(), 4);
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 3, 2}}));
}

TEST(Obj, CrlfAndTabs) {
  const PolygonSoup soup = parse_obj("v\t0 0 0\r\nv 1\t0 0\r\nv 0 1 0\r\nf 1\t2 3\r\n", "t.obj");
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
}

TEST(Obj, FaceBeforeItsVertices) {
  const PolygonSoup soup = parse_obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "late.obj");
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
}

TEST(Obj, PointsOnly) {
  const PolygonSoup soup = parse_obj("v 0 0 0\nv 1 1 1\n", "cloud.obj");
  EXPECT_EQ(soup.num_vertices(), 2);
  EXPECT_EQ(soup.num_polygons(), 0);
}

// --- errors ----------------------------------------------------------------

TEST(ObjError, EmptyFile) {
  for (const char* text : {"", "\n \n", "# nothing\n"}) {
    EXPECT_TRUE(contains(parse_error(parse_obj, text, "e.obj"), {"e.obj", "empty file"}));
  }
}

TEST(ObjError, NonNumericTokenIsQuoted) {
  const MeshFileError e = error_of([] { parse_obj("v 0 0 0\nv 1 O 0\n", "n.obj"); });
  EXPECT_EQ(e.line(), 2u);
  EXPECT_TRUE(contains(e.what(), {"n.obj:2:", "expected a vertex coordinate, found 'O'"}));
  EXPECT_TRUE(contains(parse_error(parse_obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n", "n.obj"),
                       {"n.obj:4:", "expected a vertex index, found 'two'"}));
  EXPECT_TRUE(contains(parse_error(parse_obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 //2 3\n", "n.obj"),
                       {"n.obj:4:", "expected a vertex index, found '//2'"}));
}

TEST(ObjError, ShortVertexLine) {
  EXPECT_TRUE(
      contains(parse_error(parse_obj, "v 0 0\n", "s.obj"), {"s.obj:1:", "expected a vertex coordinate, found end of"}));
}

TEST(ObjError, IndexOutOfRangeNamesFaceAndIndex) {
  const char* const vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_TRUE(contains(parse_error(parse_obj, std::string(vertices) + "f 1 2 3\nf 1 2 9\n", "r.obj"),
                       {"r.obj:5:", "face 1 refers to vertex 9, but there are 3 vertices"}));
  EXPECT_TRUE(contains(parse_error(parse_obj, std::string(vertices) + "f -1 -2 -4\n", "r.obj"),
                       {"r.obj:4:", "face 0 refers to vertex -4, but there are 3 vertices"}));
  EXPECT_TRUE(contains(parse_error(parse_obj, std::string(vertices) + "f 1 0 2\n", "r.obj"),
                       {"r.obj:4:", "face 0 refers to vertex 0, but OBJ indices start at 1"}));
}

TEST(ObjError, ForwardReferenceNeverDefined) {
  const MeshFileError e = error_of([] { parse_obj("v 0 0 0\nf 1 2 3\nv 1 0 0\n", "f.obj"); });
  EXPECT_TRUE(contains(e.what(), {"f.obj:2:", "face 0 refers to vertex 3, but there are 2 vertices"}));
}

TEST(ObjError, PolygonWithFewerThanThreeVertices) {
  EXPECT_TRUE(contains(parse_error(parse_obj, "v 0 0 0\nv 1 0 0\nf 1 2\n", "p.obj"),
                       {"p.obj:3:", "face 0 has 2 vertices; a polygon needs at least 3"}));
}

TEST(ObjError, NonFiniteCoordinateNamesTheVertex) {
  EXPECT_TRUE(contains(parse_error(parse_obj, "v 0 0 0\nv 0 nan 0\n", "f.obj"),
                       {"f.obj:2:", "vertex 1 has a non-finite coordinate"}));
}

TEST(ObjError, NotAStatement) {
  EXPECT_TRUE(contains(parse_error(parse_obj, "v 0 0 0\n1.5 2 3\n", "g.obj"),
                       {"g.obj:2:", "expected an OBJ statement, found '1.5'"}));
  EXPECT_TRUE(
      contains(parse_error(parse_obj, std::string("\x01\x02\xff", 3), "g.obj"), {"g.obj:1:", "'\\x01\\x02\\xff'"}));
}

TEST(ObjError, MissingFile) {
  const TempDir dir;
  EXPECT_TRUE(contains(error_of([&] { read_obj(dir / "absent.obj"); }).what(), {"absent.obj", "file not found"}));
}

TEST(Obj, ReadsFromFile) {
  const TempDir dir;
  write_bytes(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const PolygonSoup soup = read_obj(dir / "tri.obj");
  EXPECT_EQ(soup.source, (dir / "tri.obj").string());
  EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
}

}  // namespace
}  // namespace reebkit::test

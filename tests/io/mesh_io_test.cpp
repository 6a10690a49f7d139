#include "reebkit/io/mesh_io.h"

#include "reebkit/io/obj.h"
#include "reebkit/io/off.h"
#include "reebkit/io/ply.h"
#include "reebkit/io/stl.h"

#include "io/io_test_util.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <random>
#include <regex>

namespace reebkit::test {
namespace {

/// The same triangle in each format.
struct Sample {
  const char* name;
  std::string bytes;
};

std::vector<Sample> one_triangle_in_every_format() {
  return {
      {"tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"tri.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"tri.stl",
       "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
       "endsolid t\n"},
  };
}

TEST(MeshIo, DispatchesOnTheExtensionInAnyCase) {
  const TempDir dir;
  for (const Sample& sample : one_triangle_in_every_format()) {
    std::string upper = sample.name;
    for (std::size_t i = upper.find('.'); i < upper.size(); ++i) upper[i] = static_cast<char>(std::toupper(upper[i]));
    for (const std::string& name : {std::string(sample.name), upper}) {
      SCOPED_TRACE(name);
      write_bytes(dir / name, sample.bytes);
      const PolygonSoup soup = read_polygon_soup(dir / name);
      EXPECT_EQ(soup.source, (dir / name).string());
      EXPECT_EQ(soup.num_vertices(), 3);
      EXPECT_EQ(soup.vertices.row(1), Vec3(1, 0, 0).transpose());
      EXPECT_EQ(polygons(soup), (Polygons{{0, 1, 2}}));
    }
  }
}

TEST(MeshIo, UnknownExtensionNamesFileAndSupportedFormats) {
  const TempDir dir;
  write_bytes(dir / "shape.vtk", "whatever");
  EXPECT_TRUE(contains(error_of([&] { read_polygon_soup(dir / "shape.vtk"); }).what(),
                       {"shape.vtk", "unknown mesh format '.vtk' (supported: .off, .obj, .ply, .stl)"}));
  EXPECT_TRUE(contains(error_of([&] { read_polygon_soup(dir / "no_extension"); }).what(),
                       {"no_extension", "no file extension (supported: .off, .obj, .ply, .stl)"}));
}

TEST(MeshIo, MissingAndUnreadableFiles) {
  const TempDir dir;
  EXPECT_TRUE(
      contains(error_of([&] { read_polygon_soup(dir / "absent.ply"); }).what(), {"absent.ply", "file not found"}));
  std::filesystem::create_directories(dir / "folder.off");
  EXPECT_TRUE(
      contains(error_of([&] { read_polygon_soup(dir / "folder.off"); }).what(), {"folder.off", "not a regular file"}));
}

TEST(MeshIo, EmptyFilesInEveryFormat) {
  const TempDir dir;
  for (const char* name : {"e.off", "e.obj", "e.ply", "e.stl"}) {
    write_bytes(dir / name, "");
    EXPECT_TRUE(contains(error_of([&] { read_polygon_soup(dir / name); }).what(), {name, "empty file"}));
  }
}

TEST(MeshIo, WriteMeshRoundTrips) {
  const TempDir dir;
  const Mesh mesh = awkward_tetrahedron();
  for (const char* name : {"t.off", "t.ply", "T.PLY"}) {
    SCOPED_TRACE(name);
    write_mesh(dir / name, mesh);
    const PolygonSoup soup = read_polygon_soup(dir / name);
    EXPECT_TRUE(same_mesh(soup, mesh));
    EXPECT_EQ(soup.vertex_colors.rows(), 0);
  }
}

TEST(MeshIo, WriteMeshRejectsOtherFormats) {
  const TempDir dir;
  const MeshFileError e = error_of([&] { write_mesh(dir / "t.stl", awkward_tetrahedron()); });
  EXPECT_TRUE(contains(e.what(), {"t.stl", "cannot write format '.stl' (supported: .off, .ply)"}));
  EXPECT_FALSE(std::filesystem::exists(dir / "t.stl"));
}

/// Every prefix of a valid file, and the file with bytes overwritten at
/// random, either parses or throws MeshFileError: no crash, no other error.
TEST(MeshIo, DamagedFilesThrowOnlyMeshFileError) {
  const TempDir dir;
  write_ply(dir / "le.ply", awkward_tetrahedron(), {}, PlyEncoding::BinaryLittleEndian);
  write_ply(dir / "be.ply", awkward_tetrahedron(), {}, PlyEncoding::BinaryBigEndian);
  std::ifstream le(dir / "le.ply", std::ios::binary);
  std::ifstream be(dir / "be.ply", std::ios::binary);
  const std::string stl =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid\n";
  std::string binary_stl(80, ' ');
  binary_stl += std::string("\x01\0\0\0", 4) + std::string(48, '\0') + "\0\0";
  const std::vector<std::pair<PolygonSoup (*)(std::string_view, std::string), std::string>> files = {
      {parse_off, one_triangle_in_every_format()[0].bytes},
      {parse_obj, one_triangle_in_every_format()[1].bytes},
      {parse_ply, one_triangle_in_every_format()[2].bytes},
      {parse_ply, std::string(std::istreambuf_iterator<char>(le), {})},
      {parse_ply, std::string(std::istreambuf_iterator<char>(be), {})},
      {parse_stl, stl},
      {parse_stl, binary_stl},
  };
  std::mt19937 random(7);
  for (const auto& [parse, bytes] : files) {
    std::vector<std::string> damaged;
    for (std::size_t size = 0; size < bytes.size(); ++size) damaged.push_back(bytes.substr(0, size));
    for (int trial = 0; trial < 300; ++trial) {
      std::string copy = bytes;
      for (int k = 0; k < 3; ++k) copy[random() % copy.size()] = static_cast<char>(random() % 256);
      damaged.push_back(copy);
    }
    for (const std::string& text : damaged) {
      try {
        parse(text, "damaged");
      } catch (const MeshFileError& e) {
        EXPECT_TRUE(contains(e.what(), {"damaged"}));
      } catch (const std::exception& e) {
        ADD_FAILURE() << "unexpected " << e.what();
      }
    }
  }
}

/// Every OFF file of the CGAL set reads with the vertex and face counts the
/// manifest measured (rows naming an error are files the measuring script
/// could not parse; they have tests of their own in off_test.cpp).
TEST(MeshIoDataset, EveryCgalOffFileHasTheManifestCounts) {
  REEBKIT_REQUIRE_DATASET(dir, "cgal_meshes");
  std::ifstream manifest(dir / "manifest.jsonl");
  ASSERT_TRUE(manifest) << "no manifest.jsonl in " << dir;
  const std::regex row(R"re("file": "([^"]+)", "V": (\d+), "F": (\d+))re");
  int checked = 0;
  for (std::string line; std::getline(manifest, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    SCOPED_TRACE(m[1].str());
    const PolygonSoup soup = read_polygon_soup(dir / m[1].str());
    EXPECT_EQ(soup.num_vertices(), std::stoi(m[2].str()));
    EXPECT_EQ(soup.num_polygons(), std::stoi(m[3].str()));
    ++checked;
  }
  EXPECT_GE(checked, 130);
}

}  // namespace
}  // namespace reebkit::test

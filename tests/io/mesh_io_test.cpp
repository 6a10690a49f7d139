#include "reebkit/io/mesh_io.h"

#include "io/io_test_util.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
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
  for (const char* name : {"shape.vtk", "no_extension"}) {
    const MeshFileError e = error_of([&] { read_polygon_soup(dir / name); });
    EXPECT_TRUE(contains(e.what(), {name, "unknown mesh format", "supported: .off, .obj, .ply, .stl"}));
  }
}

TEST(MeshIo, MissingAndUnreadableFiles) {
  const TempDir dir;
  EXPECT_TRUE(contains(error_of([&] { read_polygon_soup(dir / "absent.ply"); }).what(),
                       {"absent.ply", "file not found"}));
  std::filesystem::create_directories(dir / "folder.off");
  EXPECT_TRUE(contains(error_of([&] { read_polygon_soup(dir / "folder.off"); }).what(),
                       {"folder.off", "not a regular file"}));
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
  EXPECT_TRUE(contains(e.what(), {"t.stl", "cannot write format '.stl'", "supported: .off, .ply"}));
  EXPECT_FALSE(std::filesystem::exists(dir / "t.stl"));
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

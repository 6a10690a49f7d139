#include "reebkit/mesh/mesh_cleanup.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/mesh_topology.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace reebkit {
namespace {

PolygonSoup make_soup(const std::vector<std::array<double, 3>>& points, const std::vector<std::vector<Index>>& polygons,
                      const std::string& source = "soup.off") {
  PolygonSoup soup;
  soup.source = source;
  soup.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t v = 0; v < points.size(); ++v)
    soup.vertices.row(static_cast<Eigen::Index>(v)) << points[v][0], points[v][1], points[v][2];
  for (const auto& polygon : polygons) {
    soup.face_vertex.insert(soup.face_vertex.end(), polygon.begin(), polygon.end());
    soup.face_offset.push_back(static_cast<Index>(soup.face_vertex.size()));
  }
  return soup;
}

Vec3 triangle_normal(const Mesh& mesh, Index t) {
  const Vec3 a = mesh.vertices.row(mesh.triangles(t, 0)).transpose();
  const Vec3 b = mesh.vertices.row(mesh.triangles(t, 1)).transpose();
  const Vec3 c = mesh.vertices.row(mesh.triangles(t, 2)).transpose();
  return 0.5 * (b - a).cross(c - a);  // length = area
}

double total_area(const Mesh& mesh) {
  double area = 0;
  for (Index t = 0; t < mesh.num_triangles(); ++t) area += triangle_normal(mesh, t).norm();
  return area;
}

/// Every triangle faces +z (the polygon orientation was kept) and none overlaps.
void expect_faces_up(const Mesh& mesh) {
  for (Index t = 0; t < mesh.num_triangles(); ++t) EXPECT_GT(triangle_normal(mesh, t).z(), 0) << "triangle " << t;
}

std::string message_of(const PolygonSoup& soup) {
  try {
    clean_mesh(soup);
  } catch (const InvalidMeshError& e) {
    return e.what();
  }
  return "no InvalidMeshError";
}

// The unit cube: 8 corners, 6 quads facing outwards.
const std::vector<std::array<double, 3>> kCubeCorners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<std::vector<Index>> kCubeQuads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

TEST(CleanMesh, QuadGivesTwoTriangles) {
  const CleanedMesh cleaned = clean_mesh(make_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}));
  ASSERT_EQ(cleaned.components.size(), 1u);
  const Mesh& mesh = cleaned.components[0];
  EXPECT_EQ(mesh.num_triangles(), 2);
  EXPECT_EQ(mesh.num_vertices(), 4);
  expect_faces_up(mesh);
  EXPECT_DOUBLE_EQ(total_area(mesh), 1.0);
  EXPECT_EQ(cleaned.report.polygons_triangulated, 1);
  EXPECT_EQ(cleaned.report.triangles_created, 2);
  EXPECT_EQ(cleaned.report.boundary_edges, 4);
  EXPECT_EQ(cleaned.report.boundary_loops, 1);
  EXPECT_TRUE(cleaned.report.warnings.empty());
}

TEST(CleanMesh, PentagonGivesThreeTriangles) {
  const CleanedMesh cleaned =
      clean_mesh(make_soup({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}}, {{0, 1, 2, 3, 4}}));
  const Mesh& mesh = cleaned.components[0];
  EXPECT_EQ(mesh.num_triangles(), 3);
  expect_faces_up(mesh);
  EXPECT_DOUBLE_EQ(total_area(mesh), 5.0);  // shoelace area of the pentagon
  EXPECT_EQ(cleaned.report.triangles_created, 3);
}

TEST(CleanMesh, NonConvexPolygonIsEarClipped) {
  // An L-shaped hexagon that starts at a corner next to the reflex vertex:
  // a fan from vertex 0 would produce a flipped, overlapping triangle.
  const CleanedMesh cleaned =
      clean_mesh(make_soup({{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}}, {{0, 1, 2, 3, 4, 5}}));
  const Mesh& mesh = cleaned.components[0];
  EXPECT_EQ(mesh.num_triangles(), 4);
  expect_faces_up(mesh);
  EXPECT_DOUBLE_EQ(total_area(mesh), 3.0);
  EXPECT_EQ(analyze_topology(mesh).boundary_edges, 6);
}

TEST(CleanMesh, CornersOnAStraightEdgeGiveNoFlatTriangle) {
  // Vertex 1 lies on the edge from 0 to 2: a fan from vertex 0 would make
  // the flat triangle (0, 1, 2).
  const CleanedMesh cleaned =
      clean_mesh(make_soup({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3, 4}}));
  const Mesh& mesh = cleaned.components[0];
  ASSERT_EQ(mesh.num_triangles(), 3);
  expect_faces_up(mesh);
  EXPECT_DOUBLE_EQ(total_area(mesh), 2.0);
}

TEST(CleanMesh, TriangulationKeepsThePolygonOrientation) {
  // The L shape in the x = 0 plane, traversed clockwise seen from +x.
  const CleanedMesh cleaned =
      clean_mesh(make_soup({{0, 0, 2}, {0, 1, 2}, {0, 1, 1}, {0, 2, 1}, {0, 2, 0}, {0, 0, 0}}, {{0, 1, 2, 3, 4, 5}}));
  const Mesh& mesh = cleaned.components[0];
  ASSERT_EQ(mesh.num_triangles(), 4);
  for (Index t = 0; t < 4; ++t) EXPECT_LT(triangle_normal(mesh, t).x(), 0) << "triangle " << t;
  EXPECT_DOUBLE_EQ(total_area(mesh), 3.0);
}

TEST(CleanMesh, DegenerateFacesAreDropped) {
  const CleanedMesh cleaned = clean_mesh(make_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                                   {{0, 1, 2},
                                                    {0, 0, 1},           // repeated vertex
                                                    {2, 3, 2, 1},        // repeat after collapsing: dropped
                                                    {0, 2, 2, 3, 3, 0},  // consecutive repeats: triangle 0 2 3
                                                    {1, 1, 1}}));
  EXPECT_EQ(cleaned.report.degenerate_faces_dropped, 3);
  EXPECT_EQ(cleaned.report.polygons_triangulated, 0);
  ASSERT_EQ(cleaned.components[0].num_triangles(), 2);
  EXPECT_EQ(cleaned.components[0].triangles.row(1), (Eigen::RowVector3i(0, 2, 3)));
  ASSERT_EQ(cleaned.report.warnings.size(), 1u);
  EXPECT_NE(cleaned.report.warnings[0].find("soup.off: dropped 3 degenerate polygons"), std::string::npos)
      << cleaned.report.warnings[0];
}

TEST(CleanMesh, DuplicateFacesInEitherOrientationAreDropped) {
  const CleanedMesh cleaned = clean_mesh(
      make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 3, 2}, {1, 2, 0}, {2, 1, 0}, {2, 3, 1}}));
  EXPECT_EQ(cleaned.report.duplicate_faces_dropped, 3);
  const Mesh& mesh = cleaned.components[0];
  ASSERT_EQ(mesh.num_triangles(), 2);
  EXPECT_EQ(mesh.triangles.row(0), (Eigen::RowVector3i(0, 1, 2)));  // the first of each set is kept
  EXPECT_EQ(mesh.triangles.row(1), (Eigen::RowVector3i(1, 3, 2)));
  EXPECT_EQ(cleaned.report.non_manifold_edges, 0);
  ASSERT_EQ(cleaned.report.warnings.size(), 1u);
  EXPECT_NE(cleaned.report.warnings[0].find("3 duplicate triangles"), std::string::npos);
}

// Polygons of 0, 1 and 2 corners give no triangle; the pentagon after them
// still gets its 3 (the triangles are written to storage sized by the
// polygons' corners, which the short ones must not shrink).
TEST(CleanMesh, PolygonsOfFewerThanThreeCornersAreDegenerate) {
  const CleanedMesh cleaned = clean_mesh(
      make_soup({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}}, {{}, {0}, {0, 1}, {0}, {}, {0, 1, 2, 3, 4}}));
  EXPECT_EQ(cleaned.report.degenerate_faces_dropped, 5);
  EXPECT_EQ(cleaned.report.triangles_created, 3);
  ASSERT_EQ(cleaned.components[0].num_triangles(), 3);
  expect_faces_up(cleaned.components[0]);
}

// A duplicate whose three edges no other triangle uses closes on its
// original: no edge is non-manifold. Attached by a vertex it makes that
// vertex non-manifold; alone it is a component; as the whole mesh it is two
// triangles. Each is found and dropped.
TEST(CleanMesh, DuplicatesClosingOnTheirOriginalAreDropped) {
  const std::vector<std::array<double, 3>> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                                     {2, 0, 1}, {2, 1, 1}, {5, 5, 5}, {6, 5, 5}};
  // A square, and a triangle with its reversed copy on its corner 1.
  const CleanedMesh attached = clean_mesh(make_soup(points, {{0, 1, 2}, {1, 3, 2}, {1, 4, 5}, {1, 5, 4}}));
  EXPECT_EQ(attached.report.duplicate_faces_dropped, 1);
  ASSERT_EQ(attached.components[0].num_triangles(), 3);
  EXPECT_EQ(attached.report.non_manifold_edges, 0);
  EXPECT_EQ(attached.report.non_manifold_vertices, 1);  // vertex 1: the square's fan and the triangle
  EXPECT_EQ(attached.report.boundary_edges, 7);         // after the copy went: the triangle's edges are open

  // The square, and the triangle and its copy apart from it.
  CleanupOptions keep_all;
  keep_all.keep_all_components = true;
  const CleanedMesh apart = clean_mesh(make_soup(points, {{0, 1, 2}, {1, 3, 2}, {4, 6, 7}, {7, 6, 4}}), keep_all);
  EXPECT_EQ(apart.report.duplicate_faces_dropped, 1);
  EXPECT_EQ(apart.report.components, 2);
  ASSERT_EQ(apart.components.size(), 2u);
  EXPECT_EQ(apart.components[0].num_triangles(), 1);  // the triangle, larger than the square
  EXPECT_EQ(apart.components[1].num_triangles(), 2);
  EXPECT_EQ(apart.report.boundary_edges, 7);

  const CleanedMesh alone = clean_mesh(make_soup(points, {{0, 1, 2}, {2, 1, 0}}));
  EXPECT_EQ(alone.report.duplicate_faces_dropped, 1);
  ASSERT_EQ(alone.components[0].num_triangles(), 1);
  EXPECT_EQ(alone.report.boundary_edges, 3);
}

// A disk triangulated as a fan around its centre: every triangle shares the
// smallest vertex, so the duplicates are found in one large bucket.
TEST(CleanMesh, DuplicatesInALargeFanAreDroppedAndTheFirstKept) {
  const int n = 200;
  std::vector<std::array<double, 3>> points = {{0, 0, 0}};
  std::vector<std::vector<Index>> faces;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::acos(-1.0) * k / n;
    points.push_back({std::cos(a), std::sin(a), 0});
  }
  for (int k = 0; k < n; ++k) faces.push_back({0, 1 + k, 1 + (k + 1) % n});
  for (int k = 0; k < n; k += 10) faces.push_back({1 + (k + 1) % n, 1 + k, 0});  // reversed copies
  for (int k = 5; k < n; k += 20) faces.push_back({1 + k, 1 + (k + 1) % n, 0});  // rotated copies
  const CleanedMesh cleaned = clean_mesh(make_soup(points, faces));
  EXPECT_EQ(cleaned.report.duplicate_faces_dropped, n / 10 + n / 20);
  const Mesh& mesh = cleaned.components[0];
  ASSERT_EQ(mesh.num_triangles(), n);
  for (int k = 0; k < n; ++k)  // the fan's own triangles, in file order
    EXPECT_EQ(mesh.triangles.row(k), (Eigen::RowVector3i(0, 1 + k, 1 + (k + 1) % n))) << k;
  EXPECT_EQ(cleaned.report.non_manifold_edges, 0);
}

TEST(CleanMesh, UnreferencedVerticesAreDroppedAndSourceVertexMapsBack) {
  const PolygonSoup soup =
      make_soup({{0, 0, 0}, {1, 0, 0}, {9, 9, 9}, {0, 1, 0}, {1, 1, 0}, {8, 8, 8}}, {{0, 1, 3}, {1, 4, 3}});
  const CleanedMesh cleaned = clean_mesh(soup);
  EXPECT_EQ(cleaned.report.unreferenced_vertices_dropped, 2);
  const Mesh& mesh = cleaned.components[0];
  EXPECT_EQ(mesh.source_vertex, (std::vector<Index>{0, 1, 3, 4}));
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    EXPECT_EQ(mesh.vertices.row(v), soup.vertices.row(mesh.source_index(v)));
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(mesh.source_index(mesh.triangles(t, k)), soup.face_vertex[static_cast<std::size_t>(3 * t + k)]);
  EXPECT_EQ(mesh.source, "soup.off");
}

// A small triangle (vertices 0-2, area 0.5) and, after it in the file, a
// large square (vertices 3-6, area 4).
PolygonSoup two_components() {
  return make_soup({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}},
                   {{0, 1, 2}, {3, 4, 5, 6}});
}

TEST(CleanMesh, KeepsTheLargestComponentByDefaultAndWarns) {
  const CleanedMesh cleaned = clean_mesh(two_components());
  ASSERT_EQ(cleaned.components.size(), 1u);
  EXPECT_EQ(cleaned.components[0].source_vertex, (std::vector<Index>{3, 4, 5, 6}));
  EXPECT_EQ(cleaned.report.components, 2);
  EXPECT_EQ(cleaned.report.components_dropped, 1);
  ASSERT_EQ(cleaned.report.warnings.size(), 1u);
  const std::string& warning = cleaned.report.warnings[0];
  EXPECT_EQ(warning,
            "soup.off: kept the largest of 2 connected components (2 triangles, 88.9% of the area); "
            "dropped 1 component with 1 triangle (11.1% of the area); the reeb commands keep them with "
            "--all-components");
}

TEST(CleanMesh, KeepAllComponentsSortsThemLargestFirst) {
  CleanupOptions options;
  options.keep_all_components = true;
  const CleanedMesh cleaned = clean_mesh(two_components(), options);
  ASSERT_EQ(cleaned.components.size(), 2u);
  EXPECT_EQ(cleaned.components[0].source_vertex, (std::vector<Index>{3, 4, 5, 6}));
  EXPECT_EQ(cleaned.components[0].num_triangles(), 2);
  EXPECT_EQ(cleaned.components[1].source_vertex, (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(cleaned.components[1].triangles.row(0), (Eigen::RowVector3i(0, 1, 2)));
  EXPECT_EQ(cleaned.report.components_dropped, 0);
  EXPECT_TRUE(cleaned.report.warnings.empty());
}

TEST(CleanMesh, EqualAreasAreOrderedByTriangleCountThenSourceVertex) {
  // Three unit squares: one quad (2 triangles), then one split in 4 around
  // its centre, then another quad.
  CleanupOptions options;
  options.keep_all_components = true;
  const CleanedMesh cleaned =
      clean_mesh(make_soup({{0, 0, 0},
                            {1, 0, 0},
                            {1, 1, 0},
                            {0, 1, 0},
                            {5, 0, 0},
                            {6, 0, 0},
                            {6, 1, 0},
                            {5, 1, 0},
                            {5.5, 0.5, 0},
                            {9, 0, 0},
                            {10, 0, 0},
                            {10, 1, 0},
                            {9, 1, 0}},
                           {{9, 10, 11, 12}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}, {0, 1, 2, 3}}),
                 options);
  ASSERT_EQ(cleaned.components.size(), 3u);
  EXPECT_EQ(cleaned.components[0].source_vertex.front(), 4);
  EXPECT_EQ(cleaned.components[1].source_vertex.front(), 0);
  EXPECT_EQ(cleaned.components[2].source_vertex.front(), 9);
}

TEST(CleanMesh, BowtieVertexIsReportedAsNonManifold) {
  const CleanedMesh cleaned =
      clean_mesh(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}, {{0, 1, 2}, {0, 3, 4}}));
  EXPECT_EQ(cleaned.report.non_manifold_vertices, 1);
  EXPECT_EQ(cleaned.report.non_manifold_edges, 0);
  EXPECT_EQ(cleaned.report.components, 1);
  EXPECT_EQ(cleaned.report.boundary_loops, 2);
  ASSERT_EQ(cleaned.components.size(), 1u);
  EXPECT_EQ(cleaned.components[0].num_triangles(), 2);  // kept as is
  ASSERT_EQ(cleaned.report.warnings.size(), 1u);
  EXPECT_EQ(cleaned.report.warnings[0],
            "soup.off: 1 non-manifold vertex (incident triangles form more than one fan), kept as is");
}

TEST(CleanMesh, ThreeTrianglesOnOneEdgeAreANonManifoldEdge) {
  const CleanedMesh cleaned = clean_mesh(
      make_soup({{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, -1, 0}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}));
  EXPECT_EQ(cleaned.report.non_manifold_edges, 1);
  // Both ends of that edge see three fans, since fans never cross it.
  EXPECT_EQ(cleaned.report.non_manifold_vertices, 2);
  EXPECT_EQ(cleaned.components[0].num_triangles(), 3);
  ASSERT_EQ(cleaned.report.warnings.size(), 2u);
  EXPECT_EQ(cleaned.report.warnings[0], "soup.off: 1 non-manifold edge (used by more than 2 triangles), kept as is");
}

TEST(CleanMesh, ClosedCubeOfQuads) {
  const CleanedMesh cleaned = clean_mesh(make_soup(kCubeCorners, kCubeQuads));
  const Mesh& mesh = cleaned.components[0];
  EXPECT_EQ(mesh.num_triangles(), 12);
  EXPECT_EQ(cleaned.report.boundary_edges, 0);
  const MeshTopology topology = analyze_topology(mesh);
  EXPECT_TRUE(topology.closed);
  EXPECT_EQ(topology.genus, 0);
}

TEST(CleanMesh, OpenBoxHasOneBoundaryLoop) {
  std::vector<std::vector<Index>> open_box = kCubeQuads;
  open_box.erase(open_box.begin() + 1);  // the top
  const CleanedMesh cleaned = clean_mesh(make_soup(kCubeCorners, open_box));
  EXPECT_EQ(cleaned.report.boundary_edges, 4);
  EXPECT_EQ(cleaned.report.boundary_loops, 1);
  EXPECT_TRUE(cleaned.report.warnings.empty());  // holes are fine
  EXPECT_EQ(analyze_topology(cleaned.components[0]).genus, 0);
}

TEST(CleanMesh, MergingCoincidentVerticesWeldsSeparateTriangles) {
  // Two triangles of a square stored STL-style, each with its own corners.
  const PolygonSoup soup =
      make_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {3, 4, 5}});
  CleanupOptions options;
  options.keep_all_components = true;
  EXPECT_EQ(clean_mesh(soup, options).components.size(), 2u);

  options.merge_coincident_vertices = true;
  const CleanedMesh welded = clean_mesh(soup, options);
  EXPECT_EQ(welded.report.coincident_vertices_merged, 2);
  EXPECT_EQ(welded.report.unreferenced_vertices_dropped, 0);
  ASSERT_EQ(welded.components.size(), 1u);
  EXPECT_EQ(welded.components[0].source_vertex, (std::vector<Index>{0, 1, 2, 5}));
  EXPECT_EQ(welded.components[0].triangles.row(1), (Eigen::RowVector3i(0, 2, 3)));
  EXPECT_EQ(welded.report.boundary_edges, 4);
}

TEST(CleanMesh, MergingCanMakeFacesDegenerate) {
  CleanupOptions options;
  options.merge_coincident_vertices = true;
  const CleanedMesh cleaned =
      clean_mesh(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}}, {{0, 1, 2}, {1, 3, 2}}), options);
  EXPECT_EQ(cleaned.report.coincident_vertices_merged, 1);
  EXPECT_EQ(cleaned.report.degenerate_faces_dropped, 1);
  EXPECT_EQ(cleaned.components[0].num_triangles(), 1);
}

TEST(CleanMesh, NonFiniteCoordinateNamesTheVertex) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PolygonSoup soup = make_soup({{0, 0, 0}, {1, 0, 0}, {0, nan, 0}}, {{0, 1, 2}}, "bad.off");
  EXPECT_EQ(message_of(soup), "bad.off: vertex 2 has a non-finite coordinate (0, nan, 0)");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message_of(make_soup({{0, 0, 0}, {inf, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, "")),
            "<memory>: vertex 1 has a non-finite coordinate (inf, 0, 0)");
}

TEST(CleanMesh, EmptySoupsAreErrors) {
  EXPECT_EQ(message_of(make_soup({}, {}, "empty.off")), "empty.off: no vertices: the file holds no vertices");
  EXPECT_EQ(message_of(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, "cloud.ply")),
            "cloud.ply: no faces: the file holds 3 vertices and no polygons (a point cloud?)");
  EXPECT_EQ(message_of(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 1}, {2, 2, 2}}, "flat.off")),
            "flat.off: no usable triangle: all 2 polygons are degenerate (fewer than 3 distinct vertices, or a "
            "repeated vertex)");
}

TEST(CleanMesh, TrianglesOfZeroTotalAreaAreAnError) {
  // Distinct vertex ids, but every triangle's corners on one line.
  EXPECT_EQ(message_of(make_soup({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, {{0, 1, 2}, {1, 2, 3}}, "line.off")),
            "line.off: no surface: the vertices of every one of its 2 triangles are collinear (zero area, degenerate)");
  // One flat triangle in a surface is kept.
  const CleanedMesh kept = clean_mesh(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}}, {{0, 1, 2}, {0, 1, 3}}));
  EXPECT_EQ(kept.components.front().num_triangles(), 2);
}

TEST(CleanMesh, IndexOutOfRangeIsAnError) {
  EXPECT_EQ(message_of(make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}})),
            "soup.off: polygon 1 refers to vertex 3, but there are 3 vertices");
}

TEST(CleanMesh, MalformedOffsetsAreAnInvalidArgument) {
  PolygonSoup soup = make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  soup.face_offset.back() = 2;
  EXPECT_THROW(clean_mesh(soup), InvalidArgument);
}

}  // namespace
}  // namespace reebkit

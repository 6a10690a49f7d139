#include "reebkit/attributes/graph_attributes.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"
#include "reebkit/reeb/deformation.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <string>

namespace reebkit {
namespace {

constexpr double kPi = static_cast<double>(EIGEN_PI);

double node_value(const GraphAttributes& g, Index node, NodeAttribute column) {
  return g.node[static_cast<std::size_t>(node) * kNodeAttributeCount + column];
}

double edge_value(const GraphAttributes& g, Index edge, EdgeAttribute column) {
  return g.edge[static_cast<std::size_t>(edge) * kEdgeAttributeCount + column];
}

double signature_value(const GraphAttributes& g, const std::string& name) {
  const auto it = std::find(kSignatureNames.begin(), kSignatureNames.end(), name);
  EXPECT_NE(it, kSignatureNames.end()) << name;
  return g.signature[static_cast<std::size_t>(it - kSignatureNames.begin())];
}

/// A capsule along z: a cylinder of radius r from z = -half_length to
/// +half_length closed by two hemispheres, `sides` vertices per ring, rings
/// about `sides`/2pi per unit of length on the cylinder and `cap_rings` per
/// hemisphere (its equator included), a pole at each end.
Mesh make_capsule(double r, double half_length, int sides, int cap_rings) {
  std::vector<std::pair<double, double>> rings;  // (radius, z), south to north
  for (int j = 1; j <= cap_rings; ++j) {
    const double theta = 0.5 * kPi * j / cap_rings;
    rings.emplace_back(r * std::sin(theta), -half_length - r * std::cos(theta));
  }
  const int cylinder = static_cast<int>(std::lround(2.0 * half_length * sides / (2.0 * kPi * r)));
  for (int j = 1; j < cylinder; ++j) rings.emplace_back(r, -half_length + 2.0 * half_length * j / cylinder);
  for (int j = cap_rings; j >= 1; --j) {
    const double theta = 0.5 * kPi * j / cap_rings;
    rings.emplace_back(r * std::sin(theta), half_length + r * std::cos(theta));
  }
  const Index ring_count = static_cast<Index>(rings.size());
  Mesh m;
  m.vertices.resize(ring_count * sides + 2, 3);
  for (Index i = 0; i < ring_count; ++i)
    for (int j = 0; j < sides; ++j) {
      const double phi = 2.0 * kPi * j / sides;
      m.vertices.row(i * sides + j) << rings[i].first * std::cos(phi), rings[i].first * std::sin(phi), rings[i].second;
    }
  const Index south = ring_count * sides, north = south + 1;
  m.vertices.row(south) << 0, 0, -half_length - r;
  m.vertices.row(north) << 0, 0, half_length + r;
  std::vector<Index> t;
  const auto at = [&](Index ring, int j) { return ring * sides + (j % sides); };
  for (int j = 0; j < sides; ++j) {
    t.insert(t.end(), {south, at(0, j + 1), at(0, j)});
    for (Index i = 0; i + 1 < ring_count; ++i)
      t.insert(t.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    t.insert(t.end(), {north, at(ring_count - 1, j), at(ring_count - 1, j + 1)});
  }
  m.triangles = Eigen::Map<Triangles>(t.data(), static_cast<Index>(t.size() / 3), 3);
  return m;
}

/// `mesh` without its last vertex and the triangles around it: a small hole.
Mesh punched(const Mesh& mesh) {
  const Index last = mesh.num_vertices() - 1;
  Mesh out;
  out.vertices = mesh.vertices.topRows(last);
  out.triangles.resize(mesh.num_triangles(), 3);
  Index n = 0;
  for (Index t = 0; t < mesh.num_triangles(); ++t)
    if ((mesh.triangles.row(t).array() != last).all()) out.triangles.row(n++) = mesh.triangles.row(t);
  out.triangles.conservativeResize(n, 3);
  return out;
}

struct Case {
  std::string name;
  MeshAnalysis analysis;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = [] {
    StarOptions star;
    star.arms = 5;
    star.levels = 4;
    star.twist = 0.3;
    std::vector<Case> c;
    c.push_back({"star", analyze_mesh(make_star(star))});
    c.push_back({"punched star", analyze_mesh(punched(make_star(star)))});
    c.push_back({"torus", analyze_mesh(make_torus(60, 20, 1.0, 0.3))});
    c.push_back({"capsule", analyze_mesh(make_capsule(1.0, 30.0, 48, 12))});
    c.push_back({"bunny", analyze_mesh(load_mesh(test::embedded_dataset_dir() / "bunny.off").components.front())});
    c.push_back({"elk", analyze_mesh(load_mesh(test::embedded_dataset_dir() / "elk.off").components.front())});
    return c;
  }();
  return all;
}

/// Area of the triangles of `mesh`.
double surface_area(const Mesh& mesh) {
  double area = 0.0;
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const Vec3 a = mesh.vertices.row(mesh.triangles(t, 0)), b = mesh.vertices.row(mesh.triangles(t, 1)),
               c = mesh.vertices.row(mesh.triangles(t, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

TEST(GraphAttributes, NamesAreDistinctSnakeCase) {
  std::set<std::string> seen;
  const auto check = [&](const char* name) {
    ASSERT_NE(name, nullptr);
    const std::string s(name);
    EXPECT_FALSE(s.empty());
    EXPECT_TRUE(std::all_of(s.begin(), s.end(), [](char ch) { return (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_'; })) << s;
    EXPECT_TRUE(seen.insert(s).second) << s;
  };
  for (const char* name : kNodeAttributeNames) check(name);
  seen.clear();
  for (const char* name : kEdgeAttributeNames) check(name);
  seen.clear();
  for (const char* name : kSignatureNames) check(name);
}

// Shapes, sums and the columns copied from the graph, on generated and real
// meshes (the bunny has holes that analyze_mesh fills).
TEST(GraphAttributes, ColumnsAgreeWithTheGraphAndSumToOne) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const MeshAnalysis& a = c.analysis;
    const GraphAttributes g = compute_attributes(a);
    const ReebGraph& reeb = a.reeb;
    ASSERT_EQ(g.node.size(), reeb.nodes.size() * kNodeAttributeCount);
    ASSERT_EQ(g.edge.size(), reeb.edges.size() * kEdgeAttributeCount);
    ASSERT_EQ(g.signature.size(), static_cast<std::size_t>(kSignatureLength));
    for (const double x : g.node) ASSERT_TRUE(std::isfinite(x));
    for (const double x : g.edge) ASSERT_TRUE(std::isfinite(x));
    for (const double x : g.signature) ASSERT_TRUE(std::isfinite(x));

    const Mesh surface = original_surface(a.mesh);
    const double area = surface_area(surface);
    double area_sum = 0.0, share_sum = 0.0, degree_sum = 0.0;
    for (Index n = 0; n < reeb.num_nodes(); ++n) {
      const ReebNode& node = reeb.nodes[static_cast<std::size_t>(n)];
      area_sum += node_value(g, n, kNodeRelativeArea);
      share_sum += node_value(g, n, kNodeVertexShare);
      degree_sum += node_value(g, n, kNodeDegree);
      EXPECT_EQ(node_value(g, n, kNodeFqMin), node.fq_min);
      EXPECT_EQ(node_value(g, n, kNodeFqMax), node.fq_max);
      EXPECT_EQ(node_value(g, n, kNodeFqSpan), node.fq_max - node.fq_min);
      EXPECT_EQ(node_value(g, n, kNodeStartType), static_cast<double>(node.type));
      EXPECT_EQ(node_value(g, n, kNodeEndType), static_cast<double>(node.end));
      const double degree = static_cast<double>(std::count_if(reeb.edges.begin(), reeb.edges.end(), [&](const auto& e) {
        return e[0] == n || e[1] == n;
      }));
      EXPECT_EQ(node_value(g, n, kNodeDegree), degree);
      EXPECT_GE(node_value(g, n, kNodeGeodesicExtent), 0.0);
      EXPECT_GE(node_value(g, n, kNodeMeanRadius), 0.0);
      if (node.vertex_count > 1) {
        EXPECT_GT(node_value(g, n, kNodeGeodesicExtent), 0.0) << "node " << n;
      }
      // Without hole fans the region's area is the graph's own (one third of
      // each incident triangle), relative to the surface as read.
      if (surface.num_vertices() == a.mesh.num_vertices()) {
        EXPECT_NEAR(node_value(g, n, kNodeRelativeArea), node.area / area, 1e-12) << "node " << n;
        EXPECT_DOUBLE_EQ(node_value(g, n, kNodeVertexShare), node.vertex_count / static_cast<double>(a.mesh.num_vertices()));
      }
    }
    EXPECT_NEAR(area_sum, 1.0, 1e-10);
    EXPECT_NEAR(share_sum, 1.0, 1e-10);
    EXPECT_EQ(degree_sum, 2.0 * reeb.num_edges());
    for (Index e = 0; e < reeb.num_edges(); ++e) {
      EXPECT_GE(edge_value(g, e, kEdgeBoundaryLength), 0.0);
      EXPECT_GE(edge_value(g, e, kEdgeEventFq), 0.0);
      EXPECT_LE(edge_value(g, e, kEdgeEventFq), 1.0);
    }
    for (const double x : g.signature) {
      EXPECT_GE(x, 0.0);
      EXPECT_LE(x, 1.0);
    }
    double histogram = 0.0;
    for (int b = 0; b < 6; ++b) histogram += signature_value(g, "area_hist_" + std::to_string(b));
    EXPECT_NEAR(histogram, 1.0, 1e-12);
    for (int k = 0; k + 1 < 6; ++k) {
      EXPECT_GE(signature_value(g, "leaf_area_" + std::to_string(k)), signature_value(g, "leaf_area_" + std::to_string(k + 1)));
      EXPECT_GE(signature_value(g, "leaf_extent_" + std::to_string(k)), signature_value(g, "leaf_extent_" + std::to_string(k + 1)));
    }
  }
}

// The hole of the punched star is closed by a fan around a new vertex: it
// counts neither towards areas nor vertex shares, which are relative to the
// surface as read, while the graph's own areas include the fan.
TEST(GraphAttributes, HoleFansDoNotCount) {
  const Case& c = cases()[1];
  ASSERT_EQ(c.name, "punched star");
  const MeshAnalysis& a = c.analysis;
  const Mesh surface = original_surface(a.mesh);
  ASSERT_EQ(surface.num_vertices() + 1, a.mesh.num_vertices()) << "expected the hole to be filled";
  const GraphAttributes g = compute_attributes(a);
  const double area = surface_area(surface);
  std::set<Index> at_fan;  // nodes with a vertex on a fan triangle
  for (Index t = 0; t < a.mesh.num_triangles(); ++t)
    if ((a.mesh.triangles.row(t).array() >= surface.num_vertices()).any())
      for (int k = 0; k < 3; ++k) at_fan.insert(a.reeb.vertex_node[static_cast<std::size_t>(a.mesh.triangles(t, k))]);
  ASSERT_FALSE(at_fan.empty());
  double graph_area = 0.0;
  for (Index n = 0; n < a.reeb.num_nodes(); ++n) {
    const ReebNode& node = a.reeb.nodes[static_cast<std::size_t>(n)];
    graph_area += node.area;
    Index original = 0;
    for (Index v = 0; v < surface.num_vertices(); ++v) original += a.reeb.vertex_node[static_cast<std::size_t>(v)] == n;
    EXPECT_NEAR(node_value(g, n, kNodeVertexShare) * surface.num_vertices(), original, 1e-9) << "node " << n;
    if (at_fan.count(n) == 0) {  // away from the fan: the graph's own area
      EXPECT_NEAR(node_value(g, n, kNodeRelativeArea) * area, node.area, 1e-12 * area) << "node " << n;
    }
  }
  EXPECT_GT(graph_area, area * (1 + 1e-6));  // the fan
}

}  // namespace
}  // namespace reebkit

#include "reebkit/output/reeb_graph_export.h"

#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/io/ply.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/output/colormap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <sstream>

namespace reebkit::test {
namespace {

const char* const kPython = "/usr/bin/python3";

/// A star (5 leaves, a tree) and a torus (one cycle), numbered as two
/// components of one file: the torus's vertex ids come after the star's.
std::vector<MeshAnalysis> star_and_torus() {
  std::vector<MeshAnalysis> components;
  components.push_back(analyze_mesh(make_star(StarOptions{5, 4})));
  Mesh torus = make_torus(40, 14);
  torus.source_vertex.resize(static_cast<std::size_t>(torus.num_vertices()));
  std::iota(torus.source_vertex.begin(), torus.source_vertex.end(), components[0].mesh.num_vertices());
  components.push_back(analyze_mesh(torus));
  return components;
}

/// Standard output of `python3 -c script path`.
std::string run_python(const std::string& script, const std::filesystem::path& path) {
  const std::string command = std::string(kPython) + " -c '" + script + "' '" + path.string() + "'";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return "popen failed";
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  ::pclose(pipe);
  return output;
}

TEST(ReebGraphExport, JsonParsesWithEveryNodeEdgeAndSkeletonPoint) {
  if (!std::filesystem::exists(kPython)) GTEST_SKIP() << kPython << " not found";
  const std::vector<MeshAnalysis> components = star_and_torus();
  const TempDir dir;
  write_reeb_graph_json(dir / "graph.json", components);
  // Counts as Python's json module reads them, and the checks it can make alone.
  const std::string output = run_python(
      "import json, sys\n"
      "g = json.load(open(sys.argv[1]))\n"
      "ids = [n[\"id\"] for n in g[\"nodes\"]]\n"
      "assert ids == list(range(len(ids))), ids\n"
      "assert all(0 <= a < b < len(ids) for a, b in g[\"edges\"])\n"
      "assert len(g[\"skeleton\"]) == len(ids)\n"
      "assert all(len(p) == 3 for s in g[\"skeleton\"] for p in s)\n"
      "leaves = sum(n[\"end\"] == \"termination\" for n in g[\"nodes\"])\n"
      "t = g[\"timings_ms\"]\n"
      "print(g[\"components\"], g[\"vertices\"], g[\"triangles\"], len(g[\"feature_points\"]), len(ids),\n"
      "      len(g[\"edges\"]), g[\"cycles\"], g[\"leaves\"], leaves, sum(len(s) for s in g[\"skeleton\"]),\n"
      "      sum(n[\"type\"] == \"root\" for n in g[\"nodes\"]), g[\"feature_points\"][-1], g[\"edges\"][-1][1],\n"
      "      round(t[\"graph\"] + t[\"features\"] + t[\"quotient\"] + t[\"reeb\"], 6))\n",
      dir / "graph.json");
  long long vertices = 0, triangles = 0, features = 0, nodes = 0, edges = 0, leaves = 0, points = 0;
  double time = 0;
  for (const MeshAnalysis& r : components) {
    vertices += r.mesh.num_vertices();
    triangles += r.mesh.num_triangles();
    features += static_cast<long long>(r.features.vertices.size());
    nodes += r.reeb.num_nodes();
    edges += r.reeb.num_edges();
    time += r.timings.total();
    for (const ReebNode& n : r.reeb.nodes) {
      leaves += n.end == NodeType::Termination;
      points += static_cast<long long>(n.skeleton.size());
    }
  }
  const MeshAnalysis& torus = components[1];
  std::ostringstream expected;
  expected << "2 " << vertices << " " << triangles << " " << features << " " << nodes << " " << edges << " 1 " << leaves
           << " " << leaves << " " << points << " 2 " << torus.mesh.source_index(torus.features.vertices.back()) << " "
           << components[0].reeb.num_nodes() + torus.reeb.edges.back()[1];
  // The timings are rounded by Python: compare them as numbers.
  std::istringstream got(output);
  std::string line;
  std::getline(got, line);
  const auto cut = line.rfind(' ');
  ASSERT_NE(cut, std::string::npos) << output;
  EXPECT_EQ(line.substr(0, cut), expected.str());
  EXPECT_NEAR(std::stod(line.substr(cut + 1)), time, 1e-5);
  EXPECT_EQ(leaves, 5 + std::count_if(torus.reeb.nodes.begin(), torus.reeb.nodes.end(),
                                      [](const ReebNode& n) { return n.end == NodeType::Termination; }));
}

TEST(ReebGraphExport, PlyHoldsTheSegmentation) {
  const std::vector<MeshAnalysis> components = star_and_torus();
  const TempDir dir;
  write_segmentation_ply(dir / "segments.ply", components);
  const PolygonSoup soup = read_ply(dir / "segments.ply");
  const MeshAnalysis& star = components[0];
  const MeshAnalysis& torus = components[1];
  ASSERT_EQ(soup.num_vertices(), star.mesh.num_vertices() + torus.mesh.num_vertices());
  EXPECT_EQ(soup.num_polygons(), star.mesh.num_triangles() + torus.mesh.num_triangles());
  ASSERT_EQ(soup.vertex_colors.rows(), soup.num_vertices());
  for (const auto& [r, first_vertex, first_node] :
       {std::tuple{&star, 0, 0}, std::tuple{&torus, star.mesh.num_vertices(), star.reeb.num_nodes()}}) {
    for (Index v = 0; v < r->mesh.num_vertices(); ++v) {
      const Vec3 color = category_color(first_node + r->reeb.vertex_node[static_cast<std::size_t>(v)]);
      EXPECT_LT((Vec3(soup.vertex_colors.row(first_vertex + v)) - color).cwiseAbs().maxCoeff(), 0.5 / 255 + 1e-9);
      EXPECT_EQ(Vec3(soup.vertices.row(first_vertex + v)), Vec3(r->mesh.vertices.row(v)));
    }
  }
  if (!std::filesystem::exists(kPython))
    GTEST_SKIP() << kPython << " not found: the node and fq properties are unchecked";
  // The scalar properties, read by numpy from the binary body.
  const std::string output = run_python(
      "import sys, numpy as np\n"
      "data = open(sys.argv[1], \"rb\").read()\n"
      "end = data.index(b\"end_header\\n\") + len(b\"end_header\\n\")\n"
      "header = data[:end].decode().split(\"\\n\")\n"
      "n = int([l for l in header if l.startswith(\"element vertex\")][0].split()[2])\n"
      "types = {\"double\": \"<f8\", \"uchar\": \"u1\", \"float\": \"<f4\"}\n"
      "props = [l.split() for l in header if l.startswith(\"property \") and \"list\" not in l]\n"
      "dt = np.dtype([(p[2], types[p[1]]) for p in props])\n"
      "v = np.frombuffer(data, dtype=dt, count=n, offset=end)\n"
      "print(\" \".join(\"%r\" % x for x in v[\"node\"]))\n"
      "print(\" \".join(\"%r\" % x for x in v[\"fq\"]))\n",
      dir / "segments.ply");
  std::istringstream lines(output);
  std::string node_line, fq_line;
  std::getline(lines, node_line);
  std::getline(lines, fq_line);
  std::istringstream nodes(node_line), fq(fq_line);
  for (const auto& [r, first_node] : {std::pair{&star, 0}, std::pair{&torus, star.reeb.num_nodes()}}) {
    for (Index v = 0; v < r->mesh.num_vertices(); ++v) {
      double node = -1, f = -1;
      ASSERT_TRUE(nodes >> node) << output.substr(0, 300);
      ASSERT_TRUE(fq >> f);
      EXPECT_EQ(node, first_node + r->reeb.vertex_node[static_cast<std::size_t>(v)]);
      EXPECT_EQ(f, r->fq.value[static_cast<std::size_t>(v)]);
    }
  }
}

/// The OBJ's objects: vertices and `l` lines (1-based numbers) of each.
struct ObjLines {
  std::vector<Vec3> vertices;
  std::vector<std::string> objects;
  std::vector<std::vector<std::vector<Index>>> lines;  // per object
};

ObjLines read_obj_lines(const std::filesystem::path& path) {
  ObjLines obj;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "o") {
      obj.objects.emplace_back();
      words >> obj.objects.back();
      obj.lines.emplace_back();
    } else if (tag == "v") {
      Vec3 p;
      words >> p.x() >> p.y() >> p.z();
      obj.vertices.push_back(p);
    } else if (tag == "l") {
      std::vector<Index> polyline;
      for (Index i; words >> i;) polyline.push_back(i);
      obj.lines.back().push_back(polyline);
    }
  }
  return obj;
}

// The graph object is the graph; the skeleton object holds every skeleton
// point, each node's polyline, and is connected like the graph (one piece
// per component).
TEST(ReebGraphExport, ObjDrawsTheGraphAndAConnectedSkeleton) {
  const std::vector<MeshAnalysis> components = star_and_torus();
  const TempDir dir;
  write_skeleton_obj(dir / "skeleton.obj", components);
  const ObjLines obj = read_obj_lines(dir / "skeleton.obj");
  ASSERT_EQ(obj.objects, (std::vector<std::string>{"reeb_graph", "skeleton"}));
  std::vector<Vec3> expected;
  std::vector<std::vector<Index>> graph_lines;
  for (const MeshAnalysis& r : components) {
    const auto first = static_cast<Index>(expected.size()) + 1;
    for (const ReebNode& n : r.reeb.nodes) expected.push_back(n.barycenter);
    for (const auto& [a, b] : r.reeb.edges) graph_lines.push_back({first + a, first + b});
  }
  EXPECT_EQ(obj.lines[0], graph_lines);
  const std::size_t nodes = expected.size();
  for (const MeshAnalysis& r : components)
    for (const ReebNode& n : r.reeb.nodes) expected.insert(expected.end(), n.skeleton.begin(), n.skeleton.end());
  ASSERT_EQ(obj.vertices.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(obj.vertices[k], expected[k]) << "vertex " << k + 1;

  // Pieces of the skeleton: union-find over its points joined by its lines.
  std::vector<std::size_t> parent(expected.size() - nodes);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto find = [&parent](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const std::vector<Index>& polyline : obj.lines[1]) {
    ASSERT_GE(polyline.size(), 2u);
    for (const Index i : polyline)
      ASSERT_TRUE(i > static_cast<Index>(nodes) && i <= static_cast<Index>(expected.size()));
    for (std::size_t k = 1; k < polyline.size(); ++k)
      parent[find(static_cast<std::size_t>(polyline[k]) - nodes - 1)] =
          find(static_cast<std::size_t>(polyline[0]) - nodes - 1);
  }
  std::size_t pieces = 0;
  for (std::size_t k = 0; k < parent.size(); ++k) pieces += find(k) == k;
  EXPECT_EQ(pieces, components.size());
}

TEST(ReebGraphExport, RejectsMissingGraphsAndUnwritablePaths) {
  const TempDir dir;
  EXPECT_THROW(write_reeb_graph_json(dir / "a.json", {}), InvalidArgument);
  AnalysisOptions no_graph;
  no_graph.reeb_graph = false;
  const std::vector<MeshAnalysis> features_only = {analyze_mesh(make_icosphere(2), no_graph)};
  EXPECT_THROW(write_skeleton_obj(dir / "a.obj", features_only), InvalidArgument);
  const std::vector<MeshAnalysis> sphere = {analyze_mesh(make_icosphere(2))};
  try {
    write_reeb_graph_json(dir / "missing" / "a.json", sphere);
    ADD_FAILURE() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_skeleton_obj(dir / "missing" / "a.obj", sphere), Error);
}

}  // namespace
}  // namespace reebkit::test

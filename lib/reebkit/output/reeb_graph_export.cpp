#include "reebkit/output/reeb_graph_export.h"

#include "reebkit/core/error.h"
#include "reebkit/io/ply.h"
#include "reebkit/mesh/hole_filling.h"
#include "reebkit/output/colormap.h"
#include "reebkit/output/json_writer.h"

#include <fstream>
#include <string>

namespace reebkit {
namespace {

/// Throws unless there is at least one component and each has its Reeb graph.
void check_components(const char* who, const std::vector<MeshAnalysis>& components) {
  if (components.empty()) throw InvalidArgument(std::string(who) + ": no components");
  for (std::size_t c = 0; c < components.size(); ++c)
    if (components[c].reeb.nodes.empty())
      throw InvalidArgument(std::string(who) + ": component " + std::to_string(c) + " has no Reeb graph");
}

/// The id of each component's node 0 in the joined graph.
std::vector<Index> node_offsets(const std::vector<MeshAnalysis>& components) {
  std::vector<Index> offset;
  Index next = 0;
  for (const MeshAnalysis& r : components) {
    offset.push_back(next);
    next += r.reeb.num_nodes();
  }
  return offset;
}

std::ofstream open_for_writing(const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw Error(path.string() + ": cannot open for writing");
  return out;
}

void check_written(const std::ofstream& out, const std::filesystem::path& path) {
  if (!out) throw Error(path.string() + ": write failed");
}

template <typename Point>
std::vector<double> xyz(const Point& p) {
  return {p(0), p(1), p(2)};
}

}  // namespace

void write_reeb_graph_json(const std::filesystem::path& path, const std::vector<MeshAnalysis>& components) {
  check_components("write_reeb_graph_json", components);
  const std::vector<Index> offset = node_offsets(components);
  long long vertices = 0, triangles = 0, cycles = 0, leaves = 0;
  AnalysisTimings time;
  for (const MeshAnalysis& r : components) {
    const Mesh surface = original_surface(r.mesh);
    vertices += surface.num_vertices();
    triangles += surface.num_triangles();
    cycles += r.reeb.independent_cycles();
    for (const ReebNode& node : r.reeb.nodes) leaves += node.end == NodeType::Termination;
    time.graph += r.timings.graph;
    time.features += r.timings.features;
    time.quotient += r.timings.quotient;
    time.reeb += r.timings.reeb;
  }

  std::ofstream out = open_for_writing(path);
  JsonWriter json(out);
  json.begin_object()
      .field("mesh", components.front().mesh.source)
      .field("components", static_cast<long long>(components.size()))
      .field("vertices", vertices)
      .field("triangles", triangles);
  std::vector<long long> features;
  for (const MeshAnalysis& r : components)
    for (const Index v : r.features.vertices) features.push_back(r.mesh.source_index(v));
  json.key("feature_points").numbers(features);

  json.key("nodes").begin_array();
  for (std::size_t c = 0; c < components.size(); ++c) {
    const MeshAnalysis& r = components[c];
    for (Index n = 0; n < r.reeb.num_nodes(); ++n) {
      const ReebNode& node = r.reeb.nodes[static_cast<std::size_t>(n)];
      json.begin_object()
          .field("id", static_cast<long long>(offset[c] + n))
          .field("component", static_cast<long long>(c))
          .field("type", node_type_name(node.type))
          .field("end", node_type_name(node.end))
          .field("birth_vertex", static_cast<long long>(r.mesh.source_index(node.birth_vertex)))
          .field("vertex_count", static_cast<long long>(node.vertex_count))
          .field("area", node.area)
          .field("fq_min", node.fq_min)
          .field("fq_max", node.fq_max);
      json.key("barycenter").numbers(xyz(node.barycenter));
      json.end_object();
    }
  }
  json.end_array();

  json.key("edges").begin_array();
  for (std::size_t c = 0; c < components.size(); ++c)
    for (const auto& [a, b] : components[c].reeb.edges)
      json.numbers(std::vector<long long>{offset[c] + a, offset[c] + b});
  json.end_array();
  json.field("cycles", cycles).field("leaves", leaves);

  json.key("skeleton").begin_array();
  for (const MeshAnalysis& r : components) {
    for (const ReebNode& node : r.reeb.nodes) {
      json.begin_array();
      for (const Vec3& p : node.skeleton) json.numbers(xyz(p));
      json.end_array();
    }
  }
  json.end_array();

  json.key("timings_ms")
      .begin_object()
      .field("graph", time.graph)
      .field("features", time.features)
      .field("quotient", time.quotient)
      .field("reeb", time.reeb)
      .end_object();
  json.end_object();
  out << "\n";
  check_written(out, path);
}

void write_segmentation_ply(const std::filesystem::path& path, const std::vector<MeshAnalysis>& components) {
  check_components("write_segmentation_ply", components);
  const std::vector<Index> offset = node_offsets(components);
  // The surfaces as read: vertices and triangles added by hole filling are
  // left out (they come last in each component).
  std::vector<Mesh> surfaces;
  Index vertices = 0, triangles = 0;
  for (const MeshAnalysis& r : components) {
    surfaces.push_back(original_surface(r.mesh));
    vertices += surfaces.back().num_vertices();
    triangles += surfaces.back().num_triangles();
  }
  Mesh mesh;
  mesh.vertices.resize(vertices, 3);
  mesh.triangles.resize(triangles, 3);
  PlyVertexData data;
  data.colors.resize(vertices, 3);
  std::vector<double> node(static_cast<std::size_t>(vertices));
  std::vector<double> fq(static_cast<std::size_t>(vertices));
  Index v0 = 0, t0 = 0;
  for (std::size_t c = 0; c < components.size(); ++c) {
    const MeshAnalysis& r = components[c];
    const Mesh& surface = surfaces[c];
    mesh.vertices.middleRows(v0, surface.num_vertices()) = surface.vertices;
    mesh.triangles.middleRows(t0, surface.num_triangles()) = surface.triangles.array() + v0;
    for (Index v = 0; v < surface.num_vertices(); ++v) {
      const Index id = offset[c] + r.reeb.vertex_node[static_cast<std::size_t>(v)];
      data.colors.row(v0 + v) = category_color(id).transpose();
      node[static_cast<std::size_t>(v0 + v)] = id;
      fq[static_cast<std::size_t>(v0 + v)] = r.fq.value[static_cast<std::size_t>(v)];
    }
    v0 += surface.num_vertices();
    t0 += surface.num_triangles();
  }
  data.scalars.emplace_back("node", std::move(node));
  data.scalars.emplace_back("fq", std::move(fq));
  write_ply(path, mesh, data);
}

void write_skeleton_obj(const std::filesystem::path& path, const std::vector<MeshAnalysis>& components) {
  check_components("write_skeleton_obj", components);
  std::ofstream out = open_for_writing(path);
  out.precision(17);
  out << "# reebkit: dual Reeb graph (nodes at their barycenters) and topological skeleton of "
      << components.front().mesh.source << "\n";
  // OBJ vertex numbers are 1-based and run on across objects.
  out << "o reeb_graph\n";
  Index first = 1;  // OBJ number of the current component's node 0
  for (const MeshAnalysis& r : components) {
    for (const ReebNode& node : r.reeb.nodes)
      out << "v " << node.barycenter.x() << " " << node.barycenter.y() << " " << node.barycenter.z() << "\n";
    for (const auto& [a, b] : r.reeb.edges) out << "l " << first + a << " " << first + b << "\n";
    first += r.reeb.num_nodes();
  }
  out << "o skeleton\n";
  Index next = first;  // OBJ number of the next skeleton point
  for (const MeshAnalysis& r : components) {
    std::vector<Index> start;  // OBJ number of each node's first skeleton point
    for (const ReebNode& node : r.reeb.nodes) {
      start.push_back(next);
      for (const Vec3& p : node.skeleton) out << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
      if (node.skeleton.size() > 1) {
        out << "l";
        for (std::size_t k = 0; k < node.skeleton.size(); ++k) out << " " << next + static_cast<Index>(k);
        out << "\n";
      }
      next += static_cast<Index>(node.skeleton.size());
    }
    for (const auto& [a, b] : r.reeb.edges) {
      const Index last_of_a = start[static_cast<std::size_t>(a)] +
                              static_cast<Index>(r.reeb.nodes[static_cast<std::size_t>(a)].skeleton.size()) - 1;
      out << "l " << last_of_a << " " << start[static_cast<std::size_t>(b)] << "\n";
    }
  }
  check_written(out, path);
}

}  // namespace reebkit

#include "reebkit/output/reeb_graph_export.h"

#include "reebkit/core/error.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/json_writer.h"
#include "reebkit/io/ply.h"
#include "reebkit/mesh/hole_filling.h"
#include "reebkit/output/colormap.h"
#include "reebkit/output/obj_lines.h"
#include "reebkit/pipeline/mesh_record.h"

#include <sstream>
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

}  // namespace

void write_reeb_graph_json(std::ostream& out, const std::string& mesh, const std::vector<GraphRecord>& components) {
  if (components.empty()) throw InvalidArgument("write_reeb_graph_json: no components");
  for (std::size_t c = 0; c < components.size(); ++c)
    if (!components[c].ok || components[c].nodes.empty())
      throw InvalidArgument("write_reeb_graph_json: component " + std::to_string(c) + " has no Reeb graph" +
                            (components[c].error.empty() ? "" : " (" + components[c].error + ")"));
  long long vertices = 0, triangles = 0, cycles = 0, leaves = 0;
  std::array<double, kTimeColumnCount> time{};
  std::vector<long long> features;
  for (const GraphRecord& e : components) {
    vertices += e.vertices;
    triangles += e.faces;
    cycles += independent_cycles(e);
    leaves += leaf_count(e);
    for (std::size_t k = 0; k < time.size(); ++k) time[k] += e.timings[k];
    features.insert(features.end(), e.feature_points.begin(), e.feature_points.end());
  }

  JsonWriter json(out);
  json.begin_object()
      .field("mesh", mesh)
      .field("components", static_cast<long long>(components.size()))
      .field("vertices", vertices)
      .field("triangles", triangles);
  json.key("feature_points").numbers(features);

  const auto name = [](std::int32_t type) { return node_type_name(static_cast<NodeType>(type)); };
  json.key("nodes").begin_array();
  long long first = 0;  // id of the component's node 0
  for (std::size_t c = 0; c < components.size(); ++c) {
    const GraphRecord& e = components[c];
    for (std::size_t n = 0; n < static_cast<std::size_t>(e.num_nodes()); ++n) {
      const std::int32_t* node = &e.nodes[n * kNodeColumnCount];
      const double* geometry = &e.node_geometry[n * kGeomColumnCount];
      json.begin_object()
          .field("id", first + static_cast<long long>(n))
          .field("component", static_cast<long long>(c))
          .field("type", name(node[kNodeType]))
          .field("end", name(node[kNodeEnd]))
          .field("birth_vertex", static_cast<long long>(node[kNodeBirthVertex]))
          .field("vertex_count", static_cast<long long>(node[kNodeVertexCount]))
          .field("area", geometry[kGeomArea])
          .field("fq_min", geometry[kGeomFqMin])
          .field("fq_max", geometry[kGeomFqMax]);
      json.key("barycenter").numbers(std::vector<double>(geometry + kGeomBarycenterX, geometry + kGeomBarycenterZ + 1));
      json.key("attributes").begin_object();
      for (std::size_t a = 0; a < kNodeAttributeNames.size(); ++a)
        json.field(kNodeAttributeNames[a], e.node_attributes[n * kNodeAttributeCount + a]);
      json.end_object().end_object();
    }
    first += e.num_nodes();
  }
  json.end_array();

  json.key("edges").begin_array();
  first = 0;
  for (const GraphRecord& e : components) {
    for (std::size_t k = 0; k < e.edges.size(); k += 2)
      json.numbers(std::vector<long long>{first + e.edges[k], first + e.edges[k + 1]});
    first += e.num_nodes();
  }
  json.end_array();
  json.key("edge_attributes").begin_array();
  for (const GraphRecord& e : components) {
    for (std::size_t k = 0; k < static_cast<std::size_t>(e.num_edges()); ++k) {
      json.begin_object();
      for (std::size_t a = 0; a < kEdgeAttributeNames.size(); ++a)
        json.field(kEdgeAttributeNames[a], e.edge_attributes[k * kEdgeAttributeCount + a]);
      json.end_object();
    }
  }
  json.end_array();
  json.field("cycles", cycles).field("leaves", leaves);

  json.key("skeleton").begin_array();
  for (const GraphRecord& e : components) {
    for (std::size_t n = 0; n + 1 < e.skeleton_offset.size(); ++n) {
      json.begin_array();
      for (auto p = e.skeleton_offset[n]; p < e.skeleton_offset[n + 1]; ++p) {
        const double* xyz = &e.skeleton_points[3 * static_cast<std::size_t>(p)];
        json.numbers(std::vector<double>(xyz, xyz + 3));
      }
      json.end_array();
    }
  }
  json.end_array();
  json.key("signature").begin_array();
  for (const GraphRecord& e : components) json.numbers(e.signature);
  json.end_array();

  json.key("timings_ms")
      .begin_object()
      .field("graph", time[kTimeGraph])
      .field("features", time[kTimeFeatures])
      .field("quotient", time[kTimeQuotient])
      .field("reeb", time[kTimeReeb])
      .end_object();
  json.end_object();
  out << "\n";
}

void write_reeb_graph_json(const std::filesystem::path& path, const std::vector<MeshAnalysis>& components) {
  check_components("write_reeb_graph_json", components);
  std::vector<GraphRecord> entries;
  for (const MeshAnalysis& r : components) entries.push_back(make_graph_record(r, compute_attributes(r)));
  std::ostringstream out;
  write_reeb_graph_json(out, components.front().mesh.source, entries);
  write_file_bytes(path, out.str());
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
  std::ostringstream out;
  ObjLinesWriter obj(out);
  obj.comment("reebkit: dual Reeb graph (nodes at their barycenters) and topological skeleton of " +
              components.front().mesh.source);
  obj.object("reeb_graph");
  for (const MeshAnalysis& r : components) {
    const Index first = obj.points() + 1;  // OBJ number of the component's node 0
    for (const ReebNode& node : r.reeb.nodes) obj.point(node.barycenter);
    for (const auto& [a, b] : r.reeb.edges) obj.line({first + a, first + b});
  }
  obj.object("skeleton");
  for (const MeshAnalysis& r : components) {
    std::vector<std::vector<Index>> polyline;  // OBJ numbers of each node's skeleton points
    for (const ReebNode& node : r.reeb.nodes) {
      polyline.emplace_back();
      for (const Vec3& p : node.skeleton) polyline.back().push_back(obj.point(p));
      if (polyline.back().size() > 1) obj.line(polyline.back());
    }
    for (const auto& [a, b] : r.reeb.edges)
      obj.line({polyline[static_cast<std::size_t>(a)].back(), polyline[static_cast<std::size_t>(b)].front()});
  }
  write_file_bytes(path, out.str());
}

}  // namespace reebkit

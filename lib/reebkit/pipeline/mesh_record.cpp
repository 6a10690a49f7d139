#include "reebkit/pipeline/mesh_record.h"

#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/content_hash.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/mesh/hole_filling.h"
#include "reebkit/mesh/load_mesh.h"

#include <limits>

namespace reebkit {

GraphRecord make_graph_record(const MeshAnalysis& analysis, const GraphAttributes& attributes) {
  const ReebGraph& reeb = analysis.reeb;
  const Mesh& mesh = analysis.mesh;
  if (reeb.nodes.empty()) throw InvalidArgument("make_graph_record: the analysis has no Reeb graph");
  const auto n = static_cast<std::size_t>(reeb.num_nodes());
  const auto e = static_cast<std::size_t>(reeb.num_edges());
  if (attributes.node.size() != n * kNodeAttributeCount || attributes.edge.size() != e * kEdgeAttributeCount ||
      attributes.signature.size() != static_cast<std::size_t>(kSignatureLength))
    throw InvalidArgument("make_graph_record: the attributes do not match the graph (" + std::to_string(n) +
                          " nodes, " + std::to_string(e) + " edges)");

  GraphRecord out;
  out.ok = true;
  const Index kept = original_vertex_count(mesh);
  out.vertices = kept;
  for (Index f = 0; f < mesh.num_triangles(); ++f) out.faces += (mesh.triangles.row(f).array() < kept).all();
  out.timings[kTimeGraph] = analysis.timings.graph;
  out.timings[kTimeFeatures] = analysis.timings.features;
  out.timings[kTimeQuotient] = analysis.timings.quotient;
  out.timings[kTimeReeb] = analysis.timings.reeb;

  out.nodes.reserve(n * kNodeColumnCount);
  out.node_geometry.reserve(n * kGeomColumnCount);
  out.skeleton_offset.push_back(0);
  for (const ReebNode& node : reeb.nodes) {
    out.nodes.insert(out.nodes.end(), {static_cast<std::int32_t>(node.type), static_cast<std::int32_t>(node.end),
                                       mesh.source_index(node.birth_vertex), node.vertex_count});
    out.node_geometry.insert(out.node_geometry.end(), {node.area, node.fq_min, node.fq_max, node.barycenter.x(),
                                                       node.barycenter.y(), node.barycenter.z()});
    for (const Vec3& p : node.skeleton) out.skeleton_points.insert(out.skeleton_points.end(), {p.x(), p.y(), p.z()});
    out.skeleton_offset.push_back(out.skeleton_offset.back() + static_cast<std::int64_t>(node.skeleton.size()));
  }
  for (const auto& [a, b] : reeb.edges) out.edges.insert(out.edges.end(), {a, b});
  for (const Index v : analysis.features.vertices) out.feature_points.push_back(mesh.source_index(v));
  out.node_attributes = attributes.node;
  out.edge_attributes = attributes.edge;
  out.signature = attributes.signature;
  return out;
}

GraphRecord analyze_mesh_file(const std::filesystem::path& path, std::string name, const AnalysisOptions& options,
                              std::uint64_t* content_hash) {
  Timer timer;
  const std::string bytes = read_file_bytes(path);
  const std::uint64_t hash = hash_bytes(bytes);
  if (content_hash) *content_hash = hash;
  CleanedMesh cleaned = load_mesh_bytes(bytes, path);
  const double load_ms = timer.lap();
  const MeshAnalysis analysis = analyze_mesh(std::move(cleaned.components.front()), options);
  timer.lap();
  const GraphAttributes attributes = compute_attributes(analysis);
  const double attributes_ms = timer.lap();
  GraphRecord entry = make_graph_record(analysis, attributes);
  entry.name = std::move(name);
  entry.content_hash = hash;
  entry.timings[kTimeLoad] = load_ms;
  entry.timings[kTimeAttributes] = attributes_ms + analysis.timings.spectra_surface + analysis.timings.measures;
  return entry;
}

GraphRecord failed_graph_record(std::string name, std::string class_label, std::uint64_t content_hash,
                                std::string error) {
  GraphRecord out;
  out.name = std::move(name);
  out.class_label = std::move(class_label);
  out.content_hash = content_hash;
  out.error = std::move(error);
  out.signature.assign(kSignatureLength, std::numeric_limits<double>::quiet_NaN());
  return out;
}

}  // namespace reebkit

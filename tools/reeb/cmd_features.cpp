// reeb features MESH: feature points and the quotient function f_q of a mesh
// (Tierny et al. 2006, section 4.1).
#include "reeb/cli.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/json_writer.h"
#include "reebkit/io/ply.h"
#include "reebkit/mesh/hole_filling.h"
#include "reebkit/output/colormap.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <iomanip>
#include <iostream>
#include <sstream>

namespace reebkit::cli {

namespace {

void print(const MeshAnalysis& r, std::size_t index, std::size_t count) {
  const Index added = r.mesh.num_vertices() - original_vertex_count(r.mesh);
  std::cout << (count > 1 ? "component " + std::to_string(index) + ": " : std::string())
            << original_vertex_count(r.mesh) << " vertices"
            << (added > 0 ? " (+" + std::to_string(added) + " added to close small holes)" : std::string())
            << ", geodesic diameter " << r.features.diameter << "\n"
            << r.features.vertices.size()
            << " feature points (vertex ids as in the file; -1: a vertex added to close a hole):\n";
  for (const Index v : r.features.vertices)
    std::cout << "  " << std::setw(8) << r.mesh.source_index(v) << "  (" << r.mesh.vertices(v, 0) << ", "
              << r.mesh.vertices(v, 1) << ", " << r.mesh.vertices(v, 2) << ")\n";
  std::cout << std::fixed << std::setprecision(2) << "time: graph " << r.timings.graph << " ms, features "
            << r.timings.features << " ms, f_q " << r.timings.quotient << " ms\n"
            << std::defaultfloat << std::setprecision(6);
}

void write_json(const std::string& path, const std::string& mesh_path, const FeatureOptions& options,
                const std::vector<MeshAnalysis>& results, double load_ms) {
  std::ostringstream out;
  JsonWriter json(out);
  json.begin_object()
      .field("mesh", mesh_path)
      .field("epsilon", options.epsilon)
      .field("geodesic", geodesic_name(options.geodesic))
      .field("min_persistence", options.min_persistence)
      .field("load_ms", load_ms);
  json.key("components").begin_array();
  for (const MeshAnalysis& r : results) {
    json.begin_object()
        .field("vertices", static_cast<long long>(original_vertex_count(r.mesh)))
        .field("hole_filling_vertices", static_cast<long long>(r.mesh.num_vertices() - original_vertex_count(r.mesh)))
        .field("diameter", r.features.diameter);
    json.key("diameter_ends")
        .numbers(
            std::vector<long long>{r.mesh.source_index(r.features.source1), r.mesh.source_index(r.features.source2)});
    json.key("feature_points").begin_array();
    for (const Index v : r.features.vertices) {
      json.begin_object().field("vertex", static_cast<long long>(r.mesh.source_index(v)));
      json.key("position")
          .numbers(std::vector<double>{r.mesh.vertices(v, 0), r.mesh.vertices(v, 1), r.mesh.vertices(v, 2)});
      json.end_object();
    }
    json.end_array();
    json.key("timings_ms")
        .begin_object()
        .field("graph", r.timings.graph)
        .field("features", r.timings.features)
        .field("quotient", r.timings.quotient)
        .end_object();
    json.end_object();
  }
  json.end_array().end_object();
  write_file_bytes(path, out.str());
}

// f_q as viridis colors; the geodesic disc of radius 1.5% of the diameter
// around each feature point painted red so that the points are visible.
// Shows the surface as read: vertices added by hole filling (the last ones)
// are left out.
void write_fq_ply(const std::string& path, const MeshAnalysis& r, Geodesic geodesic) {
  const Mesh surface = original_surface(r.mesh);
  const auto n = static_cast<std::size_t>(surface.num_vertices());
  const std::vector<double> fq(r.fq.value.begin(), r.fq.value.begin() + static_cast<std::ptrdiff_t>(n));
  PlyVertexData data;
  data.colors = colorize(fq, 0.0, 1.0);
  std::vector<double> marker(n, 0.0);
  const DistanceField near =
      geodesic_distances(r.graph, r.features.vertices, geodesic, GeodesicOptions{0.015 * r.features.diameter});
  for (Index v = 0; v < surface.num_vertices(); ++v) {
    if (near.nearest_source[v] == kInvalidIndex) continue;
    data.colors.row(v) << 0.85, 0.1, 0.1;
    marker[static_cast<std::size_t>(v)] = near.nearest_source[v] + 1;
  }
  data.scalars.emplace_back("fq", fq);
  data.scalars.emplace_back("feature", marker);
  write_ply(path, surface, data);
}

}  // namespace

int run_features(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string mesh_path, json_path, ply_path;
  AnalysisOptions analysis;
  analysis.reeb_graph = false;
  FeatureOptions& feature_options = analysis.features;
  bool all_components = false;
  options.add_options()("mesh", po::value(&mesh_path)->required(), "mesh file (.off .obj .ply .stl)")(
      "output,o", po::value(&json_path),
      "write the feature points as JSON")("ply", po::value(&ply_path),
                                          "write the mesh with f_q as colors and the feature points marked in red");
  add_components_option(options, all_components);
  options.add(analysis_options(analysis));
  po::positional_options_description positional;
  positional.add("mesh", 1);
  po::variables_map vm;
  if (!parse(args, "reeb features MESH [-o features.json] [--ply fq.ply] [--all-components] [analysis options]",
             options, positional, vm))
    return 0;
  check_outputs({json_path, ply_path}, {mesh_path});

  LoadedMesh loaded = load_for_command(mesh_path, all_components);
  CleanedMesh& cleaned = loaded.cleaned;
  const double load_ms = loaded.milliseconds;

  std::vector<MeshAnalysis> results;
  for (std::size_t c = 0; c < cleaned.components.size(); ++c) {
    results.push_back(analyze_mesh(std::move(cleaned.components[c]), analysis));
    print(results.back(), c, cleaned.components.size());
  }
  if (!json_path.empty()) {
    write_json(json_path, mesh_path, feature_options, results, load_ms);
    std::cout << "wrote " << json_path << "\n";
  }
  if (!ply_path.empty()) {
    write_fq_ply(ply_path, results.front(), feature_options.geodesic);
    std::cout << "wrote " << ply_path << (results.size() > 1 ? " (largest component)" : "") << "\n";
  }
  return 0;
}

}  // namespace reebkit::cli

// reeb graph MESH -o graph.json: the invariant high-level Reeb graph of a mesh
// (Tierny et al. 2006, section 4.2), its segmentation and topological
// skeleton (section 5.2), as JSON, a colored PLY, OBJ lines and a figure.
#include "reeb/cli.h"
#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/output/reeb_graph_export.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>

namespace reebkit::cli {

namespace {

void print_summary(const std::vector<MeshAnalysis>& results) {
  Index vertices = 0, features = 0, cycles = 0;
  Index count[4] = {0, 0, 0, 0};  // nodes by type, in NodeType order
  Index leaves = 0;
  AnalysisTimings time;
  for (const MeshAnalysis& r : results) {
    vertices += r.mesh.num_vertices();
    features += static_cast<Index>(r.features.vertices.size());
    cycles += r.reeb.independent_cycles();
    leaves += r.reeb.leaf_count();
    for (const ReebNode& n : r.reeb.nodes) ++count[static_cast<int>(n.type)];
    time.graph += r.timings.graph;
    time.features += r.timings.features;
    time.quotient += r.timings.quotient;
    time.reeb += r.timings.reeb;
    time.measures += r.timings.measures;
    time.spectra_surface += r.timings.spectra_surface;
  }
  std::cout << vertices << " vertices, " << features << " feature points\n"
            << count[0] + count[1] + count[2] + count[3] << " nodes:";
  for (const NodeType type : {NodeType::Root, NodeType::Bifurcation, NodeType::Junction})
    std::cout << " " << count[static_cast<int>(type)] << " " << node_type_name(type);
  std::cout << "; " << leaves << " leaves, " << cycles << " cycles\n"
            << std::fixed << std::setprecision(2) << "time: graph " << time.graph << " ms, features " << time.features
            << " ms, f_q " << time.quotient << " ms, Reeb graph " << time.reeb << " ms, region measures "
            << time.measures << " ms; the spectra's surface and its spectrum " << time.spectra_surface
            << " ms (beside them where a second thread is free)\n"
            << std::defaultfloat;
}

/// `path`, or when empty a file `name` in the temporary folder `scratch`.
std::filesystem::path or_temporary(const std::string& path, const std::filesystem::path& scratch,
                                   const std::string& name) {
  if (!path.empty()) return path;
  std::filesystem::create_directories(scratch);
  return scratch / name;
}

/// Renders the segmentation with the skeleton over it (tools/figures/render_mesh.py)
/// into the folder `scratch`, then puts the figure in place (write_file_bytes).
void render_png(const std::filesystem::path& ply, const std::filesystem::path& obj, const std::string& png,
                const std::filesystem::path& scratch) {
  const std::filesystem::path rendered = or_temporary("", scratch, "figure.png");
  const std::string command = std::string("/usr/bin/python3 '") + REEBKIT_RENDER_SCRIPT + "' '" + ply.string() + "' '" +
                              rendered.string() + "' --lines '" + obj.string() + "'";
  if (std::system(command.c_str()) != 0) throw Error(png + ": rendering failed (" + command + ")");
  write_file_bytes(png, read_file_bytes(rendered));
}

}  // namespace

int run_graph(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string mesh_path, json_path, ply_path, obj_path, png_path;
  AnalysisOptions analysis;
  bool all_components = false;
  options.add_options()("mesh", po::value(&mesh_path)->required(),
                        "mesh file (.off .obj .ply .stl)")("output,o", po::value(&json_path)->required(),
                                                           "write the graph as JSON (schema: docs/formats.md)")(
      "ply", po::value(&ply_path), "write the mesh colored by segment, with node and fq vertex properties")(
      "obj", po::value(&obj_path), "write the graph and its skeleton as OBJ lines")(
      "png", po::value(&png_path), "render the segmentation with the skeleton to a PNG (needs /usr/bin/python3)");
  add_components_option(options, all_components);
  options.add(analysis_options(analysis));
  po::positional_options_description positional;
  positional.add("mesh", 1);
  po::variables_map vm;
  if (!parse(args,
             "reeb graph MESH -o graph.json [--ply segmentation.ply] [--obj skeleton.obj] [--png figure.png] "
             "[--all-components] [analysis options]",
             options, positional, vm))
    return 0;
  check_outputs({json_path, ply_path, obj_path, png_path}, {mesh_path});

  CleanedMesh cleaned = load_for_command(mesh_path, all_components).cleaned;

  std::vector<MeshAnalysis> results;
  for (Mesh& component : cleaned.components) results.push_back(analyze_mesh(std::move(component), analysis));
  print_summary(results);

  // --png without --ply/--obj renders from temporary files, removed at the end.
  const auto scratch = std::filesystem::temp_directory_path() / ("reeb_graph_" + std::to_string(::getpid()));
  Timer attributes;  // the attributes are computed for the JSON
  write_reeb_graph_json(json_path, results);
  std::cout << "wrote " << json_path << " (attributes and JSON " << std::fixed << std::setprecision(2)
            << attributes.elapsed() << " ms)\n"
            << std::defaultfloat;
  if (!png_path.empty() || !ply_path.empty()) {
    const auto ply = or_temporary(ply_path, scratch, "segmentation.ply");
    write_segmentation_ply(ply, results);
    if (!ply_path.empty()) std::cout << "wrote " << ply_path << "\n";
    ply_path = ply.string();
  }
  if (!png_path.empty() || !obj_path.empty()) {
    const auto obj = or_temporary(obj_path, scratch, "skeleton.obj");
    write_skeleton_obj(obj, results);
    if (!obj_path.empty()) std::cout << "wrote " << obj_path << "\n";
    obj_path = obj.string();
  }
  if (!png_path.empty()) {
    render_png(ply_path, obj_path, png_path, scratch);
    std::filesystem::remove_all(scratch);
    std::cout << "wrote " << png_path << "\n";
  }
  return 0;
}

}  // namespace reebkit::cli

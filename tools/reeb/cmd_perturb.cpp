// reeb perturb MESH -o OUT [...]: a variant of a mesh for the robustness
// experiments (Tierny et al. 2006, section 5.3: invariance to rotation,
// translation and scale, robustness to pose and to sampling), and the
// correspondence of its vertices to the original's. The steps given run in
// this order: pose, decimation, remeshing, subdivision, noise, then the
// similarity (rotation, scale, translation). Each step is perturb_mesh
// (deform/perturbation.h, as experiments/robustness.cpp applies them), the
// similarity mesh/transform.h.
#include "reeb/cli.h"
#include "reebkit/deform/perturbation.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/mesh_io.h"
#include "reebkit/mesh/remeshing.h"
#include "reebkit/mesh/transform.h"

#include <cmath>
#include <iostream>
#include <sstream>

namespace reebkit::cli {

namespace {

/// "1,2,3" -> (1, 2, 3); anything else throws po::error naming the option.
Vec3 parse_triple(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  Vec3 v;
  char comma1 = 0, comma2 = 0;
  if (!(in >> v.x() >> comma1 >> v.y() >> comma2 >> v.z()) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !v.allFinite())
    throw po::error("--" + option + " takes X,Y,Z (three numbers), not '" + text + "'");
  return v;
}

/// "random" -> random_rotation(seed); "x:90", "y:-30", "1,1,0:45" -> that
/// rotation (axis x, y, z or X,Y,Z; degrees, right-handed).
Eigen::Matrix3d parse_rotation(const std::string& text, std::uint64_t seed) {
  if (text == "random") return random_rotation(seed);
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos) throw po::error("--rotate takes random or AXIS:DEGREES, not '" + text + "'");
  const std::string axis_text = text.substr(0, colon);
  Vec3 axis = axis_text == "x"   ? Vec3::UnitX()
              : axis_text == "y" ? Vec3::UnitY()
              : axis_text == "z" ? Vec3::UnitZ()
                                 : parse_triple(axis_text, "rotate");
  double degrees = 0;
  std::istringstream in(text.substr(colon + 1));
  if (!(in >> degrees) || !(in >> std::ws).eof() || !std::isfinite(degrees) || axis.norm() == 0.0)
    throw po::error("--rotate takes random or AXIS:DEGREES with a nonzero axis, not '" + text + "'");
  return Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
}

/// "MIN:MAX" -> the pose's angle range in degrees, 0 <= MIN <= MAX <= 180.
void parse_degrees(const std::string& text, PoseOptions& pose) {
  std::istringstream in(text);
  char colon = 0;
  if (!(in >> pose.min_degrees >> colon >> pose.max_degrees) || colon != ':' || !(in >> std::ws).eof() ||
      !(0.0 <= pose.min_degrees && pose.min_degrees <= pose.max_degrees && pose.max_degrees <= 180.0))
    throw po::error("--pose-degrees takes MIN:MAX, 0 <= MIN <= MAX <= 180, not '" + text + "'");
}

/// Composes one step's correspondence into the running one: vertex v of the
/// step's result stands for original[step[v]].
void compose(std::vector<Index>& original, const std::vector<Index>& step) {
  std::vector<Index> next(step.size());
  for (std::size_t v = 0; v < step.size(); ++v) next[v] = original[static_cast<std::size_t>(step[v])];
  original = std::move(next);
}

}  // namespace

int run_perturb(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string mesh_path, out_path, correspondence_path, rotate, translate, remesh_text;
  double scale = 1.0, noise = 0.0, decimate = 1.0;
  int subdivide = 0;
  std::uint64_t seed = 1, pose_seed = 0;
  PoseOptions pose;
  std::ostringstream default_degrees;
  default_degrees << pose.min_degrees << ":" << pose.max_degrees;
  std::string pose_degrees = default_degrees.str();
  options.add_options()("mesh", po::value(&mesh_path)->required(),
                        "mesh file (.off .obj .ply .stl); its largest component is perturbed")(
      "output,o", po::value(&out_path)->required(),
      "the variant (.off or .ply)")("correspondence", po::value(&correspondence_path),
                                    "the correspondence file (default: OUT with the extension .corr; docs/formats.md)")(
      "rotate", po::value(&rotate),
      "random (uniform, from --seed) or AXIS:DEGREES, AXIS = x, y, z or X,Y,Z")("scale",
                                                                                po::value(&scale)->default_value(scale),
                                                                                "uniform scale factor (> 0)")(
      "translate", po::value(&translate),
      "translation X,Y,Z")("noise", po::value(&noise)->default_value(noise),
                           "Gaussian noise along the normals, sigma as a fraction of the bounding box diagonal")(
      "decimate", po::value(&decimate)->default_value(decimate),
      "quadric edge collapse to this share of the vertices, in (0, 1]")(
      "remesh", po::value(&remesh_text),
      "a new triangulation sharing no vertex: N_VERTICES (an integer) or TARGET_EDGE (a number with a decimal point)")(
      "subdivide", po::value(&subdivide)->default_value(subdivide), "rounds of 1-to-4 midpoint subdivision")(
      "pose", po::value(&pose_seed),
      "turn up to --pose-leaves leaf components of the Reeb graph by --pose-degrees, picked by this seed "
      "(section 5.2)")("pose-leaves", po::value(&pose.leaves)->default_value(pose.leaves),
                       "how many of the four largest leaves (by area) --pose turns")(
      "pose-degrees", po::value(&pose_degrees)->default_value(pose_degrees),
      "MIN:MAX, the range of the angles --pose turns by, either way")(
      "seed", po::value(&seed)->default_value(seed), "seed of the random rotation, noise and remeshing");
  AnalysisOptions pose_graph;  // the analysis of the graph whose leaves --pose turns
  options.add(analysis_options(pose_graph));
  po::positional_options_description positional;
  positional.add("mesh", 1);
  po::variables_map vm;
  if (!parse(args,
             "reeb perturb MESH -o OUT [--rotate random|AXIS:DEG] [--scale S] [--translate X,Y,Z] [--noise SIGMA] "
             "[--decimate RATIO] [--remesh N_VERTICES|TARGET_EDGE] [--subdivide K] [--pose SEED [--pose-leaves K] "
             "[--pose-degrees MIN:MAX]] [--seed N] "
             "[analysis options]",
             options, positional, vm))
    return 0;
  if (!(scale > 0.0 && std::isfinite(scale))) throw po::error("--scale must be a finite number > 0");
  if (!(noise >= 0.0 && std::isfinite(noise))) throw po::error("--noise must be a finite number >= 0");
  if (subdivide < 0) throw po::error("--subdivide must be >= 0");
  if (pose.leaves < 0) throw po::error("--pose-leaves must be >= 0");
  parse_degrees(pose_degrees, pose);
  if (correspondence_path.empty())
    correspondence_path = std::filesystem::path(out_path).replace_extension(".corr").string();
  check_outputs({out_path, correspondence_path}, {mesh_path});
  Similarity similarity;
  similarity.scale = scale;
  if (!rotate.empty()) similarity.rotation = parse_rotation(rotate, seed);
  if (!translate.empty()) similarity.translation = parse_triple(translate, "translate");
  RemeshOptions remesh_options;
  remesh_options.seed = seed;
  if (!remesh_text.empty()) {
    const bool count = remesh_text.find_first_not_of("0123456789") == std::string::npos;
    try {
      if (count)
        remesh_options.target_vertices = static_cast<Index>(std::stol(remesh_text));
      else
        remesh_options.target_edge_length = std::stod(remesh_text);
    } catch (const std::exception&) {
      throw po::error("--remesh takes a vertex count or an edge length, not '" + remesh_text + "'");
    }
  }

  const Mesh original = std::move(load_for_command(mesh_path, false).cleaned.components.front());
  Mesh mesh = original;
  std::vector<Index> correspondence = same_vertices(original).original_vertex;
  const auto step = [&](const char* what, const Perturbation& p, const MeshAnalysis* analysis = nullptr) {
    std::vector<std::string> notes;
    MeshVariant variant = perturb_mesh(mesh, p, analysis, &notes);
    compose(correspondence, variant.original_vertex);
    if (p.kind == PerturbationKind::Pose) {  // the skipped leaves, then the turns
      for (std::size_t k = 0; k + 1 < notes.size(); ++k)
        std::cerr << "warning: " << mesh_path << ": " << notes[k] << "\n";
      std::cout << what << ": " << notes.back() << "\n";
    } else {
      std::cout << what << ": " << mesh.num_vertices() << " -> " << variant.mesh.num_vertices() << " vertices\n";
    }
    mesh = std::move(variant.mesh);
  };
  if (vm.count("pose")) {
    pose_graph.prepare_attributes = false;  // the graph alone: its leaves are what --pose turns
    const MeshAnalysis planned = analyze_mesh(original, pose_graph);
    step("pose", Perturbation{PerturbationKind::Pose, 0, {}, pose_seed, pose}, &planned);
  }
  if (decimate != 1.0) step("decimate", Perturbation{PerturbationKind::Decimate, decimate, {}, seed, {}});
  if (!remesh_text.empty()) step("remesh", Perturbation{PerturbationKind::Remesh, 0, remesh_options, seed, {}});
  if (subdivide > 0)
    step("subdivide", Perturbation{PerturbationKind::Subdivide, static_cast<double>(subdivide), {}, seed, {}});
  if (noise > 0.0) step("noise", Perturbation{PerturbationKind::Noise, noise, {}, seed, {}});
  mesh = transformed(mesh, similarity);

  write_mesh(out_path, mesh);
  std::ostringstream out;
  out << "# reeb perturb correspondence: line v (0-based, after this header) = the vertex of " << mesh_path
      << "\n# (its numbering in the file) that vertex v of " << out_path << " stands for\n";
  for (const Index v : correspondence) out << original.source_index(v) << "\n";
  write_file_bytes(correspondence_path, out.str());
  std::cout << "wrote " << out_path << " (" << mesh.num_vertices() << " vertices, " << mesh.num_triangles()
            << " triangles) and " << correspondence_path << "\n";
  return 0;
}

}  // namespace reebkit::cli

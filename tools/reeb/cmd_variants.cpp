// reeb variants INPUT... -o DIR: a collection with classes made from a few
// meshes (the embedded default collection of the demo). For every mesh it
// writes the mesh and five variants that keep what it is, each in the class
// named after it:
//   NAME.off           the mesh (cleaned, largest component)
//   NAME_rotated.off   randomly rotated, rescaled (x 0.5 .. 2) and translated
//   NAME_resampled.off the same surface sampled differently (resample_mesh)
//   NAME_posed1.off    one leaf component of the Reeb graph turned by 20..35
//                      degrees either way (random_pose, Tierny et al.
//                      2006, section 5.2)
//   NAME_posed2.off    two leaf components turned (one, the other way, when
//                      the graph has a single leaf)
//   NAME_noisy.off     vertices moved along their normals by up to 0.2 % of
//                      the bounding box diagonal (add_normal_noise)
// and DIR/variants.cla, the classes in the Princeton Shape Benchmark format
// (read_psb_classes) with the model ids reeb index gives the files. The same
// inputs and --seed give the same files.
#include "reeb/cli.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/core/error.h"
#include "reebkit/deform/pose.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/off.h"
#include "reebkit/mesh/resampling.h"
#include "reebkit/mesh/transform.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <iostream>
#include <map>
#include <random>
#include <sstream>

namespace reebkit::cli {

namespace {

// The name of a mesh's outputs and class: the stem of its file, however it
// was given (`reeb variants datasets/*.off`, a folder, /data/cat.off), so
// that every file goes straight into the output folder and a class is named
// after its mesh. Throws Error naming both meshes when two share a stem.
std::vector<std::string> output_names(const std::vector<MeshInput>& meshes) {
  std::vector<std::string> names;
  std::map<std::string, std::string> first;  // stem -> the mesh that has it
  for (const MeshInput& mesh : meshes) {
    const std::string stem = mesh.path.stem().string();
    const auto [it, added] = first.emplace(stem, mesh.path.string());
    if (!added)
      throw Error(mesh.path.string() + " and " + it->second + " would both be named '" + stem +
                  "': rename one, or make the variants of each in its own folder");
    names.push_back(stem);
  }
  return names;
}

}  // namespace

int run_variants(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::vector<std::string> inputs;
  std::string out_dir;
  std::uint64_t seed = 2006;
  options.add_options()("input", po::value(&inputs)->multitoken()->required(),
                        "mesh files, folders or list files (as reeb index)")(
      "output,o", po::value(&out_dir)->required(),
      "folder for the meshes and variants.cla (created)")("seed", po::value(&seed)->default_value(seed),
                                                          "random seed of every variant");
  po::positional_options_description positional;
  positional.add("input", -1);
  po::variables_map vm;
  if (!parse(args, "reeb variants INPUT... -o DIR [--seed S]", options, positional, vm)) return 0;

  const std::vector<MeshInput> meshes = list_mesh_inputs(inputs);
  const std::vector<std::string> names = output_names(meshes);
  const std::filesystem::path dir = output_folder(out_dir);
  std::vector<std::pair<std::string, std::vector<std::string>>> classes;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const std::string& name = names[i];
    std::mt19937_64 rng(seed + 0x9E3779B97F4A7C15ull * (i + 1));
    CleanedMesh cleaned = load_for_command(meshes[i].path.string(), false).cleaned;
    AnalysisOptions graph_alone;  // no attributes: the poses turn the graph's leaves
    graph_alone.prepare_attributes = false;
    const MeshAnalysis analysis = analyze_mesh(std::move(cleaned.components.front()), graph_alone);
    const Mesh& mesh = analysis.mesh;

    std::vector<std::pair<std::string, Mesh>> variants;
    variants.emplace_back("", mesh);
    variants.emplace_back("_rotated", transformed(mesh, random_similarity(mesh, rng)));
    variants.emplace_back("_resampled", resample_mesh(mesh, ResamplingOptions{0.2, rng()}));
    for (int turned = 1; turned <= 2; ++turned) {
      PoseOptions pose_options;
      pose_options.leaves = turned;
      RandomPose pose = random_pose(analysis, pose_options, rng);
      for (const std::string& why : pose.skipped) std::cerr << "warning: " << meshes[i].name << ": " << why << "\n";
      if (pose.turns.empty()) {
        std::cerr << "warning: " << meshes[i].name << ": no leaf to turn, no _posed" << turned << " copy\n";
        continue;
      }
      variants.emplace_back("_posed" + std::to_string(turned), std::move(pose.mesh));
    }
    variants.emplace_back("_noisy", add_normal_noise(mesh, NoiseOptions{0.002, rng()}));

    auto& [class_name, models] = classes.emplace_back(name, std::vector<std::string>{});
    for (const auto& [suffix, variant] : variants) {
      const std::filesystem::path path = dir / (name + suffix + ".off");
      if (std::filesystem::exists(path) && std::filesystem::equivalent(path, meshes[i].path))
        throw Error(path.string() + ": would overwrite an input mesh; choose another output folder");
      write_off(path, variant);
      models.push_back(name + suffix);
    }
    std::cout << class_name << ": " << models.size() << " meshes\n";
  }

  std::size_t total = 0;
  for (const auto& c : classes) total += c.second.size();
  const std::filesystem::path cla_path = dir / "variants.cla";
  std::ostringstream cla;
  cla << "PSB 1\n" << classes.size() << " " << total << "\n";
  for (const auto& [class_name, models] : classes) {
    cla << "\n" << class_name << " 0 " << models.size() << "\n";
    for (const std::string& m : models) cla << m << "\n";
  }
  write_file_bytes(cla_path, cla.str());
  std::cout << "wrote " << total << " meshes in " << classes.size() << " classes to " << dir.string() << ", classes in "
            << cla_path.string() << "\n";
  return 0;
}

}  // namespace reebkit::cli

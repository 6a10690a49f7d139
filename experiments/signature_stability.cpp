// How much the graph signature (attributes/graph_attributes.h) varies within
// a class of poses against between classes, over a folder of meshes whose
// class is the file name without its trailing digits (TOSCA: cat0 ... cat10).
//
//   build/experiments/signature_stability build/data/tosca_dev > results/signature_stability.md
#include "batch_failures.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

struct Sample {
  std::string name, label;
  std::vector<double> signature;
};

double distance(const Sample& a, const Sample& b) {
  double d = 0;
  for (int k = 0; k < reebkit::kSignatureLength; ++k) d += std::pow(a.signature[k] - b.signature[k], 2);
  return std::sqrt(d);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: signature_stability MESH_DIR\n";
    return 2;
  }
  try {
    std::vector<Sample> samples;
    BatchFailures failures("signature_stability");
    const std::vector<reebkit::MeshInput> inputs = reebkit::list_mesh_inputs({argv[1]});
    for (const reebkit::MeshInput& input : inputs) {
      const std::filesystem::path& f = input.path;
      std::string label = f.stem().string();
      while (!label.empty() && std::isdigit(static_cast<unsigned char>(label.back()))) label.pop_back();
      try {
        const auto analysis = reebkit::analyze_mesh(reebkit::load_mesh(f).components.front());
        samples.push_back({f.stem().string(), label, reebkit::compute_attributes(analysis).signature});
      } catch (const std::exception& e) {
        failures.add(e.what(), f.string());
      }
    }
    // Per class: mean distance to the same class, to the others, and how many
    // meshes have their nearest neighbour in their own class.
    std::map<std::string, std::array<double, 5>> per_class;  // within sum, n, between sum, n, nn hits
    std::map<std::string, int> sizes;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      auto& c = per_class[samples[i].label];
      ++sizes[samples[i].label];
      double best = INFINITY;
      std::size_t nearest = i;
      for (std::size_t j = 0; j < samples.size(); ++j) {
        if (i == j) continue;
        const double d = distance(samples[i], samples[j]);
        if (d < best) best = d, nearest = j;
        const bool same = samples[i].label == samples[j].label;
        c[same ? 0 : 2] += d;
        c[same ? 1 : 3] += 1;
      }
      c[4] += samples[nearest].label == samples[i].label;
    }
    std::printf(
        "# Graph signature: within-class vs between-class distances\n\n"
        "`build/experiments/signature_stability %s` (L2 distance between the %d-entry signatures; "
        "class = file name without trailing digits).\n\n"
        "| class | meshes | mean distance within | mean distance to other classes | nearest neighbour in class |\n"
        "|---|---:|---:|---:|---:|\n",
        argv[1], reebkit::kSignatureLength);
    double hits = 0;
    for (const auto& [label, c] : per_class) {
      std::printf("| %s | %d | %.3f | %.3f | %d of %d |\n", label.c_str(), sizes[label], c[1] != 0 ? c[0] / c[1] : 0.0,
                  c[3] != 0 ? c[2] / c[3] : 0.0, static_cast<int>(c[4]), sizes[label]);
      hits += c[4];
    }
    std::printf("\nNearest neighbour in the same class: %d of %zu meshes.\n", static_cast<int>(hits), samples.size());
    std::fflush(stdout);
    return failures.finish(inputs.size());
  } catch (const std::exception& e) {
    std::cerr << "signature_stability: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

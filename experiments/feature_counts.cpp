// Feature points per mesh over a classified collection (PSB .cla file), as a
// Markdown table: per class the min / median / max count and every count.
//
//   build/experiments/feature_counts ../shared/.../shrec07_watertight.cla MESH_DIR > results/shrec07_feature_counts.md
#include "batch_failures.h"
#include "reebkit/core/timer.h"
#include "reebkit/features/feature_points.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/mesh/load_mesh.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: feature_counts CLASSES.cla MESH_DIR\n";
    return 2;
  }
  try {
    const auto classes = reebkit::read_psb_classes(argv[1]);
    reebkit::Timer timer;
    std::cout << "| class | min | median | max | feature points per mesh |\n|---|---:|---:|---:|---|\n";
    BatchFailures failures("feature_counts");
    std::size_t attempted = 0;
    for (const auto& c : classes) {
      std::vector<std::size_t> counts;
      for (const auto& m : c.models) {
        ++attempted;
        try {
          const auto mesh = reebkit::load_mesh(std::filesystem::path(argv[2]) / (m + ".off")).components.front();
          counts.push_back(reebkit::extract_feature_points(mesh, reebkit::build_mesh_graph(mesh)).vertices.size());
        } catch (const std::exception& e) {
          failures.add(e.what(), m);
        }
      }
      if (counts.empty()) continue;
      auto s = counts;
      std::sort(s.begin(), s.end());
      std::cout << "| " << c.name << " | " << s.front() << " | " << s[s.size() / 2] << " | " << s.back() << " |";
      for (const std::size_t n : counts) std::cout << ' ' << n;
      std::cout << " |\n";
    }
    std::cerr << "feature_counts: " << timer.lap() / 1000.0 << " s\n";
    return failures.finish(attempted);
  } catch (const std::exception& e) {
    std::cerr << "feature_counts: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

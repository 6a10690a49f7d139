// How much the feature points and the Reeb graph of a mesh change when only
// its sampling changes (resample_mesh: 1-to-4 subdivision, edge vertices
// jittered along their edges) or when it gets a little noise
// (add_normal_noise), with Dijkstra and with fast-marching geodesics
// (FeatureOptions::geodesic), each with every persistence threshold given
// (FeatureOptions::min_persistence; default 0 only). Markdown on stdout.
//
//   build/experiments/sampling_stability [--min-persistence 0,0.01,...] [--shrec CLASSES.cla SHREC_DIR] MESH_OR_DIR... > results/sampling_stability.md
//
// Each MESH_OR_DIR is a group (a folder: its .off files; a file: grouped by
// its folder). Per mesh (largest component, analysed as `reeb graph` does):
// the original, 3 resampled copies (seeds 1-3, jitter 0.2) and 2 noisy ones
// (seeds 1-2, 0.2 % of the bounding box diagonal). With --shrec: the same
// for the first 2 meshes of every SHREC07 class, and the feature point
// counts of all its meshes per class with both methods. For the first group:
// how many local extrema f1 has on each copy with Dijkstra, with fast
// marching, and with fast marching on the copy refined twice more by plain
// midpoint subdivision (the same surface, the distance nearer convergence),
// then how many of the last two persist above each nonzero threshold.
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/core/timer.h"
#include "reebkit/features/critical_points.h"
#include "reebkit/features/persistence.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/geodesic/fast_marching.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/resampling.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace reebkit;
namespace fs = std::filesystem;

constexpr Geodesic kMethods[] = {Geodesic::Dijkstra, Geodesic::FastMarching};

// One way of computing the feature points: a geodesic method and a
// persistence threshold. Every mesh is analysed with each, method first.
struct Config {
  Geodesic geodesic = Geodesic::Dijkstra;
  double min_persistence = 0.0;

  FeatureOptions features() const {
    FeatureOptions options;
    options.geodesic = geodesic;
    options.min_persistence = min_persistence;
    return options;
  }
  std::string persistence() const {
    char text[32];
    std::snprintf(text, sizeof text, "%g", min_persistence);
    return text;
  }
};
std::vector<Config> g_configs;     // set once by main
std::vector<double> g_thresholds;  // the persistence thresholds, as given
constexpr int kResampled = 3, kNoisy = 2;
constexpr int kVariants = 1 + kResampled + kNoisy;  // original first

struct Outcome {
  std::size_t features = 0, extrema1 = 0, nodes = 0, cycles = 0;
  int unmatched = 0;  // feature points without a counterpart within epsilon (both ways; not for the original)
};

struct MeshResult {
  std::string name;
  Index vertices = 0;
  int genus = -1;
  std::vector<std::array<Outcome, kVariants>> outcome;  // [config][variant]
};

Mesh make_variant(const Mesh& mesh, int k) {
  if (k == 0) return mesh;
  if (k <= kResampled) return resample_mesh(mesh, ResamplingOptions{0.2, static_cast<std::uint64_t>(k)});
  return add_normal_noise(mesh, NoiseOptions{0.002, static_cast<std::uint64_t>(k - kResampled)});
}

// Feature points of `a` with none of `b` within `radius` on `graph`
// (fast-marching distances whichever method found them: one yardstick).
int unmatched(FastMarchingSolver& solver, const std::vector<Index>& a, const std::vector<Index>& b, double radius) {
  const DistanceField& d = solver.run(b, GeodesicOptions{radius});
  return static_cast<int>(std::count_if(a.begin(), a.end(), [&](Index v) { return !(d.distance[v] < radius); }));
}

MeshResult analyse(const std::string& name, const Mesh& mesh) {
  MeshResult r;
  r.name = name;
  r.vertices = mesh.num_vertices();
  r.genus = analyze_topology(mesh).genus;
  r.outcome.resize(g_configs.size());
  for (std::size_t m = 0; m < g_configs.size(); ++m) {
    AnalysisOptions options;
    options.features = g_configs[m].features();
    std::vector<Index> original_features;
    for (int k = 0; k < kVariants; ++k) {
      const MeshAnalysis a = analyze_mesh(make_variant(mesh, k), options);
      Outcome& o = r.outcome[m][k];
      o.features = a.features.vertices.size();
      o.extrema1 = a.features.extrema1.size();
      o.nodes = a.reeb.nodes.size();
      o.cycles = static_cast<std::size_t>(a.reeb.independent_cycles());
      // Resampling keeps the vertex ids of the original and noise keeps all
      // ids, so the original's feature points are vertices of every variant;
      // feature points on vertices added to fill holes are left out.
      std::vector<Index> mine;
      for (const Index v : a.features.vertices)
        if (v < original_vertex_count(a.mesh)) mine.push_back(v);
      if (k == 0) {
        original_features = mine;
        continue;
      }
      FastMarchingSolver solver(a.graph);
      const double radius = options.features.epsilon * a.features.diameter;
      o.unmatched = unmatched(solver, original_features, mine, radius) + unmatched(solver, mine, original_features, radius);
    }
  }
  return r;
}

std::string list(const MeshResult& r, std::size_t m, std::size_t Outcome::*field) {
  std::string s;
  for (int k = 0; k < kVariants; ++k) {
    s += std::to_string(r.outcome[m][k].*field);
    s += k == 0 || k == kResampled ? " / " : k + 1 < kVariants ? " " : "";
  }
  return s;
}

// The summary line of one configuration over a group of meshes.
void print_summary_row(const std::string& group, const std::vector<MeshResult>& results, std::size_t m) {
  int same_f[2] = {0, 0}, same_nodes[2] = {0, 0}, genus_cycles[3] = {0, 0, 0}, variants[2] = {0, 0}, closed = 0;
  double delta_f[2] = {0, 0}, unmatched[2] = {0, 0}, e1[2] = {0, 0};
  for (const MeshResult& r : results) {
    const Outcome& o0 = r.outcome[m][0];
    e1[0] += static_cast<double>(o0.extrema1);
    if (r.genus >= 0) {
      ++closed;
      genus_cycles[0] += static_cast<int>(o0.cycles) == r.genus;
    }
    for (int k = 1; k < kVariants; ++k) {
      const int kind = k <= kResampled ? 0 : 1;
      const Outcome& o = r.outcome[m][k];
      ++variants[kind];
      same_f[kind] += o.features == o0.features;
      same_nodes[kind] += o.nodes == o0.nodes;
      delta_f[kind] += std::abs(static_cast<double>(o.features) - static_cast<double>(o0.features));
      unmatched[kind] += o.unmatched;
      if (kind == 0) e1[1] += static_cast<double>(o.extrema1) / kResampled;
      if (r.genus >= 0) genus_cycles[1 + kind] += static_cast<int>(o.cycles) == r.genus;
    }
  }
  const auto n = static_cast<double>(results.size());
  std::printf("| %s | %s | %s | %zu | %d/%d, %d/%d | %.2f, %.2f | %.2f, %.2f | %d/%d, %d/%d | %d/%d, %d/%d, %d/%d | %.1f -> %.1f |\n",
              group.c_str(), geodesic_name(g_configs[m].geodesic), g_configs[m].persistence().c_str(), results.size(), same_f[0], variants[0], same_f[1], variants[1],
              delta_f[0] / variants[0], delta_f[1] / variants[1], unmatched[0] / variants[0],
              unmatched[1] / variants[1], same_nodes[0], variants[0], same_nodes[1], variants[1], genus_cycles[0],
              closed, genus_cycles[1], closed * kResampled, genus_cycles[2], closed * kNoisy, e1[0] / n, e1[1] / n);
}

void print_group(const std::string& group, const std::vector<MeshResult>& results) {
  std::printf("\n### %s\n\n"
              "Per mesh and configuration: counts for the original / resampled 1 2 3 / noisy 1 2 (extrema of f1: "
              "E1, after the threshold); `unmatched` sums, over "
              "the 5 copies, the feature points of the copy and of the original with no counterpart within "
              "epsilon = 5 %% of the diameter (fast-marching distances on the copy).\n\n"
              "| mesh | vertices | genus | geodesic | min persistence | feature points | extrema of f1 | Reeb nodes | "
              "cycles | unmatched |\n"
              "|---|---:|---:|---|---|---|---|---|---|---:|\n",
              group.c_str());
  for (const MeshResult& r : results)
    for (std::size_t m = 0; m < g_configs.size(); ++m) {
      int unmatched = 0;
      for (int k = 1; k < kVariants; ++k) unmatched += r.outcome[m][k].unmatched;
      const std::string genus = r.genus >= 0 ? std::to_string(r.genus) : "open";
      std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %d |\n", m == 0 ? r.name.c_str() : "",
                  m == 0 ? std::to_string(r.vertices).c_str() : "", m == 0 ? genus.c_str() : "",
                  geodesic_name(g_configs[m].geodesic), g_configs[m].persistence().c_str(),
                  list(r, m, &Outcome::features).c_str(),
                  list(r, m, &Outcome::extrema1).c_str(), list(r, m, &Outcome::nodes).c_str(),
                  list(r, m, &Outcome::cycles).c_str(), unmatched);
    }
}

// Local extrema of f1 = d(v_s1, .) on each copy (v_s1 of the fast-marching
// analysis of that copy), f1 from Dijkstra and from fast marching on the
// copy and from fast marching on the copy refined by 1-to-4 midpoint
// subdivision twice (16 times the triangles; vertex ids kept), restricted to
// the copy's vertices; then those of the last two that persist at least
// each nonzero threshold times max f1.
void converged_extrema(const std::string& group, const std::vector<MeshInput>& files) {
  std::string head = "| mesh | copy | dijkstra | fmm | fmm, refined x16 |", rule = "|---|---|---:|---:|---:|";
  for (const double t : g_thresholds)
    if (t > 0) {
      char text[96];
      std::snprintf(text, sizeof text, " fmm, persistence >= %g | refined, persistence >= %g |", t, t);
      head += text;
      rule += "---:|---:|";
    }
  std::printf("\n## How far fast marching is from converged distances (%s)\n\n"
              "Local extrema of f1 (one-ring, as `local_extrema`) on each mesh and its resampled copies: f1 "
              "from Dijkstra and from fast marching on the copy, and from fast marching on the copy refined "
              "twice more by midpoint subdivision (`resample_mesh` with jitter 0: the same surface, 16 times the "
              "triangles, the copy's vertices keep their ids), taken at the copy's vertices. Extrema that "
              "remain with the refined distance belong to the surface's distance function sampled at these "
              "vertices (ridges where fronts meet), not to the approximation. Then how many of the fast-marching "
              "and of the refined extrema have a persistence (`extrema_persistence` on the copy's graph) of at "
              "least each threshold times max f1.\n\n%s\n%s\n",
              group.c_str(), head.c_str(), rule.c_str());
  for (const MeshInput& file : files) {
    const Mesh mesh = load_mesh(file.path).components.front();
    for (int k = 0; k <= kResampled; ++k) {
      const Mesh copy = make_variant(mesh, k);
      const MeshGraph graph = build_mesh_graph(copy);
      FeatureOptions options;
      options.geodesic = Geodesic::FastMarching;
      const Index s1 = extract_feature_points(graph, options).source1;
      const Mesh fine = resample_mesh(resample_mesh(copy, ResamplingOptions{0.0, 1}), ResamplingOptions{0.0, 1});
      std::vector<double> converged = fast_marching(build_mesh_graph(fine), s1).distance;
      converged.resize(static_cast<std::size_t>(copy.num_vertices()));
      const DistanceField fmm = fast_marching(graph, s1);
      std::printf("| %s | %s | %zu | %zu | %zu |", k == 0 ? file.path.stem().string().c_str() : "",
                  k == 0 ? "original" : ("resampled " + std::to_string(k)).c_str(),
                  local_extrema(graph, dijkstra(graph, s1).distance).size(), local_extrema(graph, fmm.distance).size(),
                  local_extrema(graph, converged).size());
      const double fine_max = *std::max_element(converged.begin(), converged.end());
      for (const double t : g_thresholds)
        if (t > 0)
          std::printf(" %zu | %zu |", persistent_extrema(graph, fmm.distance, t * fmm.max_distance).size(),
                      persistent_extrema(graph, converged, t * fine_max).size());
      std::printf("\n");
    }
  }
}

// min / median / max and every count.
std::string counts_cell(std::vector<std::size_t> counts, bool all) {
  std::string s;
  if (all) {
    for (const std::size_t c : counts) s += (s.empty() ? "" : " ") + std::to_string(c);
    return s;
  }
  std::sort(counts.begin(), counts.end());
  return std::to_string(counts.front()) + " / " + std::to_string(counts[counts.size() / 2]) + " / " +
         std::to_string(counts.back());
}

void shrec_feature_counts(const std::vector<PsbClass>& classes, const fs::path& dir) {
  const std::size_t nc = g_configs.size();
  std::vector<std::vector<std::vector<std::size_t>>> counts(classes.size(), std::vector<std::vector<std::size_t>>(nc));
  std::vector<double> seconds(nc, 0.0);
  std::vector<std::size_t> total(nc, 0), same(nc, 0);  // feature points; meshes with config 0's count
  for (std::size_t c = 0; c < classes.size(); ++c)
    for (const std::string& model : classes[c].models) {
      const MeshGraph graph = build_mesh_graph(load_mesh(dir / (model + ".off")).components.front());
      for (std::size_t m = 0; m < nc; ++m) {
        Timer timer;
        const std::size_t n = extract_feature_points(graph, g_configs[m].features()).vertices.size();
        seconds[m] += timer.lap() / 1000.0;
        counts[c][m].push_back(n);
        total[m] += n;
        same[m] += n == counts[c][0].back();
      }
    }
  std::printf("\n## SHREC07 feature points per class\n\n"
              "Every mesh of the collection, as `experiments/feature_counts` (results/shrec07_feature_counts.md: "
              "dijkstra, min persistence 0); min / median / max per class and configuration (geodesic, min "
              "persistence), then the total over the 400 meshes, how many meshes have the count of the first "
              "configuration, and the extraction time (graph built once, files read once, one core, shared "
              "machine).\n\n| class |");
  for (const Config& config : g_configs)
    std::printf(" %s %s |", geodesic_name(config.geodesic), config.persistence().c_str());
  std::printf("\n|---|");
  for (std::size_t m = 0; m < nc; ++m) std::printf("---|");
  std::printf("\n");
  for (std::size_t c = 0; c < classes.size(); ++c) {
    std::printf("| %s |", classes[c].name.c_str());
    for (std::size_t m = 0; m < nc; ++m) std::printf(" %s |", counts_cell(counts[c][m], false).c_str());
    std::printf("\n");
  }
  const auto footer = [&](const char* name, const auto& cell) {
    std::printf("| %s |", name);
    for (std::size_t m = 0; m < nc; ++m) std::printf(" %s |", cell(m).c_str());
    std::printf("\n");
  };
  footer("feature points, all meshes", [&](std::size_t m) { return std::to_string(total[m]); });
  footer("same count as the first column", [&](std::size_t m) { return std::to_string(same[m]) + " / 400"; });
  footer("time", [&](std::size_t m) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", seconds[m]);
    return std::string(text);
  });
  std::printf("\nEvery count, in the order of the .cla file:\n\n| class | geodesic | min persistence | per mesh |\n"
              "|---|---|---|---|\n");
  for (std::size_t c = 0; c < classes.size(); ++c)
    for (std::size_t m = 0; m < nc; ++m)
      std::printf("| %s | %s | %s | %s |\n", m == 0 ? classes[c].name.c_str() : "",
                  geodesic_name(g_configs[m].geodesic), g_configs[m].persistence().c_str(),
                  counts_cell(counts[c][m], true).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  fs::path cla, shrec_dir;
  std::string thresholds = "0";
  if (args.size() >= 2 && args[0] == "--min-persistence") {
    thresholds = args[1];
    args.erase(args.begin(), args.begin() + 2);
  }
  if (args.size() >= 3 && args[0] == "--shrec") {
    cla = args[1];
    shrec_dir = args[2];
    args.erase(args.begin(), args.begin() + 3);
  }
  if (args.empty() && cla.empty()) {
    std::cerr << "usage: sampling_stability [--min-persistence T1,T2,...] [--shrec CLASSES.cla SHREC_DIR] "
                 "MESH_OR_DIR...\n";
    return 2;
  }
  try {
    for (std::size_t at = 0; at <= thresholds.size();) {
      const std::size_t comma = std::min(thresholds.find(',', at), thresholds.size());
      g_thresholds.push_back(std::stod(thresholds.substr(at, comma - at)));
      at = comma + 1;
    }
    for (const Geodesic method : kMethods)
      for (const double t : g_thresholds) g_configs.push_back({method, t});
    Timer timer;
    // Groups in argument order; files of one folder given one by one share it.
    std::vector<std::pair<std::string, std::vector<MeshResult>>> groups;
    const auto group_of = [&](const std::string& name) -> std::vector<MeshResult>& {
      for (auto& [g, results] : groups)
        if (g == name) return results;
      groups.emplace_back(name, std::vector<MeshResult>{});
      return groups.back().second;
    };
    for (const std::string& arg : args) {
      const fs::path p(arg);
      const std::string group = fs::is_directory(p) ? fs::canonical(p).filename().string()
                                                    : fs::canonical(p).parent_path().filename().string();
      for (const MeshInput& file : list_mesh_inputs({arg}))
        group_of(group).push_back(analyse(file.path.stem().string(), load_mesh(file.path).components.front()));
    }
    std::vector<PsbClass> classes;
    if (!cla.empty()) {
      classes = read_psb_classes(cla);
      auto& shrec = group_of("shrec07 (first 2 meshes of each class)");
      for (const PsbClass& c : classes)
        for (std::size_t i = 0; i < std::min<std::size_t>(2, c.models.size()); ++i)
          shrec.push_back(analyse(c.name + " " + c.models[i],
                                  load_mesh(shrec_dir / (c.models[i] + ".off")).components.front()));
    }

    std::printf("# Sampling stability: Dijkstra against fast marching, persistence thresholds\n\n"
                "`build/experiments/sampling_stability%s%s%s%s", thresholds == "0" ? "" : " --min-persistence ",
                thresholds == "0" ? "" : thresholds.c_str(), cla.empty() ? "" : " --shrec ",
                cla.empty() ? "" : (cla.string() + " " + shrec_dir.string()).c_str());
    for (const std::string& a : args) std::printf(" %s", a.c_str());
    std::printf("` (experiments/sampling_stability.cpp). Each mesh (largest component, small holes filled, "
                "epsilon = 0.05) against %d copies resampled by `resample_mesh` (1-to-4 subdivision, edge "
                "vertices jittered by up to 20 %% along their edge; seeds 1-%d) and %d noisy ones "
                "(`add_normal_noise`, 0.2 %% of the bounding box diagonal; seeds 1-%d), with the feature "
                "points and f_q computed from Dijkstra and from fast-marching distances, each with the extrema of "
                "f1 and f2 filtered by persistence (`FeatureOptions::min_persistence`, a fraction of the geodesic "
                "diameter; 0 = every local extremum, the paper's rule) at %s.\n\n",
                kResampled, kResampled, kNoisy, kNoisy, thresholds.c_str());
    std::printf("## Summary\n\n"
                "Per group and configuration, over the resampled copies, then the noisy ones: how many keep the "
                "original's number of feature points, the mean change of that number, the mean number of "
                "unmatched feature points per copy (of the copy or of the original: none of the other within "
                "epsilon), how many keep the number of Reeb graph nodes; how many graphs have genus-many "
                "cycles (closed meshes: original, resampled, noisy); the mean number of extrema of f1 in E1 (the "
                "local extrema that persist at least the threshold) on the originals and on the resampled "
                "copies.\n\n"
                "| group | geodesic | min persistence | meshes | same feature count (resampled, noisy) | mean change "
                "| unmatched per copy | same node count | cycles = genus | extrema of f1 |\n"
                "|---|---|---|---:|---|---|---|---|---|---|\n");
    std::vector<MeshResult> everything;
    for (const auto& [group, results] : groups) {
      for (std::size_t m = 0; m < g_configs.size(); ++m) print_summary_row(group, results, m);
      everything.insert(everything.end(), results.begin(), results.end());
    }
    if (groups.size() > 1)
      for (std::size_t m = 0; m < g_configs.size(); ++m) print_summary_row("all", everything, m);
    std::printf("\n## Per mesh\n");
    for (const auto& [group, results] : groups) print_group(group, results);
    if (!args.empty()) converged_extrema(groups.front().first, list_mesh_inputs({args.front()}));
    if (!classes.empty()) shrec_feature_counts(classes, shrec_dir);
    std::cerr << "sampling_stability: " << timer.lap() / 1000.0 << " s\n";
  } catch (const std::exception& e) {
    std::cerr << "sampling_stability: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

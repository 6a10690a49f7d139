// How the weights of the graph-matching cost model (matching/graph_matching.h)
// change retrieval: for a few settings, the leave-one-out nearest-neighbour
// rate and the first tier over an indexed collection with class labels,
// one factor at a time from the defaults and then a few combinations.
// The defaults of MatchingOptions are the best row of this table.
//
//   build/tools/reeb index build/data/shrec07_watertight -o shrec.h5
//         (with --classes build/data/shrec07_watertight/shrec07_watertight.cla --threads 2)
//   build/experiments/matching_weights shrec.h5 > results/matching_weights.md
#include "reebkit/core/timer.h"
#include "reebkit/matching/graph_matching.h"
#include "reebkit/retrieval/all_pairs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace {

struct Scores {
  double nearest_neighbour = 0, first_tier = 0;
};

/// Leave-one-out nearest neighbour and first tier (share of the |C| - 1
/// others of the query's class among its |C| - 1 nearest; ties by index)
/// of an n x n distance matrix.
Scores score(const std::vector<double>& distance, const std::vector<std::string>& labels) {
  const std::size_t n = labels.size();
  std::map<std::string, int> class_size;
  for (const auto& l : labels) ++class_size[l];
  Scores s;
  std::vector<std::size_t> order;
  for (std::size_t q = 0; q < n; ++q) {
    order.resize(n);
    std::iota(order.begin(), order.end(), 0);
    order.erase(order.begin() + static_cast<std::ptrdiff_t>(q));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return distance[q * n + a] < distance[q * n + b]; });
    s.nearest_neighbour += labels[order.front()] == labels[q];
    const int tier = class_size[labels[q]] - 1;
    int hits = 0;
    for (int k = 0; k < tier; ++k) hits += labels[order[static_cast<std::size_t>(k)]] == labels[q];
    s.first_tier += tier > 0 ? static_cast<double>(hits) / tier : 0.0;
  }
  s.nearest_neighbour /= static_cast<double>(n);
  s.first_tier /= static_cast<double>(n);
  return s;
}

struct Setting {
  std::string change;
  std::function<void(reebkit::MatchingOptions&)> apply;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: matching_weights COLLECTION.h5 (indexed with --classes)\n");
    return 2;
  }
  try {
    const reebkit::CollectionReader reader(argv[1]);
    std::vector<reebkit::CollectionEntry> entries;
    std::vector<std::string> labels;
    std::vector<std::vector<double>> signatures;
    for (std::int64_t i = 0; i < reader.size(); ++i) {
      reebkit::CollectionEntry entry = reader.entry(i);
      if (!entry.ok) continue;
      if (entry.class_label.empty()) throw std::runtime_error(entry.name + ": no class label (index with --classes)");
      labels.push_back(entry.class_label);
      signatures.push_back(entry.signature);
      entries.push_back(std::move(entry));
    }
    const reebkit::MatchingOptions defaults;
    std::printf("# Graph matching weights: leave-one-out retrieval\n\n"
                "`build/experiments/matching_weights %s`: %zu graphs. Each row changes the defaults "
                "(attribute %.2g, structure %.2g, edge %.2g, unmatched %.2g, min node weight %.2g, "
                "%d refinement rounds) as stated; NN = nearest neighbour in the query's class, FT = first tier "
                "(query excluded, ties by index).\n\n"
                "| setting | NN | FT | all pairs (s) |\n|---|---:|---:|---:|\n",
                argv[1], entries.size(), defaults.attribute_weight, defaults.structure_weight, defaults.edge_weight,
                defaults.unmatched_cost, defaults.min_node_weight, defaults.refine_rounds);
    // For context: the 32-entry signature alone (L2), no matching.
    {
      const std::size_t n = entries.size();
      std::vector<double> d(n * n, 0.0);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
          for (std::size_t k = 0; k < signatures[i].size(); ++k)
            d[i * n + j] += std::pow(signatures[i][k] - signatures[j][k], 2);
      const Scores s = score(d, labels);
      std::printf("| signature L2 only (no matching) | %.3f | %.3f | - |\n", s.nearest_neighbour, s.first_tier);
    }
    using O = reebkit::MatchingOptions;
    const std::vector<Setting> settings = {
        {"**defaults**", [](O&) {}},
        {"attribute 0 (structure and edges only)", [](O& o) { o.attribute_weight = 0; }},
        {"attribute 1", [](O& o) { o.attribute_weight = 1; }},
        {"attribute 2", [](O& o) { o.attribute_weight = 2; }},
        {"attribute 8", [](O& o) { o.attribute_weight = 8; }},
        {"structure 0", [](O& o) { o.structure_weight = 0; }},
        {"structure 0.5", [](O& o) { o.structure_weight = 0.5; }},
        {"structure 2", [](O& o) { o.structure_weight = 2; }},
        {"edge 0, no refinement", [](O& o) { o.edge_weight = 0, o.refine_rounds = 0; }},
        {"no refinement (edge term only scored)", [](O& o) { o.refine_rounds = 0; }},
        {"edge 0.1", [](O& o) { o.edge_weight = 0.1; }},
        {"edge 0.5", [](O& o) { o.edge_weight = 0.5; }},
        {"edge 1", [](O& o) { o.edge_weight = 1; }},
        {"edge 0.25, 4 rounds", [](O& o) { o.refine_rounds = 4; }},
        {"unmatched 0.25", [](O& o) { o.unmatched_cost = 0.25; }},
        {"unmatched 1", [](O& o) { o.unmatched_cost = 1; }},
        {"unmatched 2", [](O& o) { o.unmatched_cost = 2; }},
        {"min node weight 0", [](O& o) { o.min_node_weight = 0; }},
        {"min node weight 0.05", [](O& o) { o.min_node_weight = 0.05; }},
        {"first defaults: attribute 1, edge 0.5", [](O& o) { o.attribute_weight = 1, o.edge_weight = 0.5; }},
    };
    for (const Setting& setting : settings) {
      reebkit::AllPairsOptions options;
      setting.apply(options.matching);
      reebkit::Timer timer;
      const std::vector<double> d = reebkit::all_pairs_distances(entries, options).values;
      const double seconds = timer.lap() / 1000.0;
      const Scores s = score(d, labels);
      std::printf("| %s | %.3f | %.3f | %.2f |\n", setting.change.c_str(), s.nearest_neighbour, s.first_tier, seconds);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "matching_weights: %s\n", e.what());
    return 1;
  }
  return 0;
}

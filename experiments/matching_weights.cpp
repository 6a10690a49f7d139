// How the weights of the graph-matching cost model (matching/graph_matching.h)
// change retrieval: for a few settings, the leave-one-out nearest-neighbour
// rate and the first tier over an indexed collection with class labels,
// one factor at a time from the defaults, over all graphs and over each half
// of the classes alone, and a split-half check (the best setting on one half,
// scored on the other). The defaults of MatchingOptions are near the best
// rows of this table.
//
//   experiments/shrec07_retrieval.sh build   (indexes build/shrec07_retrieval/shrec07.h5)
//   build/experiments/matching_weights build/shrec07_retrieval/shrec07.h5 > results/matching_weights.md
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
/// of an n x n distance matrix, over the sub-collection `rows` (queries and
/// results both restricted to it).
Scores score(const std::vector<double>& distance, const std::vector<std::string>& labels,
             const std::vector<std::size_t>& rows) {
  const std::size_t n = labels.size();
  std::map<std::string, int> class_size;
  for (const std::size_t r : rows) ++class_size[labels[r]];
  Scores s;
  std::vector<std::size_t> order;
  for (const std::size_t q : rows) {
    order.clear();
    for (const std::size_t r : rows)
      if (r != q) order.push_back(r);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return distance[q * n + a] < distance[q * n + b]; });
    s.nearest_neighbour += labels[order.front()] == labels[q];
    const int tier = class_size[labels[q]] - 1;
    int hits = 0;
    for (int k = 0; k < tier; ++k) hits += labels[order[static_cast<std::size_t>(k)]] == labels[q];
    s.first_tier += tier > 0 ? static_cast<double>(hits) / tier : 0.0;
  }
  s.nearest_neighbour /= static_cast<double>(rows.size());
  s.first_tier /= static_cast<double>(rows.size());
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
    std::vector<reebkit::GraphRecord> entries;
    std::vector<std::string> labels;
    std::vector<std::vector<double>> signatures;
    for (std::int64_t i = 0; i < reader.size(); ++i) {
      reebkit::GraphRecord entry = reader.entry(i);
      if (!entry.ok) continue;
      if (entry.class_label.empty()) throw std::runtime_error(entry.name + ": no class label (index with --classes)");
      labels.push_back(entry.class_label);
      signatures.push_back(entry.signature);
      entries.push_back(std::move(entry));
    }
    // The two halves of the classes (in order of first appearance): a
    // setting chosen on one half is checked on the other, where it was not
    // tuned.
    std::vector<std::string> class_order;
    for (const auto& l : labels)
      if (std::find(class_order.begin(), class_order.end(), l) == class_order.end()) class_order.push_back(l);
    std::vector<std::size_t> all(labels.size()), half_a, half_b;
    std::iota(all.begin(), all.end(), 0);
    for (const std::size_t r : all) {
      const auto position = std::find(class_order.begin(), class_order.end(), labels[r]) - class_order.begin();
      (2 * static_cast<std::size_t>(position) < class_order.size() ? half_a : half_b).push_back(r);
    }
    const reebkit::MatchingOptions defaults;
    std::printf("# Graph matching weights: leave-one-out retrieval\n\n"
                "`build/experiments/matching_weights %s`: %zu graphs. Each row changes the defaults "
                "(attribute %.2g, structure %.2g, edge %.2g, profile %.2g, shape %.2g, global D2 %.2g, "
                "unmatched %.2g, min node weight %.2g, %d refinement rounds) as stated; NN = nearest neighbour in "
                "the query's class, FT = first tier (query excluded, ties by index), over all graphs and over each "
                "half of the classes alone (A: the first %zu classes of the .cla, B: the others).\n\n"
                "| setting | NN | FT | NN A | FT A | NN B | FT B | all pairs (s) |\n"
                "|---|---:|---:|---:|---:|---:|---:|---:|\n",
                argv[1], entries.size(), defaults.attribute_weight, defaults.structure_weight, defaults.edge_weight,
                defaults.profile_weight, defaults.shape_weight, defaults.global_shape_weight,
                defaults.unmatched_cost, defaults.min_node_weight, defaults.refine_rounds, (class_order.size() + 1) / 2);
    const auto print_row = [&](const std::string& name, const std::vector<double>& d, const std::string& seconds) {
      const Scores s = score(d, labels, all), sa = score(d, labels, half_a), sb = score(d, labels, half_b);
      std::printf("| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %s |\n", name.c_str(), s.nearest_neighbour,
                  s.first_tier, sa.nearest_neighbour, sa.first_tier, sb.nearest_neighbour, sb.first_tier,
                  seconds.c_str());
      std::fflush(stdout);
      return std::pair{sa, sb};
    };
    // For context: the signature alone (L2), no matching.
    {
      const std::size_t n = entries.size();
      std::vector<double> d(n * n, 0.0);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
          for (std::size_t k = 0; k < signatures[i].size(); ++k)
            d[i * n + j] += std::pow(signatures[i][k] - signatures[j][k], 2);
      print_row("signature L2 only (no matching)", d, "-");
    }
    using O = reebkit::MatchingOptions;
    const std::vector<Setting> settings = {
        {"**defaults**", [](O&) {}},
        {"session 1 model: no profile, shape or global D2, unmatched 0.5",
         [](O& o) { o.profile_weight = 0, o.shape_weight = 0, o.global_shape_weight = 0, o.unmatched_cost = 0.5; }},
        {"profile 0", [](O& o) { o.profile_weight = 0; }},
        {"profile 16", [](O& o) { o.profile_weight = 16; }},
        {"profile 64", [](O& o) { o.profile_weight = 64; }},
        {"shape 0", [](O& o) { o.shape_weight = 0; }},
        {"shape 2", [](O& o) { o.shape_weight = 2; }},
        {"shape 8", [](O& o) { o.shape_weight = 8; }},
        {"global 0", [](O& o) { o.global_shape_weight = 0; }},
        {"global 0.8", [](O& o) { o.global_shape_weight = 0.8; }},
        {"global 3.2", [](O& o) { o.global_shape_weight = 3.2; }},
        {"unmatched 0.5", [](O& o) { o.unmatched_cost = 0.5; }},
        {"unmatched 0.75", [](O& o) { o.unmatched_cost = 0.75; }},
        {"unmatched 1.5", [](O& o) { o.unmatched_cost = 1.5; }},
        {"attribute 2", [](O& o) { o.attribute_weight = 2; }},
        {"attribute 8", [](O& o) { o.attribute_weight = 8; }},
        {"structure 0", [](O& o) { o.structure_weight = 0; }},
        {"structure 2", [](O& o) { o.structure_weight = 2; }},
        {"edge 0, no refinement", [](O& o) { o.edge_weight = 0, o.refine_rounds = 0; }},
        {"edge 0.5", [](O& o) { o.edge_weight = 0.5; }},
        {"min node weight 0.05", [](O& o) { o.min_node_weight = 0.05; }},
    };
    // The setting with the best NN + FT on each half, and its scores on the other.
    std::string best_on_a, best_on_b;
    double best_a = -1, best_b = -1;
    Scores b_of_best_a, a_of_best_b;
    for (const Setting& setting : settings) {
      reebkit::AllPairsOptions options;
      setting.apply(options.matching);
      reebkit::Timer timer;
      const std::vector<double> d = reebkit::all_pairs_distances(entries, options).values;
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.2f", timer.lap() / 1000.0);
      const auto [sa, sb] = print_row(setting.change, d, seconds);
      if (sa.nearest_neighbour + sa.first_tier > best_a)
        best_a = sa.nearest_neighbour + sa.first_tier, best_on_a = setting.change, b_of_best_a = sb;
      if (sb.nearest_neighbour + sb.first_tier > best_b)
        best_b = sb.nearest_neighbour + sb.first_tier, best_on_b = setting.change, a_of_best_b = sa;
    }
    std::printf("\nSplit-half check: the best setting on half A (%s) scores NN %.3f, FT %.3f on half B; the best on "
                "half B (%s) scores NN %.3f, FT %.3f on half A.\n",
                best_on_a.c_str(), b_of_best_a.nearest_neighbour, b_of_best_a.first_tier, best_on_b.c_str(),
                a_of_best_b.nearest_neighbour, a_of_best_b.first_tier);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "matching_weights: %s\n", e.what());
    return 1;
  }
  return 0;
}

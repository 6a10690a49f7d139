// How the weights of the graph-matching cost model (matching/graph_matching.h)
// change retrieval on two indexed collections with class labels, and which
// weights to choose without tuning on the collection that reports them:
//  1. one factor at a time from the defaults, scored on both collections;
//  2. a grid over the weights of the pose-dependent terms (Euclidean shape
//     histograms of the regions, whole-surface D2), of the pose-invariant
//     ones (geodesic histograms of the regions and of the whole surface) and
//     over the deletion cost;
//  3. cross-validation across the collections: the grid setting with the best
//     score (mean of NN, FT and DCG) on one collection, reported on the
//     other, and the reverse; and the setting with the smallest sum of its
//     two ranks (by score on each collection; ranks, because the scores of
//     the two collections spread over different ranges) among those that
//     keep NN and FT on a third, guard, collection (when given) at least at
//     the previous defaults' (no regression there), which is
//     MatchingOptions' default.
// NN, FT and DCG are the PSB measures of `reeb eval` (evaluation/
// retrieval_metrics.h) on the float matrix `reeb distances` writes, rows in
// the order of the .cla file the collection was indexed with.
//
//   experiments/shrec07_retrieval.sh build   (indexes build/shrec07_retrieval/shrec07.h5)
//   build/tools/reeb index build/data/tosca_dev -o build/tosca.h5 --classes build/tosca_dev.cla
//   build/tools/reeb variants datasets -o build/variants   (the demo's variants collection)
//   build/tools/reeb index build/variants -o build/variants.h5 --classes build/variants/variants.cla
//   build/experiments/matching_weights build/shrec07_retrieval/shrec07.h5 build/tosca.h5 build/variants.h5
//       > results/matching_weights.md
#include "reebkit/core/timer.h"
#include "reebkit/evaluation/retrieval_metrics.h"
#include "reebkit/matching/graph_matching.h"
#include "reebkit/retrieval/all_pairs.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace {

using Options = reebkit::MatchingOptions;

/// One collection: its graphs in the order of its .cla file, their classes.
struct Benchmark {
  std::string path, name;
  std::vector<reebkit::GraphRecord> entries;
  reebkit::ModelClasses classes;
};

Benchmark load(const std::string& path) {
  const reebkit::CollectionReader reader(path);
  const std::vector<reebkit::PsbClass>& cla = reader.provenance().classes;
  if (cla.empty()) throw std::runtime_error(path + ": no classes (index with --classes)");
  Benchmark b;
  b.path = path;
  b.name = std::filesystem::path(path).stem().string();
  b.classes = reebkit::model_classes(cla);
  for (const std::int64_t row : reebkit::matrix_rows(reader, cla)) b.entries.push_back(reader.entry(row));
  return b;
}

struct Scores {
  double nn = 0, ft = 0, dcg = 0;
  double mean() const { return (nn + ft + dcg) / 3.0; }
};

/// The micro-averaged measures of the all-pairs distances under `options`.
Scores score(const Benchmark& b, const Options& options) {
  reebkit::AllPairsOptions all_pairs;
  all_pairs.matching = options;
  const std::vector<double> d = reebkit::all_pairs_distances(b.entries, all_pairs).values;
  const auto n = static_cast<Eigen::Index>(b.entries.size());
  reebkit::DistanceMatrix matrix(n, n);
  for (Eigen::Index i = 0; i < n * n; ++i) matrix.data()[i] = static_cast<float>(d[static_cast<std::size_t>(i)]);
  const reebkit::RetrievalScores s = reebkit::evaluate_retrieval(matrix, b.classes).micro;
  return {s.nearest_neighbor, s.first_tier, s.dcg};
}

/// The defaults before the pose-invariant terms (chosen on SHREC07 alone).
void previous_defaults(Options& o) {
  o.shape_weight = 4, o.global_shape_weight = 1.6, o.unmatched_cost = 1;
  o.geodesic_shape_weight = o.global_geodesic_weight = 0;
}

struct Setting {
  std::string change;
  std::function<void(Options&)> apply;
};

/// The weights that differ between settings, as the table shows them.
std::string describe(const Options& o) {
  char text[200];
  std::snprintf(text, sizeof text, "shape %g, geodesic shape %g, global D2 %g, global geodesic %g, unmatched %g",
                o.shape_weight, o.geodesic_shape_weight, o.global_shape_weight, o.global_geodesic_weight,
                o.unmatched_cost);
  return text;
}

/// Rank of each value among `values`, 1 for the largest, ties at their mean rank.
std::vector<double> ranks(const std::vector<double>& values) {
  std::vector<double> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    double above = 0, equal = 0;
    for (const double v : values) above += v > values[i], equal += v == values[i];
    out[i] = above + (equal + 1) / 2;
  }
  return out;
}

void print_scores(const std::string& name, const std::array<Scores, 2>& s) {
  std::printf("| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", name.c_str(), s[0].nn, s[0].ft, s[0].dcg, s[1].nn,
              s[1].ft, s[1].dcg);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: matching_weights A.h5 B.h5 [GUARD.h5] (collections indexed with --classes)\n");
    return 2;
  }
  try {
    const std::array<Benchmark, 2> bench = {load(argv[1]), load(argv[2])};
    const std::optional<Benchmark> guard = argc == 4 ? std::optional<Benchmark>(load(argv[3])) : std::nullopt;
    const Options defaults;
    const auto both = [&](const Options& o) { return std::array<Scores, 2>{score(bench[0], o), score(bench[1], o)}; };
    std::printf("# Graph matching weights: cross-validated between two collections\n\n"
                "`build/experiments/matching_weights %s %s%s%s`: %zu and %zu graphs%s%s%s. NN, FT, DCG: the PSB "
                "measures of `reeb eval` (micro averages) on the all-pairs distances.\n\n",
                argv[1], argv[2], guard ? " " : "", guard ? argv[3] : "", bench[0].entries.size(),
                bench[1].entries.size(), guard ? ", and the guard collection's " : "",
                guard ? std::to_string(guard->entries.size()).c_str() : "", guard ? " graphs" : "");
    const std::string header = "| setting | NN " + bench[0].name + " | FT | DCG | NN " + bench[1].name +
                               " | FT | DCG |\n|---|---:|---:|---:|---:|---:|---:|\n";

    std::printf("## One factor at a time\n\nEach row changes the defaults (attribute %g, structure %g, edge %g, "
                "profile %g, %s, min node weight %g, %d refinement rounds) as stated.\n\n%s",
                defaults.attribute_weight, defaults.structure_weight, defaults.edge_weight, defaults.profile_weight,
                describe(defaults).c_str(), defaults.min_node_weight, defaults.refine_rounds, header.c_str());
    const std::vector<Setting> factors = {
        {"**defaults**", [](Options&) {}},
        {"the previous defaults, pose-dependent terms only: shape 4, global D2 1.6, no geodesic shape or "
         "global geodesic, unmatched 1",
         previous_defaults},
        {"geodesic shape 0 (no pose-invariant term)", [](Options& o) { o.geodesic_shape_weight = 0; }},
        {"geodesic shape 4", [](Options& o) { o.geodesic_shape_weight = 4; }},
        {"shape 0 (no Euclidean term in the node costs)", [](Options& o) { o.shape_weight = 0; }},
        {"shape 4", [](Options& o) { o.shape_weight = 4; }},
        {"global D2 0 (no Euclidean whole-surface term)", [](Options& o) { o.global_shape_weight = 0; }},
        {"global D2 0.8", [](Options& o) { o.global_shape_weight = 0.8; }},
        {"global geodesic 0.8", [](Options& o) { o.global_geodesic_weight = 0.8; }},
        {"profile 16", [](Options& o) { o.profile_weight = 16; }},
        {"profile 64", [](Options& o) { o.profile_weight = 64; }},
        {"unmatched 1", [](Options& o) { o.unmatched_cost = 1; }},
        {"unmatched 2", [](Options& o) { o.unmatched_cost = 2; }},
        {"attribute 2", [](Options& o) { o.attribute_weight = 2; }},
        {"attribute 8", [](Options& o) { o.attribute_weight = 8; }},
        {"structure 0", [](Options& o) { o.structure_weight = 0; }},
        {"structure 2", [](Options& o) { o.structure_weight = 2; }},
        {"edge 0, no refinement", [](Options& o) { o.edge_weight = 0, o.refine_rounds = 0; }},
        {"min node weight 0.05", [](Options& o) { o.min_node_weight = 0.05; }},
    };
    for (const Setting& f : factors) {
      Options o = defaults;
      f.apply(o);
      print_scores(f.change, both(o));
    }

    // The grid over the pose-related weights, the other weights at their defaults.
    std::vector<Options> grid;
    for (const double shape : {0.0, 2.0, 4.0})
      for (const double geodesic_shape : {0.0, 1.0, 2.0, 4.0})
        for (const double global_d2 : {0.0, 0.8, 1.6})
          for (const double global_geodesic : {0.0, 0.8, 1.6})
            for (const double unmatched : {1.0, 1.5}) {
              Options o = defaults;
              o.shape_weight = shape, o.geodesic_shape_weight = geodesic_shape;
              o.global_shape_weight = global_d2, o.global_geodesic_weight = global_geodesic;
              o.unmatched_cost = unmatched;
              grid.push_back(o);
            }
    std::vector<std::array<Scores, 2>> scores;
    reebkit::Timer timer;
    for (const Options& o : grid) scores.push_back(both(o));
    const double seconds = timer.lap() / 1000.0;
    const auto best_by = [&](const std::function<double(const std::array<Scores, 2>&)>& objective) {
      std::size_t best = 0;
      for (std::size_t k = 1; k < grid.size(); ++k)  // first best in grid order on ties
        if (objective(scores[k]) > objective(scores[best])) best = k;
      return best;
    };
    const std::size_t on_a = best_by([](const auto& s) { return s[0].mean(); });
    const std::size_t on_b = best_by([](const auto& s) { return s[1].mean(); });
    std::array<std::vector<double>, 2> rank;
    for (std::size_t c = 0; c < 2; ++c) {
      std::vector<double> mean;
      for (const auto& s : scores) mean.push_back(s[c].mean());
      rank[c] = ranks(mean);
    }
    const auto rank_sum = [&](std::size_t k) { return rank[0][k] + rank[1][k]; };
    // The guard: NN and FT on the third collection not below the previous defaults'.
    std::vector<char> kept(grid.size(), 1);
    std::string guard_text;
    if (guard) {
      Options previous = defaults;
      previous_defaults(previous);
      const Scores floor = score(*guard, previous);
      for (std::size_t k = 0; k < grid.size(); ++k) {
        const Scores s = score(*guard, grid[k]);
        kept[k] = s.nn >= floor.nn && s.ft >= floor.ft;
      }
      guard_text = " among the " + std::to_string(std::count(kept.begin(), kept.end(), 1)) +
                   " settings that keep NN and FT on " + guard->name + " (" + guard->path +
                   ") at least at the previous defaults' (" + std::to_string(floor.nn).substr(0, 5) + ", " +
                   std::to_string(floor.ft).substr(0, 5) + ")";
    }
    std::size_t on_both = grid.size();
    for (std::size_t k = 0; k < grid.size(); ++k)
      if (kept[k] && (on_both == grid.size() || rank_sum(k) < rank_sum(on_both))) on_both = k;
    if (on_both == grid.size()) throw std::runtime_error("no grid setting passes the guard collection");
    std::printf("\n## Grid and cross-validation\n\n%zu settings (shape 0, 2, 4 x geodesic shape 0, 1, 2, 4 x global D2 0, "
                "0.8, 1.6 x global geodesic 0, 0.8, 1.6 x unmatched 1, 1.5; the other weights at their defaults), "
                "%.0f s for both collections. Score: the mean of NN, FT and DCG.\n\n%s",
                grid.size(), seconds, header.c_str());
    print_scores("best on " + bench[0].name + " (" + describe(grid[on_a]) + ")", scores[on_a]);
    print_scores("best on " + bench[1].name + " (" + describe(grid[on_b]) + ")", scores[on_b]);
    print_scores("smallest rank sum over both" + guard_text + " (" + describe(grid[on_both]) + ")", scores[on_both]);
    std::printf("\nCross-validation: chosen on %s, %s scores NN %.3f, FT %.3f, DCG %.3f (its best in the grid: "
                "%.3f, %.3f, %.3f); chosen on %s, %s scores NN %.3f, FT %.3f, DCG %.3f (its best: %.3f, %.3f, %.3f).\n",
                bench[0].name.c_str(), bench[1].name.c_str(), scores[on_a][1].nn, scores[on_a][1].ft,
                scores[on_a][1].dcg, scores[on_b][1].nn, scores[on_b][1].ft, scores[on_b][1].dcg,
                bench[1].name.c_str(), bench[0].name.c_str(), scores[on_b][0].nn, scores[on_b][0].ft,
                scores[on_b][0].dcg, scores[on_a][0].nn, scores[on_a][0].ft, scores[on_a][0].dcg);

    // The ten best settings over both, for how flat the optimum is.
    std::vector<std::size_t> order(grid.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return rank_sum(x) < rank_sum(y); });
    std::printf("\nThe ten grid settings with the smallest rank sums:\n\n%s", header.c_str());
    for (std::size_t k = 0; k < std::min<std::size_t>(10, order.size()); ++k)
      print_scores(describe(grid[order[k]]), scores[order[k]]);
    std::printf("\n<details><summary>The whole grid, in grid order</summary>\n\n%s", header.c_str());
    for (std::size_t k = 0; k < grid.size(); ++k) print_scores(describe(grid[k]), scores[k]);
    std::printf("\n</details>\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "matching_weights: %s\n", e.what());
    return 1;
  }
  return 0;
}

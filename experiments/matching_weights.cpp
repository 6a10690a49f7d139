// How the weights of the graph-matching cost model (matching/graph_matching.h)
// change retrieval on indexed collections with class labels, and which
// weights to choose without tuning on the collections that report them:
//  1. one factor at a time from the defaults, scored on every collection;
//  2. a grid over the weights of the intrinsic terms (the regions' and the
//     whole surface's Laplace-Beltrami spectra, the regions' geodesic
//     histograms and radius profiles) and the deletion cost, the Euclidean
//     terms off (a default cost unchanged by bending);
//  3. the choice: the grid setting whose worst rank on the --choose
//     collections is the best (ranks by the mean of NN, FT and DCG, because
//     the scores of the collections spread over different ranges; the worst
//     rather than the sum, so that no single choosing collection can carry
//     the choice; ties by the sum of the ranks), among those
//     that keep NN and FT on the --guard collection (when given) at least at
//     the current defaults'; it is reported on the --report collections,
//     which played no part in it, next to the setting best on each choosing
//     collection alone.
// NN, FT and DCG are the PSB measures of `reeb eval` (evaluation/
// retrieval_metrics.h) on the float matrix `reeb distances` writes, rows in
// the order of the .cla file the collection was indexed with. Commands:
// results/matching_weights.md.
#include "reebkit/core/timer.h"
#include "reebkit/evaluation/retrieval_metrics.h"
#include "reebkit/matching/graph_matching.h"
#include "reebkit/retrieval/all_pairs.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
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

struct Setting {
  std::string change;
  std::function<void(Options&)> apply;
};

/// Every term's weight 0, for a setting that turns one term on alone.
void without_terms(Options& o) {
  o.attribute_weight = o.structure_weight = o.edge_weight = o.profile_weight = o.shape_weight = 0;
  o.geodesic_shape_weight = o.global_shape_weight = o.global_geodesic_weight = o.spectrum_weight = 0;
  o.global_spectrum_weight = o.global_heat_weight = 0;
}

/// The weights that differ between settings, as the tables show them.
std::string describe(const Options& o) {
  char text[300];
  std::snprintf(text, sizeof text,
                "spectrum %g, global spectrum %g (%d eigenvalues, scale %g), global heat %g (scale %g), geodesic "
                "shape %g, profile %g, unmatched %g, shape %g, global D2 %g",
                o.spectrum_weight, o.global_spectrum_weight, o.global_spectrum_eigenvalues, o.global_spectrum_scale,
                o.global_heat_weight, o.global_heat_scale, o.geodesic_shape_weight, o.profile_weight, o.unmatched_cost,
                o.shape_weight, o.global_shape_weight);
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

void print_row(const std::string& name, const std::vector<Scores>& s) {
  std::printf("| %s |", name.c_str());
  for (const Scores& x : s) std::printf(" %.3f | %.3f | %.3f |", x.nn, x.ft, x.dcg);
  std::printf("\n");
  std::fflush(stdout);
}

std::string header(const std::vector<const Benchmark*>& collections) {
  std::string h = "| setting |", rule = "|---|";
  for (const Benchmark* b : collections) h += " NN " + b->name + " | FT | DCG |", rule += "---:|---:|---:|";
  return h + "\n" + rule + "\n";
}

/// Settings scored on the choosing collections, ranked, checked against the
/// guard (NN and FT at least `floor`), and the one chosen: the smallest
/// worst rank among those the guard keeps, then the smallest sum of ranks
/// (the first on ties).
struct Choice {
  std::vector<std::vector<Scores>> scores;  ///< per setting, per choosing collection
  std::vector<double> worst_rank, rank_sum;
  /// Setting a before setting b in the order of the choice.
  bool before(std::size_t a, std::size_t b) const {
    return std::make_pair(worst_rank[a], rank_sum[a]) < std::make_pair(worst_rank[b], rank_sum[b]);
  }
  std::vector<char> kept;
  /// Per setting: it meets every aim. `aimed`: some setting kept does, and
  /// the choice is among those.
  std::vector<char> meets;
  bool aimed = false;
  std::size_t chosen = 0;
  /// Why setting k cannot be chosen, as the tables say it; "" if it can.
  std::string note(std::size_t k) const {
    return !kept[k] ? " (fails the guard)" : aimed && !meets[k] ? " (misses the aims)" : "";
  }
};

/// An aim on a choosing collection (--aim NAME:NN,FT,DCG): its NN, FT and
/// DCG at least these.
struct Aim {
  std::string name;
  Scores floor;
};

Choice choose_among(const std::vector<Options>& settings, const std::vector<const Benchmark*>& choosing,
                    const std::optional<Benchmark>& guard, const std::optional<Scores>& floor,
                    const std::vector<Aim>& aims) {
  Choice c;
  for (const Options& o : settings) {
    std::vector<Scores> s;
    for (const Benchmark* b : choosing) s.push_back(score(*b, o));
    c.scores.push_back(s);
  }
  c.rank_sum.assign(settings.size(), 0.0);
  c.worst_rank.assign(settings.size(), 0.0);
  for (std::size_t b = 0; b < choosing.size(); ++b) {
    std::vector<double> mean;
    for (const auto& s : c.scores) mean.push_back(s[b].mean());
    const std::vector<double> r = ranks(mean);
    for (std::size_t k = 0; k < settings.size(); ++k) {
      c.rank_sum[k] += r[k];
      c.worst_rank[k] = std::max(c.worst_rank[k], r[k]);
    }
  }
  c.kept.assign(settings.size(), 1);
  if (guard)
    for (std::size_t k = 0; k < settings.size(); ++k) {
      const Scores s = score(*guard, settings[k]);
      c.kept[k] = s.nn >= floor->nn && s.ft >= floor->ft;
    }
  c.meets.assign(settings.size(), 1);
  for (const Aim& aim : aims)
    for (std::size_t b = 0; b < choosing.size(); ++b)
      if (choosing[b]->name == aim.name)
        for (std::size_t k = 0; k < settings.size(); ++k) {
          const Scores& s = c.scores[k][b];
          c.meets[k] &= s.nn >= aim.floor.nn && s.ft >= aim.floor.ft && s.dcg >= aim.floor.dcg;
        }
  for (std::size_t k = 0; k < settings.size(); ++k) c.aimed |= c.kept[k] && c.meets[k];
  c.chosen = settings.size();
  for (std::size_t k = 0; k < settings.size(); ++k)
    if (c.kept[k] && (c.meets[k] || !c.aimed) && (c.chosen == settings.size() || c.before(k, c.chosen))) c.chosen = k;
  if (c.chosen == settings.size()) throw std::runtime_error("no setting passes the guard collection");
  return c;
}

int usage() {
  std::fprintf(stderr,
               "usage: matching_weights --choose A.h5 [B.h5 ...] [--report C.h5 ...] [--guard G.h5]\n"
               "       [--aim NAME:NN,FT,DCG ...]\n"
               "(collections indexed with --classes; NAME: a choosing collection's file name without .h5)\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> choose_paths, report_paths, guard_paths, aim_texts;
  std::vector<std::string>* list = nullptr;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--choose"))
      list = &choose_paths;
    else if (!std::strcmp(argv[i], "--aim"))
      list = &aim_texts;
    else if (!std::strcmp(argv[i], "--report"))
      list = &report_paths;
    else if (!std::strcmp(argv[i], "--guard"))
      list = &guard_paths;
    else if (list)
      list->push_back(argv[i]);
    else
      return usage();
  }
  if (choose_paths.empty() || guard_paths.size() > 1) return usage();
  std::vector<Aim> aims;
  for (const std::string& text : aim_texts) {
    Aim aim;
    char name[200];
    if (std::sscanf(text.c_str(), "%199[^:]:%lf,%lf,%lf", name, &aim.floor.nn, &aim.floor.ft, &aim.floor.dcg) != 4)
      return usage();
    aim.name = name;
    if (std::none_of(choose_paths.begin(), choose_paths.end(),
                     [&](const std::string& p) { return std::filesystem::path(p).stem().string() == aim.name; }))
      return usage();
    aims.push_back(aim);
  }
  try {
    std::vector<Benchmark> choose, report;
    for (const std::string& p : choose_paths) choose.push_back(load(p));
    for (const std::string& p : report_paths) report.push_back(load(p));
    const std::optional<Benchmark> guard =
        guard_paths.empty() ? std::nullopt : std::optional<Benchmark>(load(guard_paths.front()));
    std::vector<const Benchmark*> all;
    for (const Benchmark& b : choose) all.push_back(&b);
    for (const Benchmark& b : report) all.push_back(&b);
    const auto on = [](const std::vector<const Benchmark*>& bs, const Options& o) {
      std::vector<Scores> s;
      for (const Benchmark* b : bs) s.push_back(score(*b, o));
      return s;
    };
    const Options defaults;

    std::printf(
        "# Graph matching weights: chosen on some collections, reported on others\n\n`build/experiments/"
        "matching_weights");
    for (int i = 1; i < argc; ++i) std::printf(" %s", argv[i]);
    std::printf("`. Choosing:");
    for (const Benchmark& b : choose) std::printf(" %s (%zu graphs)", b.name.c_str(), b.entries.size());
    std::printf("; reporting:");
    for (const Benchmark& b : report) std::printf(" %s (%zu graphs)", b.name.c_str(), b.entries.size());
    if (guard) std::printf("; guard: %s (%zu graphs)", guard->name.c_str(), guard->entries.size());
    std::printf(". NN, FT, DCG: the PSB measures of `reeb eval` (micro averages) on the all-pairs distances.\n\n");

    std::printf(
        "## One factor at a time\n\nEach row changes the defaults (attribute %g, structure %g, edge %g, %s, "
        "global geodesic %g, min node weight %g, %d refinement rounds) as stated.\n\n%s",
        defaults.attribute_weight, defaults.structure_weight, defaults.edge_weight, describe(defaults).c_str(),
        defaults.global_geodesic_weight, defaults.min_node_weight, defaults.refine_rounds, header(all).c_str());
    const std::vector<Setting> factors = {
        {"**defaults**", [](Options&) {}},
        {"the previous defaults (layout 5): shape 2, global D2 1.6, profile 32, no spectra, no global geodesic, "
         "min node weight 0.01",
         [](Options& o) {
           o.shape_weight = 2, o.global_shape_weight = 1.6, o.spectrum_weight = o.global_spectrum_weight = 0;
           o.global_heat_weight = 0;
           o.geodesic_shape_weight = 2, o.profile_weight = 32, o.unmatched_cost = 1.5;
           o.global_geodesic_weight = 0, o.min_node_weight = 0.01;
         }},
        {"no spectra (spectrum 0, global spectrum 0, global heat 0)",
         [](Options& o) { o.spectrum_weight = o.global_spectrum_weight = o.global_heat_weight = 0; }},
        {"global spectrum only (every other term 0)",
         [](Options& o) {
           without_terms(o);
           o.global_spectrum_weight = 1;
         }},
        {"spectrum 0", [](Options& o) { o.spectrum_weight = 0; }},
        {"global spectrum: 16 eigenvalues", [](Options& o) { o.global_spectrum_eigenvalues = 16; }},
        {"global spectrum: scale 0.1 (nearer linear)", [](Options& o) { o.global_spectrum_scale = 0.1; }},
        {"global spectrum 0", [](Options& o) { o.global_spectrum_weight = 0; }},
        {"global heat only (every other term 0)",
         [](Options& o) {
           without_terms(o);
           o.global_heat_weight = 1;
         }},
        {"global heat 0", [](Options& o) { o.global_heat_weight = 0; }},
        {"spectrum 8", [](Options& o) { o.spectrum_weight = 8; }},
        {"+ Euclidean: shape 2", [](Options& o) { o.shape_weight = 2; }},
        {"+ Euclidean: global D2 1.6", [](Options& o) { o.global_shape_weight = 1.6; }},
        {"global geodesic 0.8", [](Options& o) { o.global_geodesic_weight = 0.8; }},
        {"geodesic shape 2", [](Options& o) { o.geodesic_shape_weight = 2; }},
        {"attribute 2", [](Options& o) { o.attribute_weight = 2; }},
        {"attribute 8", [](Options& o) { o.attribute_weight = 8; }},
        {"structure 0", [](Options& o) { o.structure_weight = 0; }},
        {"structure 2", [](Options& o) { o.structure_weight = 2; }},
        {"edge 0, no refinement", [](Options& o) { o.edge_weight = 0, o.refine_rounds = 0; }},
        {"min node weight 0.01", [](Options& o) { o.min_node_weight = 0.01; }},
    };
    for (const Setting& f : factors) {
      Options o = defaults;
      f.apply(o);
      print_row(f.change, on(all, o));
    }

    // The grid over the intrinsic weights, the Euclidean ones off, the others
    // at their defaults but for those the second stage varies, which start
    // from min node weight 0.01, attribute 4 and global geodesic 0.
    Options base = defaults;
    base.min_node_weight = 0.01, base.attribute_weight = 4, base.global_geodesic_weight = 0;
    std::vector<Options> grid;
    for (const double spectrum : {0.0, 4.0, 8.0})
      for (const double global_spectrum : {4.0, 8.0, 16.0})
        for (const double scale : {0.005, 0.01})
          for (const double heat : {0.0, 2.0, 4.0, 8.0})
            for (const double heat_scale : {0.01, 0.03})
              for (const double unmatched : {1.0, 1.5}) {
                if (heat == 0 && heat_scale != 0.01) continue;  // the same setting
                Options o = base;
                o.spectrum_weight = spectrum, o.global_spectrum_weight = global_spectrum;
                o.global_spectrum_eigenvalues = 12, o.global_spectrum_scale = scale;
                o.global_heat_weight = heat, o.global_heat_scale = heat_scale;
                o.geodesic_shape_weight = 0, o.profile_weight = 16, o.unmatched_cost = unmatched;
                o.shape_weight = o.global_shape_weight = 0;
                grid.push_back(o);
              }
    std::vector<const Benchmark*> choosing;
    for (const Benchmark& b : choose) choosing.push_back(&b);
    // The guard: NN and FT on its collection not below the current defaults'.
    const std::optional<Scores> floor = guard ? std::optional<Scores>(score(*guard, defaults)) : std::nullopt;
    reebkit::Timer timer;
    const Choice first = choose_among(grid, choosing, guard, floor, aims);
    const double seconds = timer.lap() / 1000.0;
    const std::vector<std::vector<Scores>>& scores = first.scores;
    const std::vector<char>& kept = first.kept;
    const std::size_t chosen = first.chosen;
    std::string guard_text =
        guard ? " among the " + std::to_string(std::count(kept.begin(), kept.end(), 1)) +
                    " settings that keep NN and FT on " + guard->name + " at least at the current defaults' (" +
                    std::to_string(floor->nn).substr(0, 5) + ", " + std::to_string(floor->ft).substr(0, 5) + ")"
              : "";
    std::string aims_text;
    for (const Aim& aim : aims) {
      char text[200];
      std::snprintf(text, sizeof text, "%s%s NN, FT and DCG at least %g, %g, %g", aims_text.empty() ? "" : "; ",
                    aim.name.c_str(), aim.floor.nn, aim.floor.ft, aim.floor.dcg);
      aims_text += text;
    }
    if (!aims.empty())
      guard_text += (first.aimed ? ", meeting the aims (" : ", no setting meeting the aims (") + aims_text + ")";

    std::printf(
        "\n## Grid and the choice\n\n%zu settings (spectrum 0, 4, 8 x global spectrum 4, 8, 16 at 12 "
        "eigenvalues x its scale 0.005, 0.01 x global heat 0, 2, 4, 8 x its scale 0.01, 0.03 x unmatched 1, 1.5; "
        "profile 16, geodesic shape, shape and global D2 0; min node weight 0.01, attribute 4, global geodesic 0; "
        "the other weights at their defaults), %.0f s on the choosing collections. Score: the mean of NN, FT and DCG. "
        "Each row is scored on every collection; the reporting ones played no part in the choice.\n\n%s",
        grid.size(), seconds, header(all).c_str());
    for (std::size_t c = 0; c < choose.size(); ++c) {
      std::size_t best = 0;
      for (std::size_t k = 1; k < grid.size(); ++k)  // first best in grid order on ties
        if (scores[k][c].mean() > scores[best][c].mean()) best = k;
      print_row("best on " + choose[c].name + " alone (" + describe(grid[best]) + ")", on(all, grid[best]));
    }
    print_row("chosen in the grid: smallest worst rank, then rank sum" + guard_text + " (" + describe(grid[chosen]) +
                  ")",
              on(all, grid[chosen]));

    // Then the weights the grid kept at their defaults, around its choice,
    // chosen the same way among these settings.
    std::vector<Options> around;
    for (const double min_node_weight : {0.01, 0.05})
      for (const double attribute : {4.0, 8.0})
        for (const double global_geodesic : {0.0, 0.8}) {
          Options o = grid[chosen];
          o.min_node_weight = min_node_weight, o.attribute_weight = attribute,
          o.global_geodesic_weight = global_geodesic;
          around.push_back(o);
        }
    const Choice second = choose_among(around, choosing, guard, floor, aims);
    std::printf(
        "\nAround the grid's choice: min node weight 0.01, 0.05 x attribute 4, 8 x global geodesic 0, 0.8, "
        "chosen the same way among these %zu settings (**bold**: the choice; MatchingOptions' defaults are the "
        "**defaults** row above).\n\n%s",
        around.size(), header(all).c_str());
    for (std::size_t k = 0; k < around.size(); ++k) {
      char text[120];
      std::snprintf(text, sizeof text, "min node weight %g, attribute %g, global geodesic %g%s",
                    around[k].min_node_weight, around[k].attribute_weight, around[k].global_geodesic_weight,
                    second.note(k).c_str());
      print_row(k == second.chosen ? "**" + std::string(text) + "**" : std::string(text), on(all, around[k]));
    }

    std::vector<std::size_t> order(grid.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return first.before(x, y); });
    std::printf(
        "\nThe ten grid settings first in the order of the choice (worst rank, then rank sum), on the "
        "choosing collections:\n\n%s",
        header(choosing).c_str());
    for (std::size_t k = 0; k < std::min<std::size_t>(10, order.size()); ++k)
      print_row(describe(grid[order[k]]) + first.note(order[k]), scores[order[k]]);
    std::printf("\n<details><summary>The whole grid, in grid order</summary>\n\n%s", header(choosing).c_str());
    for (std::size_t k = 0; k < grid.size(); ++k) print_row(describe(grid[k]), scores[k]);
    std::printf("\n</details>\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "matching_weights: %s\n", e.what());
    return 1;
  }
  return 0;
}

// Graph matching speed (matching/graph_matching.h) on an indexed collection:
// time per pair (serial, default options and without refinement), then all
// pairs i < j in parallel with 1 and 2 threads, and the node counts that
// drive it. Target: all pairs of SHREC07's 400 graphs <= 5 s on 2 cores.
//
//   build/tools/reeb index build/data/shrec07_watertight -o shrec.h5 --threads 2
//   build/bench/matching_bench shrec.h5
#include "reebkit/core/timer.h"
#include "reebkit/matching/graph_matching.h"
#include "reebkit/store/collection_file.h"

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

/// Seconds for all pairs i < j with `threads` threads; `distances`
/// receives them (n x n, upper triangle), to check that the thread count
/// changes nothing.
double all_pairs_seconds(const std::vector<reebkit::MatchableGraph>& graphs, const reebkit::MatchingOptions& options,
                         int threads, std::vector<double>& distances) {
  const auto n = static_cast<std::ptrdiff_t>(graphs.size());
  distances.assign(graphs.size() * graphs.size(), 0.0);
  reebkit::Timer timer;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    for (std::ptrdiff_t j = i + 1; j < n; ++j)
      distances[static_cast<std::size_t>(i * n + j)] =
          reebkit::match_graphs(graphs[static_cast<std::size_t>(i)], graphs[static_cast<std::size_t>(j)], options)
              .distance;
  return timer.lap() / 1000.0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: matching_bench COLLECTION.h5\n");
    return 2;
  }
  try {
    reebkit::Timer read_timer;
    const reebkit::CollectionReader reader(argv[1]);
    std::vector<reebkit::MatchableGraph> graphs;
    std::vector<int> sizes;
    for (std::int64_t i = 0; i < reader.size(); ++i) {
      const reebkit::GraphRecord entry = reader.entry(i);
      if (!entry.ok) continue;
      graphs.push_back(reebkit::make_matchable_graph(entry));
      sizes.push_back(graphs.back().num_nodes);
    }
    const double read_ms = read_timer.lap();
    std::sort(sizes.begin(), sizes.end());
    const std::size_t n = graphs.size();
    const double pairs = static_cast<double>(n) * static_cast<double>(n - 1) / 2.0;
    std::printf(
        "%s: %zu graphs (read + matchable form %.0f ms), nodes per graph: min %d, median %d, max %d; "
        "%.0f pairs\n",
        argv[1], n, read_ms, sizes.front(), sizes[n / 2], sizes.back(), pairs);
    reebkit::MatchingOptions no_refinement;
    no_refinement.refine_rounds = 0;
    for (const auto& [label, options] :
         {std::pair{"default options", reebkit::MatchingOptions{}}, std::pair{"no refinement", no_refinement}}) {
      std::vector<double> serial, parallel;
      const double one = all_pairs_seconds(graphs, options, 1, serial);
      const double two = all_pairs_seconds(graphs, options, 2, parallel);
      std::printf("%-16s per pair %.1f us (1 thread); all pairs: %.2f s on 1 thread, %.2f s on 2 threads (%.2fx)%s\n",
                  label, one / pairs * 1e6, one, two, one / two,
                  serial == parallel ? "" : "  [1 and 2 threads differ]");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "matching_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}

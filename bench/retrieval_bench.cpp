// Retrieval speed: all-pairs graph-matching distances of an
// indexed collection with 1 and 2 threads (target for SHREC07's 400 graphs:
// <= 5 s on 2 cores), and one query against a SIZE-graph collection after
// the query's own graph is extracted (target <= 20 ms at 10,000). The large
// collection is the given one replicated with jittered attributes and
// signatures (2 % and 0.01), written to a collection file with its query
// file and queried as reeb query does: the signature index loaded from the
// query file and the candidates' graphs read from it, checked against the
// whole collection loaded (up to 100,000 graphs); and the recall@10 of the
// k-d tree against a linear scan.
//
//   build/bench/retrieval_bench shrec.h5 [SIZE=10000] [SCRATCH=/tmp/retrieval_bench.h5]
//
// A SCRATCH given is kept with its query file, and used again by the next
// run with the same SIZE (the collection is then neither written nor indexed).
#include "reebkit/core/timer.h"
#include "reebkit/retrieval/all_pairs.h"
#include "reebkit/retrieval/query.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <random>
#include <string>

namespace {

using namespace reebkit;

/// `size` entries handed to `take` one by one: the collection's ok entries
/// over and over, every copy after the first with its node attributes scaled
/// by 1 +- 2 % and its signature moved by +- 0.01 (clamped to [0,1]), so that
/// no two are the same.
void replicate(const std::vector<GraphRecord>& entries, std::int64_t size,
               const std::function<void(GraphRecord)>& take) {
  std::vector<const GraphRecord*> ok;
  for (const GraphRecord& e : entries)
    if (e.ok) ok.push_back(&e);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::int64_t i = 0; i < size; ++i) {
    GraphRecord e = *ok[static_cast<std::size_t>(i) % ok.size()];
    if (i >= static_cast<std::int64_t>(ok.size())) {
      e.name = "copy" + std::to_string(i) + "/" + e.name;
      for (double& a : e.node_attributes) a *= 1.0 + 0.02 * u(rng);
      for (double& s : e.signature) s = std::clamp(s + 0.01 * u(rng), 0.0, 1.0);
    }
    take(std::move(e));
  }
}

void all_pairs_figures(const CollectionReader& collection) {
  const std::vector<std::int64_t> rows = matrix_rows(collection);
  for (const int threads : {1, 2}) {
    AllPairsOptions options;
    options.threads = threads;
    Timer timer;
    const PairwiseDistances d = all_pairs_distances(collection, rows, options);
    const double ms = timer.lap();
    const double pairs = static_cast<double>(d.size()) * static_cast<double>(d.size() - 1) / 2;
    std::printf("all pairs, %lld graphs, %d thread%s: %.2f s (%.1f us per pair), reading included\n",
                static_cast<long long>(d.size()), threads, threads > 1 ? "s" : "", ms / 1000, 1000 * ms / pairs);
  }
}

/// Median, 90th percentile and max of `ms` (sorted here).
std::string spread(std::vector<double>& ms) {
  std::sort(ms.begin(), ms.end());
  char text[96];
  std::snprintf(text, sizeof text, "median %.2f ms, 90th percentile %.2f ms, max %.2f ms", ms[ms.size() / 2],
                ms[ms.size() * 9 / 10], ms.back());
  return text;
}

/// Recall@10 of the k-d tree against a linear scan (the exact signature
/// ranking), averaged over `queries`.
double prefilter_recall(const SignatureIndex& index, const std::vector<GraphRecord>& queries) {
  const std::vector<double> rows(index.rows(), index.rows() + index.size() * kSignatureLength);
  const SignatureIndex linear(rows, kSignatureLength, {SignatureIndexKind::Linear});
  double found = 0, wanted = 0;
  for (const GraphRecord& q : queries) {
    std::vector<std::int64_t> exact;
    for (const SignatureNeighbour& n : linear.nearest(q.signature, 10))
      exact.push_back(index.row_of()[static_cast<std::size_t>(n.row)]);
    for (const SignatureNeighbour& n : index.nearest(q.signature, 10))
      found += static_cast<double>(std::count(exact.begin(), exact.end(), n.row));
    wanted += static_cast<double>(exact.size());
  }
  return found / wanted;
}

bool same_results(const std::vector<QueryResult>& a, const std::vector<QueryResult>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const QueryResult& x, const QueryResult& y) {
    return x.index == y.index && x.distance == y.distance && x.signature_distance == y.signature_distance &&
           x.name == y.name;
  });
}

/// Collections up to this size are also loaded whole (load_searchable), to
/// time that and to check that the query file gives the same results.
constexpr std::int64_t kLoadedUpTo = 100000;

/// Whether `scratch` holds a collection of `size` entries with its query file
/// (kept by an earlier run).
bool kept(const std::filesystem::path& scratch, std::int64_t size) {
  if (!std::filesystem::exists(scratch)) return false;
  const CollectionReader collection(scratch);
  return collection.size() == size && QueryFile::open(collection).has_value();
}

void query_figures(const CollectionReader& source, std::int64_t size, const std::filesystem::path& scratch) {
  std::vector<GraphRecord> queries;  // 50 of the 400 graphs
  for (std::int64_t q = 0; q < source.size(); q += 8)
    if (GraphRecord e = source.entry(q); e.ok) queries.push_back(std::move(e));
  Timer timer;
  if (kept(scratch, size)) {
    std::printf("%s: the %lld-graph collection and its query file kept from an earlier run\n", scratch.string().c_str(),
                static_cast<long long>(size));
  } else {
    CollectionWriter writer(scratch, Provenance{}, false);
    replicate(source.entries(0, source.size()), size, [&](GraphRecord e) { writer.append(std::move(e)); });
    writer.close();
    std::printf("%lld-graph collection written in %.1f s\n", static_cast<long long>(size), timer.lap() / 1000);
    const CollectionReader large(scratch);
    const std::vector<double>& signatures = large.signatures();
    std::printf("signature matrix read in %.0f ms\n", timer.lap());
    const SignatureIndex index(signatures, kSignatureLength);
    std::printf("k-d tree built in %.0f ms (what the query file saves a query)\n", timer.lap());
    write_query_file(large);
    std::printf("query file written (k-d tree built again) in %.1f s: %.0f MB (collection %.0f MB)\n",
                timer.lap() / 1000, static_cast<double>(std::filesystem::file_size(QueryFile::path_of(scratch))) / 1e6,
                static_cast<double>(std::filesystem::file_size(scratch)) / 1e6);
  }
  timer.lap();
  const CollectionReader large(scratch);
  const double open_ms = timer.lap();
  const std::optional<QueryableFile> file = open_query_file(large);
  std::printf("collection opened in %.0f ms, query file's signature index loaded in %.0f ms (once per session)\n",
              open_ms, timer.lap());
  std::printf("pre-filter recall@10 of the loaded k-d tree against a linear scan: %.4f\n",
              prefilter_recall(file->index, queries));
  timer.lap();
  std::optional<SearchableCollection> searchable;
  if (size <= kLoadedUpTo) {
    searchable = load_searchable(large);
    std::printf("the whole collection read and indexed in %.0f ms\n", timer.lap());
  }
  // Warm: each query once before the timed ones, so that the pages of the
  // query file they read are in this process's page tables.
  for (const GraphRecord& q : queries) query_collection(large, *file, q, QueryOptions{});
  std::printf("warm-up pass (50 queries) in %.0f ms\n", timer.lap());
  for (const auto& [candidates, threads] : {std::pair{100, 1}, {100, 2}, {300, 2}}) {
    QueryOptions options;
    options.candidates = candidates;
    options.threads = threads;
    std::vector<double> from_file, cpu, loaded;
    for (const GraphRecord& q : queries) {
      const std::clock_t start = std::clock();
      timer.lap();
      const std::vector<QueryResult> results = query_collection(large, *file, q, options);
      from_file.push_back(timer.lap());
      cpu.push_back(1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
      if (results.empty()) throw std::runtime_error("no results");
      if (!searchable) continue;
      const std::vector<QueryResult> expected = query_collection(*searchable, q, options);
      loaded.push_back(timer.lap());
      if (!same_results(results, expected)) throw std::runtime_error("the query file gives other results");
    }
    // CPU time (of all threads) beside the wall time: on a shared machine
    // the wall time also holds the time the query waited for a core.
    std::printf(
        "query, k = 10, candidates = %d, %d thread%s, %zu queries, graphs read from the query file: %s "
        "(CPU time: %s)\n",
        candidates, threads, threads > 1 ? "s" : "", from_file.size(), spread(from_file).c_str(), spread(cpu).c_str());
    if (searchable)
      std::printf("  the same on the loaded collection (identical results): %s\n", spread(loaded).c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::cerr << "usage: retrieval_bench collection.h5 [SIZE=10000] [SCRATCH=/tmp/retrieval_bench.h5]\n";
    return 2;
  }
  try {
    const CollectionReader collection(argv[1]);
    all_pairs_figures(collection);
    const std::filesystem::path scratch =
        argc > 3 ? argv[3] : std::filesystem::temp_directory_path() / "retrieval_bench.h5";
    query_figures(collection, argc > 2 ? std::stoll(argv[2]) : 10000, scratch);
    if (argc <= 3) {
      std::filesystem::remove(QueryFile::path_of(scratch));
      std::filesystem::remove(scratch);
    }
  } catch (const std::exception& e) {
    std::cerr << "retrieval_bench: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

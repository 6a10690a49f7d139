// Write speed of the HDF5 collection file (CollectionWriter), for graphs of
// 20 to 50 nodes as SHREC07 meshes give them, against the indexing budget:
// HDF5 time <= 5 % of about 20 ms of analysis per mesh, i.e. <= 1 ms/entry.
//
//   build/bench/store_bench [folder]   (default: the system temp folder)
//
// Prints, for a few checkpoint intervals: entries per second, payload MB/s
// (bytes of the arrays handed to append), the file size, and the time per
// checkpoint; then the time to reopen with resume (a full rewrite of the
// committed entries), which is also what one checkpoint would cost if every
// checkpoint rewrote the file (temp file + rename) instead of appending.
#include "reebkit/core/timer.h"
#include "reebkit/store/collection_file.h"

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

namespace {

using namespace reebkit;

/// A graph of 20 to 50 nodes, a few cycles, ~20 feature points and the
/// skeleton of 100 levels spread over the nodes.
GraphRecord synthetic_entry(std::int64_t i, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  GraphRecord e;
  e.name = "bench/" + std::to_string(i) + ".off";
  e.class_label = "class" + std::to_string(i % 20);
  e.content_hash = rng();
  e.ok = true;
  e.vertices = 3000 + static_cast<std::int64_t>(rng() % 20000);
  e.faces = 2 * e.vertices - 4;
  const auto n = static_cast<std::int32_t>(20 + rng() % 31);
  e.skeleton_offset.push_back(0);
  for (std::int32_t k = 0; k < n; ++k) {
    e.nodes.insert(e.nodes.end(), {k % 4, (k + 1) % 4, static_cast<std::int32_t>(rng() % 20000),
                                   static_cast<std::int32_t>(rng() % 2000)});
    for (int c = 0; c < kGeomColumnCount; ++c) e.node_geometry.push_back(unit(rng));
    for (int c = 0; c < kNodeAttributeCount; ++c) e.node_attributes.push_back(unit(rng));
    const std::int64_t points = 100 / n + (k < 100 % n ? 1 : 0);
    for (std::int64_t p = 0; p < 3 * points; ++p) e.skeleton_points.push_back(unit(rng));
    e.skeleton_offset.push_back(e.skeleton_offset.back() + points);
  }
  for (std::int32_t k = 1; k < n + 2; ++k) {
    const std::int32_t later = k < n ? k : n - 1;
    e.edges.insert(e.edges.end(), {static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(later)), later});
    for (int c = 0; c < kEdgeAttributeCount; ++c) e.edge_attributes.push_back(unit(rng));
  }
  for (int k = 0; k < 20; ++k) e.feature_points.push_back(static_cast<std::int32_t>(rng() % 20000));
  for (int c = 0; c < kSignatureLength; ++c) e.signature.push_back(unit(rng));
  for (double& t : e.timings) t = 20 * unit(rng);
  return e;
}

std::size_t payload_bytes(const GraphRecord& e) {
  return e.name.size() + e.class_label.size() + e.error.size() + 8 * 3 + 1 + sizeof e.timings +
         4 * (e.nodes.size() + e.edges.size() + e.feature_points.size()) +
         8 * (e.node_geometry.size() + e.node_attributes.size() + e.edge_attributes.size() + e.skeleton_offset.size() +
              e.skeleton_points.size() + e.signature.size());
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path folder = argc > 1 ? argv[1] : std::filesystem::temp_directory_path();
  const std::filesystem::path path = folder / "reebkit_store_bench.h5";
  constexpr std::int64_t kEntries = 10000;

  // The entries, made before timing (generation is not what is measured).
  std::mt19937_64 rng(7);
  std::vector<GraphRecord> entries;
  std::size_t payload = 0;
  for (std::int64_t i = 0; i < kEntries; ++i) {
    entries.push_back(synthetic_entry(i, rng));
    payload += payload_bytes(entries.back());
  }
  std::printf("%lld entries of 20-50 nodes, %.1f MB of payload; file in %s\n", static_cast<long long>(kEntries),
              static_cast<double>(payload) / 1e6, folder.string().c_str());
  std::printf("%-22s %12s %10s %10s %14s %12s\n", "checkpoint every", "entries/s", "MB/s", "ms/entry", "ms/checkpoint",
              "file MB");
  for (const std::int64_t interval :
       {std::int64_t{16}, std::int64_t{64}, std::int64_t{256}, std::int64_t{1024}, kEntries}) {
    Timer timer;
    double checkpoint_ms = 0;
    std::int64_t checkpoints = 0;
    {
      CollectionWriter writer(path, Provenance{}, false);
      for (std::int64_t i = 0; i < kEntries; ++i) {
        writer.append(entries[static_cast<std::size_t>(i)]);
        if ((i + 1) % interval == 0) {
          Timer c;
          writer.checkpoint();
          checkpoint_ms += c.lap();
          ++checkpoints;
        }
      }
      writer.close();
    }
    const double seconds = timer.lap() / 1e3;
    std::printf("%-22lld %12.0f %10.1f %10.3f %14.2f %12.1f\n", static_cast<long long>(interval),
                static_cast<double>(kEntries) / seconds, static_cast<double>(payload) / 1e6 / seconds,
                1e3 * seconds / static_cast<double>(kEntries), checkpoint_ms / static_cast<double>(checkpoints),
                static_cast<double>(std::filesystem::file_size(path)) / 1e6);
  }

  // Resume: the committed entries rewritten into a fresh file.
  for (const std::int64_t size : {std::int64_t{400}, kEntries}) {
    {
      CollectionWriter writer(path, Provenance{}, false);
      for (std::int64_t i = 0; i < size; ++i) writer.append(entries[static_cast<std::size_t>(i)]);
    }
    Timer timer;
    CollectionWriter resumed(path, Provenance{}, true);
    std::printf("resume (full rewrite) of %lld entries: %.1f ms\n", static_cast<long long>(size), timer.lap());
  }
  {
    Timer timer;
    const CollectionReader reader(path);
    double open_ms = timer.lap();
    Timer all;
    std::size_t nodes = 0;
    for (std::int64_t i = 0; i < reader.size(); ++i) nodes += static_cast<std::size_t>(reader.entry(i).num_nodes());
    std::printf("read: open %.1f ms, entry() %.3f ms each (%zu nodes)\n", open_ms,
                all.lap() / static_cast<double>(reader.size()), nodes);
  }
  std::filesystem::remove(path);
  return 0;
}

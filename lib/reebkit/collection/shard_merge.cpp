#include "reebkit/collection/shard_merge.h"

#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/store/collection_file.h"

#include <omp.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <unordered_set>

namespace reebkit {
namespace {

namespace fs = std::filesystem;

constexpr const char* kShardPrefix = "rank-";
constexpr const char* kShardSuffix = ".h5";

/// The shards in `folder`, by rank (files named as shard_path names them).
std::vector<fs::path> shards_in(const fs::path& folder) {
  std::vector<std::pair<long, fs::path>> found;
  if (!fs::is_directory(folder)) return {};
  for (const fs::directory_entry& file : fs::directory_iterator(folder)) {
    const std::string name = file.path().filename().string();
    const std::string prefix = kShardPrefix, suffix = kShardSuffix;
    if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) continue;
    found.emplace_back(std::stol(digits), file.path());
  }
  std::sort(found.begin(), found.end());
  std::vector<fs::path> out;
  for (auto& [rank, path] : found) out.push_back(std::move(path));
  return out;
}

fs::path partial_of(const fs::path& output) { return output.string() + ".partial"; }

/// Entries of a collection read in blocks: a shard is read nearly in order
/// (each run of a job appends the inputs it was handed in input order).
class BlockReader {
 public:
  explicit BlockReader(const fs::path& path) : reader_(path) {}
  const CollectionReader& reader() const { return reader_; }

  GraphRecord entry(std::int64_t i) {
    if (i < first_ || i >= first_ + static_cast<std::int64_t>(block_.size())) {
      first_ = i;
      block_ = reader_.entries(i, std::min<std::int64_t>(kBlock, reader_.size() - i));
    }
    return block_[static_cast<std::size_t>(i - first_)];
  }

 private:
  static constexpr std::int64_t kBlock = 256;
  CollectionReader reader_;
  std::int64_t first_ = 0;
  std::vector<GraphRecord> block_;
};

}  // namespace

fs::path shard_folder(const fs::path& output) { return output.string() + ".shards"; }

fs::path shard_path(const fs::path& output, int rank) {
  return shard_folder(output) / (kShardPrefix + std::to_string(rank) + kShardSuffix);
}

ShardedJob plan_sharded_job(const std::vector<MeshInput>& inputs, const fs::path& output,
                            const ExtractionOptions& options) {
  ShardedJob job;
  const fs::path folder = shard_folder(output), partial = partial_of(output);
  if (!options.resume) {
    fs::remove_all(folder);
    fs::remove(partial);
    fs::create_directories(folder);
    for (std::size_t i = 0; i < inputs.size(); ++i) job.todo.push_back(i);
    return job;
  }
  if (fs::exists(partial) && !opens_as_collection(partial)) fs::remove(partial);
  job.base = fs::exists(partial) ? partial : fs::exists(output) ? output : fs::path();
  std::vector<fs::path> sources;
  if (!job.base.empty()) sources.push_back(job.base);
  for (const fs::path& shard : shards_in(folder)) {
    if (opens_as_collection(shard))
      sources.push_back(shard);
    else
      fs::remove(shard);  // killed while being created: no entry in it
  }
  // What the earlier runs hold: (name, hash) pairs.
  std::unordered_map<std::string, std::vector<std::uint64_t>> held;
  for (const fs::path& source : sources) {
    const CollectionReader reader(source);
    refuse_other_analysis(source, reader.provenance(), options.analysis);
    for (std::int64_t i = 0; i < reader.size(); ++i)
      held[reader.names()[static_cast<std::size_t>(i)]].push_back(reader.content_hashes()[static_cast<std::size_t>(i)]);
  }
  std::vector<std::size_t> known;  // the inputs an earlier run holds an entry of
  std::vector<MeshInput> to_hash;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (held.count(inputs[i].name) != 0) {
      known.push_back(i);
      to_hash.push_back(inputs[i]);
    }
  const std::vector<std::uint64_t> hashes =
      hash_inputs(to_hash, options.threads > 0 ? options.threads : omp_get_max_threads());
  std::unordered_set<std::size_t> done;
  for (std::size_t k = 0; k < known.size(); ++k) {
    const std::string& name = inputs[known[k]].name;
    job.hashes.emplace(name, hashes[k]);
    const std::vector<std::uint64_t>& h = held[name];
    if (std::find(h.begin(), h.end(), hashes[k]) != h.end()) done.insert(known[k]);
  }
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (done.count(i) == 0) job.todo.push_back(i);
  job.skipped = static_cast<std::int64_t>(done.size());
  fs::create_directories(folder);
  return job;
}

ExtractionSummary merge_shards(const std::vector<MeshInput>& inputs, const std::vector<PsbClass>& classes,
                               const fs::path& output, const ShardedJob& job, const ExtractionOptions& options) {
  Timer timer;
  const fs::path folder = shard_folder(output);
  std::vector<std::unique_ptr<BlockReader>> shards;
  for (const fs::path& shard : shards_in(folder)) shards.push_back(std::make_unique<BlockReader>(shard));
  std::optional<BlockReader> base;
  if (!job.base.empty()) base.emplace(job.base);

  Provenance provenance = extraction_provenance(classes, options);
  if (classes.empty()) {  // as resume: the classes of the file, else of a shard
    std::vector<const CollectionReader*> sources;
    if (base) sources.push_back(&base->reader());
    for (const auto& shard : shards) sources.push_back(&shard->reader());
    for (const CollectionReader* source : sources)
      if (!source->provenance().classes.empty()) {
        provenance.classes = source->provenance().classes;
        provenance.classes_file = source->provenance().classes_file;
        break;
      }
  }
  const ClassMap class_of_model = class_map(provenance.classes);

  // Where each name is in the shards: (shard, entry) in rank and file order.
  std::unordered_map<std::string, std::vector<std::pair<std::size_t, std::int64_t>>> in_shards;
  for (std::size_t s = 0; s < shards.size(); ++s)
    for (std::int64_t i = 0; i < shards[s]->reader().size(); ++i)
      in_shards[shards[s]->reader().names()[static_cast<std::size_t>(i)]].emplace_back(s, i);
  std::unordered_set<std::size_t> computed(job.todo.begin(), job.todo.end());

  const fs::path merged = folder / "merged.h5.tmp";
  ExtractionSummary summary;
  CollectionWriter writer(merged, provenance, false);
  std::unordered_set<std::string> written;
  const auto append = [&](GraphRecord entry) {
    if (!provenance.classes.empty()) entry.class_label = class_of(class_of_model, entry.name);
    written.insert(entry.name);
    writer.append(std::move(entry));
  };
  if (base) {
    for (std::int64_t i = 0; i < base->reader().size(); ++i) {
      const std::string& name = base->reader().names()[static_cast<std::size_t>(i)];
      const auto current = job.hashes.find(name);
      if (current != job.hashes.end() &&
          current->second != base->reader().content_hashes()[static_cast<std::size_t>(i)])
        continue;  // the input changed: its new entry comes from a shard
      append(base->entry(i));
      ++summary.kept;
    }
  }
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string& name = inputs[i].name;
    if (written.count(name) != 0) continue;
    const auto found = in_shards.find(name);
    if (found == in_shards.end())
      throw Error(output.string() + ": cannot merge the shards of " + folder.string() + ": no shard holds the mesh '" +
                  name + "' (reeb index --resume computes it)");
    // The entry with the input's current content, else the last one written.
    std::pair<std::size_t, std::int64_t> at = found->second.back();
    const auto current = job.hashes.find(name);
    if (current != job.hashes.end())
      for (const auto& candidate : found->second)
        if (shards[candidate.first]->reader().content_hashes()[static_cast<std::size_t>(candidate.second)] ==
            current->second)
          at = candidate;
    GraphRecord entry = shards[at.first]->entry(at.second);
    if (computed.count(i) == 0) {
      ++summary.kept;  // an earlier run's
    } else if (entry.ok) {
      ++summary.ok;
    } else {
      summary.failed.push_back({entry.name, entry.error});
    }
    append(std::move(entry));
  }
  writer.close();
  shards.clear();
  base.reset();
  summary.skipped = job.skipped;
  summary.all_failed = summary.ok == 0 && !summary.failed.empty() && summary.kept == 0;
  if (!summary.all_failed) fs::rename(merged, output);
  fs::remove(partial_of(output));
  fs::remove_all(folder);
  summary.write_seconds = summary.seconds = timer.lap() / 1000;
  return summary;
}

}  // namespace reebkit

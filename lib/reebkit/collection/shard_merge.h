// A collection indexed by several processes at once (reeb index under MPI,
// docs/cluster.md): each process appends the meshes it is handed to its own
// shard, a collection file of the usual layout (extract_shard), and at the
// end the shards are merged into one collection file whose entries are in
// the order a single process would have written them, so that the file is
// the same whatever the number of processes (timings and provenance aside).
#pragma once

#include "reebkit/collection/extract_collection.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace reebkit {

/// The folder of the shards of a job writing `output`: `output` + ".shards".
std::filesystem::path shard_folder(const std::filesystem::path& output);
/// Process `rank`'s shard: shard_folder(output) / "rank-<rank>.h5".
std::filesystem::path shard_path(const std::filesystem::path& output, int rank);

/// What a sharded job computes, and what it keeps from earlier runs.
struct ShardedJob {
  std::vector<std::size_t> todo;  ///< the inputs to compute, in input order
  /// The collection whose entries come first, in its order (resume): the
  /// `output` + ".partial" an interrupted run left, else the existing
  /// `output`; empty when none (as extract_collection resumes).
  std::filesystem::path base;
  /// The content hash of every input whose name the base or a shard holds
  /// (what decides whether an entry is current).
  std::unordered_map<std::string, std::uint64_t> hashes;
  std::int64_t skipped = 0;  ///< inputs already in the base or a shard with their current content
};

/// Plans the job of indexing `inputs` into `output`; call it after
/// check_extraction, holding the lock of `output` (FileLock), before any
/// process computes. Without options.resume it removes what an earlier job
/// left (the shard folder, `output` + ".partial") and every input is to
/// compute. With it, an input is done when the base or a shard of an earlier
/// run (a killed job's shards keep the entries of their last checkpoint)
/// holds its name with its current content hash; a shard or partial file
/// that does not open (killed while HDF5 created it) holds no entry and is
/// removed. Throws Error, naming the file, when the base or a shard was
/// indexed with other analysis options (refuse_other_analysis). Creates the
/// shard folder.
ShardedJob plan_sharded_job(const std::vector<MeshInput>& inputs, const std::filesystem::path& output,
                            const ExtractionOptions& options);

/// Merges the base and the shards of `job` into `output` (written into the
/// shard folder, then renamed over `output`; the shard folder and
/// `output` + ".partial" are then removed): the base's entries first, in its
/// order, without those whose input changed (a name among the inputs with
/// another content hash); then every other input, in input order, from the
/// shard that holds it with its current content. Entries are labelled with
/// `classes`, or without them with the base's (or a shard's) classes, as
/// extract_collection labels them on resume. The summary counts the inputs
/// of job.todo as computed (ok, failed), the others as skipped; kept: the
/// entries taken from the base or an earlier run's shards; write_seconds:
/// the merge. When every mesh computed failed and nothing is kept, `output`
/// is left as it was (summary.all_failed). Throws Error when an input has no
/// entry in any shard, or a file cannot be read or written.
ExtractionSummary merge_shards(const std::vector<MeshInput>& inputs, const std::vector<PsbClass>& classes,
                               const std::filesystem::path& output, const ShardedJob& job,
                               const ExtractionOptions& options);

}  // namespace reebkit

// Indexing a collection (reeb index): every mesh read, analysed (feature
// points, f_q, Reeb graph: Tierny et al. 2006, sections 4.1-4.2) and given
// its attributes by OpenMP workers, and appended to the collection file in
// input order by one thread, so that the file is the same whatever the
// number of threads.
#pragma once

#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/collection/progress.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/pipeline/analyze_mesh.h"
#include "reebkit/store/collection_file.h"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace reebkit {

struct ExtractionOptions {
  int threads = 0;  ///< workers computing meshes; 0 = omp_get_max_threads()
  /// Keep the entries already in the output file and skip every input whose
  /// name and content hash match one (a failed one too: same bytes, same
  /// failure). See extract_collection for changed files.
  bool resume = false;
  int batch_size = 64;            ///< entries computed ahead of the writer at most (bounds memory); >= 1
  double checkpoint_seconds = 5;  ///< make the file durable at least this often...
  int checkpoint_entries = 1000;  ///< ...and every this many new entries
  AnalysisOptions analysis;       ///< the pipeline run on each mesh (largest connected component)
  ProgressSink progress;          ///< called after each entry written; empty = silent
  std::string command;            ///< the command line, stored as provenance
  std::string classes_file;       ///< the .cla file the classes come from, stored with them
  /// Set to true to end the run early (it may be set from a signal handler:
  /// std::atomic<bool> is lock-free): no further mesh is started, the ones
  /// in progress are finished and written, the file is made durable, and
  /// extract_collection returns with ExtractionSummary::interrupted.
  /// Null: the run goes to the end. extract_shard does not look at it.
  const std::atomic<bool>* stop = nullptr;
};

struct FailedMesh {
  std::string name;
  std::string reason;  ///< the exception's message
};

struct ExtractionSummary {
  std::int64_t ok = 0;             ///< meshes computed into an entry with a graph
  std::vector<FailedMesh> failed;  ///< meshes computed into a failed entry, in input order
  std::int64_t skipped = 0;        ///< inputs already in the file (resume): not computed
  std::int64_t kept = 0;           ///< entries of the file kept (resume), skipped ones included
  double seconds = 0;              ///< wall time of the whole call
  double write_seconds = 0;        ///< of which the writer thread spent in CollectionWriter calls
  /// Every mesh computed failed and the file kept none: the output was left
  /// as it was (not created, not replaced).
  bool all_failed = false;
  /// ExtractionOptions::stop ended the run before every input was
  /// computed: every entry computed is in `file`, which --resume completes.
  bool interrupted = false;
  /// The file that holds the entries: the output, or, for a new collection
  /// whose run was interrupted, the output + ".partial" (not renamed over
  /// the output until the collection is complete).
  std::filesystem::path file;
  std::int64_t computed() const { return ok + static_cast<std::int64_t>(failed.size()); }
  /// The entries of `file`: those kept and those computed.
  std::int64_t entries() const { return kept + computed(); }
};

/// The analysis options as one-line JSON text, for the file's provenance:
/// the table of analysis_options.h by name, all_components and reeb_graph.
std::string analysis_options_json(const AnalysisOptions& options);

/// What a file indexed with `options` and `classes` says of where it came
/// from (no creation time: the writer stamps it).
Provenance extraction_provenance(const std::vector<PsbClass>& classes, const ExtractionOptions& options);

/// FNV-1a 64 content hash of the input's file (content_hash), 0 for a file
/// that cannot be read (load_mesh then reports why).
std::uint64_t input_hash(const MeshInput& input);
/// input_hash of every input, read by `threads` threads.
std::vector<std::uint64_t> hash_inputs(const std::vector<MeshInput>& inputs, int threads);

/// Everything extract_collection checks before any mesh is read: the
/// options, that there is an input, the output (check_output_file: its
/// folder exists and is writable, it is none of the inputs nor the classes
/// file) and that `classes`, when given, name at least one input. Throws
/// InvalidArgument.
void check_extraction(const std::vector<MeshInput>& inputs, const std::vector<PsbClass>& classes,
                      const std::filesystem::path& output, const ExtractionOptions& options);

/// Throws Error, naming the file `path` (whose provenance is `indexed`) and
/// each differing option with both values, unless it was analysed with
/// `analysis`: a file is resumed only with its own analysis options.
void refuse_other_analysis(const std::filesystem::path& path, const Provenance& indexed,
                           const AnalysisOptions& analysis);

/// Whether `path` opens as a collection file (CollectionReader).
bool opens_as_collection(const std::filesystem::path& path);

/// Indexes `inputs` into the collection file `output`: per mesh, load_mesh
/// (largest component), analyze_mesh, compute_attributes and
/// make_graph_record, with its class in `classes` (class_of) and the
/// content hash of its file. The file keeps the analysis options (by name,
/// named_analysis_options) and `classes` in their order. Any exception on a mesh becomes a failed entry
/// with its message; the batch goes on. Entries are appended in input order
/// and checkpointed (options).
///
/// Before any mesh is read it checks the options (check_analysis_options),
/// the output (check_output_file: its folder exists and is writable, it is
/// none of the inputs nor the classes file) and that `classes`, when given,
/// name at least one input; then it takes the lock of `output` (FileLock:
/// `output` + ".lock"), held to the end, so that a second writer is refused
/// naming the first one's pid. A new collection is written into `output` +
/// ".partial" and renamed over `output` at the end: until then `output`
/// keeps its old content, and an interrupted run leaves the partial file
/// holding every entry up to its last checkpoint. When every mesh failed
/// (summary.all_failed) the partial file is removed and `output` left as it was.
///
/// With options.stop set, the run ends early as ExtractionOptions::stop
/// says; a new collection then stays in `output` + ".partial".
///
/// With options.resume the entries of an existing `output` (or of the
/// `output` + ".partial" an interrupted run left, which is then completed and
/// renamed over `output`; one that does not open was killed while being
/// created, holds no entry and is dropped) are kept, and an input whose (name, content hash)
/// is among them is skipped. An input whose
/// name is in the file with another hash (the file changed) is recomputed,
/// and its old entry dropped: the file is rewritten, without the stale
/// entries, into the file + ".rewrite" and renamed over it at the end
/// (until then the file keeps its old content), so that a name appears at
/// most once in a collection file and readers need no rule for duplicates.
/// Given `classes`, resume relabels every kept entry with them (also by a
/// rewrite); without, it keeps the file's classes for the new entries.
/// Entries of meshes that are no longer among the inputs are kept. Resuming
/// a file analysed with other analysis options throws Error before any work,
/// naming the file and each differing option with both values.
/// Throws InvalidArgument on bad options, outputs or classes, and Error from
/// the lock or the writer (the file cannot be created or written: the
/// message then says which file holds the entries of the last checkpoint).
ExtractionSummary extract_collection(const std::vector<MeshInput>& inputs, const std::vector<PsbClass>& classes,
                                     const std::filesystem::path& output, const ExtractionOptions& options = {});

/// The next input to compute (an index into the inputs), or none when the
/// job has no input left.
using InputClaim = std::function<std::optional<std::size_t>()>;

/// One process's part of an extraction shared by several processes (reeb
/// index under MPI: docs/cluster.md). The workers (options.threads) take
/// the inputs `claim` hands out, which it is asked for one at a time (never
/// concurrently), until it returns none; each mesh is computed as
/// extract_collection computes it (its content hash included) and appended
/// to the collection file `shard` in the order claimed, with checkpoints as
/// in extract_collection. The shard keeps the entries it already holds (a
/// killed process's shard is resumed). Nothing is checked nor locked here:
/// the process that hands the inputs out does that for the whole job
/// (shard_merge.h). Throws Error when the shard cannot be written, and what
/// `claim` throws.
ExtractionSummary extract_shard(const std::vector<MeshInput>& inputs, const std::vector<PsbClass>& classes,
                                const std::filesystem::path& shard, const InputClaim& claim,
                                const ExtractionOptions& options);

}  // namespace reebkit

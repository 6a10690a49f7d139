#include "reebkit/collection/extract_collection.h"

#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/content_hash.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/file_lock.h"
#include "reebkit/io/json_writer.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/store/collection_file.h"

#include <omp.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <sstream>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <variant>

namespace reebkit {
namespace {

/// The entry of one mesh, its file read once (parsed and hashed); any
/// exception becomes a failed entry, with the hash of the file when it
/// could be read (0 otherwise), so that --resume skips it while it stays
/// the same.
GraphRecord compute_entry(const MeshInput& input, const std::string& class_label, const AnalysisOptions& options) {
  std::uint64_t hash = 0;
  try {
    GraphRecord entry = analyze_mesh_file(input.path, input.name, options, &hash);
    entry.class_label = class_label;
    return entry;
  } catch (const std::exception& e) {
    return failed_graph_record(input.name, class_label, hash, e.what());
  }
}

/// The writer's side: appends entries, checkpoints, counts and reports.
class EntrySink {
 public:
  EntrySink(CollectionWriter& writer, const ExtractionOptions& options, ExtractionSummary& summary,
            ProgressState& progress, const Timer& clock)
      : writer_(writer), options_(options), summary_(summary), progress_(progress), clock_(clock) {}

  void write(GraphRecord entry) {
    if (entry.ok) {
      ++summary_.ok;
      ++progress_.ok;
    } else {
      summary_.failed.push_back({entry.name, entry.error});
      ++progress_.failed;
    }
    timed([&] { writer_.append(std::move(entry)); });
    if (++since_checkpoint_ >= options_.checkpoint_entries ||
        clock_.elapsed() - last_checkpoint_ >= options_.checkpoint_seconds * 1000)
      checkpoint();
    progress_.seconds = clock_.elapsed() / 1000;
    if (options_.progress) options_.progress(progress_);
  }

  void checkpoint() {
    timed([&] { writer_.checkpoint(); });
    since_checkpoint_ = 0;
    last_checkpoint_ = clock_.elapsed();
  }

  template <typename F>
  void timed(F&& f) {
    Timer t;
    f();
    summary_.write_seconds += t.lap() / 1000;
  }

 private:
  CollectionWriter& writer_;
  const ExtractionOptions& options_;
  ExtractionSummary& summary_;
  ProgressState& progress_;
  const Timer& clock_;
  int since_checkpoint_ = 0;
  double last_checkpoint_ = 0;
};

/// Computes the entries of the jobs `claim()` hands out (it returns the next
/// job, or none when there is no job left) with `workers` OpenMP threads
/// and hands them to `sink` in claim order from the calling thread (OpenMP
/// thread 0), which does no computing: the HDF5 calls all come from it.
/// `claim` is called under a lock, so never concurrently, and not again
/// once it returned none. A worker runs at most `window` entries ahead of
/// the writer, which bounds memory.
template <typename Claim, typename Compute>
void compute_in_order(Claim claim, int workers, std::size_t window, Compute compute, EntrySink& sink) {
  std::vector<std::optional<GraphRecord>> ring(window);
  std::mutex mutex;
  std::condition_variable ready, space;
  // guarded by mutex:
  std::size_t written = 0;  // entries taken by the writer
  std::size_t claimed = 0;  // jobs claimed by the workers
  bool exhausted = false;   // claim() returned none: `claimed` is the number of entries
  bool abort = false;       // the writer failed: workers stop
  std::exception_ptr error;

#pragma omp parallel num_threads(workers + 1)
  {
    if (omp_get_thread_num() == 0) {
      try {
        if (omp_get_num_threads() == 1) {  // no thread to spare: compute and write in turn
          for (auto job = claim(); job; job = claim()) sink.write(compute(*job));
        } else {
          for (std::size_t k = 0;; ++k) {
            GraphRecord entry;
            {
              std::unique_lock<std::mutex> lock(mutex);
              ready.wait(lock, [&] { return abort || ring[k % window].has_value() || (exhausted && k == claimed); });
              if (abort || !ring[k % window]) break;
              entry = std::move(*ring[k % window]);
              ring[k % window].reset();
              written = k + 1;
            }
            space.notify_all();
            sink.write(std::move(entry));
          }
        }
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        abort = true;
      }
      space.notify_all();
    } else {
      // Dynamic schedule: each worker claims the next job when it is free.
      try {
        for (;;) {
          std::size_t k = 0;
          decltype(claim()) job;
          {
            std::unique_lock<std::mutex> lock(mutex);
            space.wait(lock, [&] { return abort || exhausted || claimed < written + window; });
            if (abort || exhausted) break;
            job = claim();
            if (job)
              k = claimed++;
            else
              exhausted = true;
          }
          if (!job) {
            ready.notify_one();
            space.notify_all();
            break;
          }
          GraphRecord entry = compute(*job);
          {
            const std::lock_guard<std::mutex> lock(mutex);
            ring[k % window] = std::move(entry);
          }
          ready.notify_one();
        }
      } catch (...) {  // claim() failed: the writer and the other workers stop
        {
          const std::lock_guard<std::mutex> lock(mutex);
          if (!error) error = std::current_exception();
          abort = true;
        }
        ready.notify_one();
        space.notify_all();
      }
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace

std::uint64_t input_hash(const MeshInput& input) {
  try {
    return content_hash(input.path);
  } catch (const std::exception&) {
    return 0;
  }
}

std::vector<std::uint64_t> hash_inputs(const std::vector<MeshInput>& inputs, int threads) {
  std::vector<std::uint64_t> hashes(inputs.size(), 0);
  const auto n = static_cast<std::ptrdiff_t>(inputs.size());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    hashes[static_cast<std::size_t>(i)] = input_hash(inputs[static_cast<std::size_t>(i)]);
  return hashes;
}

void refuse_other_analysis(const std::filesystem::path& path, const Provenance& indexed,
                           const AnalysisOptions& analysis) {
  const std::vector<OptionDifference> differences =
      analysis_option_differences(analysis_options_from(indexed.analysis_options), analysis);
  if (differences.empty()) return;
  std::string message = path.string() + ": cannot resume: the file was indexed with other analysis options:";
  for (const OptionDifference& d : differences)
    message += "\n  " + d.name + ": " + d.first + " in the file, " + d.second + " now";
  throw Error(message + "\n(resume with the file's options, or index into a new file)");
}

bool opens_as_collection(const std::filesystem::path& path) {
  try {
    const CollectionReader reader(path);
    return true;
  } catch (const Error&) {
    return false;
  }
}

void check_extraction(const std::vector<MeshInput>& inputs, const std::vector<PsbClass>& classes,
                      const std::filesystem::path& output, const ExtractionOptions& options) {
  if (options.batch_size < 1) throw InvalidArgument("extract_collection: batch_size must be >= 1");
  if (options.threads < 0) throw InvalidArgument("extract_collection: threads must be >= 0");
  if (!(options.checkpoint_seconds >= 0)) throw InvalidArgument("extract_collection: checkpoint_seconds must be >= 0");
  if (!options.analysis.reeb_graph) throw InvalidArgument("extract_collection: the analysis must build the Reeb graph");
  if (inputs.empty())
    throw InvalidArgument(output.string() + ": no mesh to index (the inputs hold no .off .obj .ply or .stl file)");
  check_analysis_options(options.analysis);
  std::vector<std::filesystem::path> input_files;
  for (const MeshInput& input : inputs) input_files.push_back(input.path);
  if (!options.classes_file.empty()) input_files.emplace_back(options.classes_file);
  check_output_file(output, input_files);
  if (classes.empty() || inputs.empty()) return;
  const ClassMap class_of_model = class_map(classes);
  for (const MeshInput& input : inputs)
    if (!class_of(class_of_model, input.name).empty()) return;
  std::size_t models = 0;
  for (const PsbClass& c : classes) models += c.models.size();
  throw InvalidArgument((options.classes_file.empty() ? std::string("the classes") : options.classes_file) +
                        ": none of its " + std::to_string(models) + " models names one of the " +
                        std::to_string(inputs.size()) + " input meshes (e.g. the mesh '" + inputs.front().name +
                        "'; a model id is a mesh's name, with or without extension, or its file name without "
                        "extension)");
}

Provenance extraction_provenance(const std::vector<PsbClass>& classes, const ExtractionOptions& options) {
  Provenance provenance;
  provenance.options = analysis_options_json(options.analysis);
  provenance.analysis_options = named_analysis_options(options.analysis);
  provenance.command = options.command;
  provenance.classes = classes;
  provenance.classes_file = options.classes_file;
  return provenance;
}

std::string analysis_options_json(const AnalysisOptions& options) {
  std::ostringstream text;
  JsonWriter json(text);
  json.begin_object();
  // The table's options by their names (analysis_options.h), then the two it leaves out.
  for (const NamedOption& option : named_analysis_options(options)) {
    json.key(option.name);
    std::visit(
        [&json](const auto& value) {
          if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::int64_t>)
            json.value(static_cast<long long>(value));
          else
            json.value(value);
        },
        option.value);
  }
  json.field("all_components", options.reeb.all_components).field("reeb_graph", options.reeb_graph).end_object();
  // One line for the file attribute: drop the writer's line breaks and indentation.
  std::string compact;
  bool indent = false;
  for (const char c : text.str()) {
    indent = c == '\n' || (indent && c == ' ');
    if (!indent) compact += c;
  }
  return compact;
}

ExtractionSummary extract_collection(const std::vector<MeshInput>& inputs, const std::vector<PsbClass>& classes,
                                     const std::filesystem::path& requested, const ExtractionOptions& options) {
  const std::filesystem::path output = resolved_output(requested);  // a link: its file is locked and replaced
  check_extraction(inputs, classes, output, options);
  const FileLock lock(output);
  // A new collection is written into OUTPUT.partial, renamed over OUTPUT at
  // the end; resume goes on in place, in OUTPUT.partial when an interrupted
  // run left one.
  const std::filesystem::path partial = output.string() + ".partial";
  if (options.resume && std::filesystem::exists(partial) && !opens_as_collection(partial))
    std::filesystem::remove(partial);  // killed while being created, before its first checkpoint: no entry in it
  const bool resume_partial = options.resume && std::filesystem::exists(partial);
  const bool in_place = options.resume && !resume_partial && std::filesystem::exists(output);
  const std::filesystem::path target = in_place ? output : partial;
  const bool resume = options.resume && std::filesystem::exists(target);

  Provenance provenance = extraction_provenance(classes, options);
  if (resume) {
    const Provenance indexed = CollectionReader(target).provenance();
    refuse_other_analysis(target, indexed, options.analysis);
    if (classes.empty()) {  // resume keeps the file's classes unless given others
      provenance.classes = indexed.classes;
      provenance.classes_file = indexed.classes_file;
    }
  }
  const Timer clock;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  ExtractionSummary summary;
  ProgressState progress;
  progress.total = static_cast<std::int64_t>(inputs.size());
  const ClassMap class_of_model = class_map(provenance.classes);

  // Resume: which entries of the file stay, and whether stale ones (or new
  // classes for every entry) force a rewrite. Only the inputs the file
  // already holds are hashed here, to tell which changed; every other file
  // is read once, when it is analysed (compute_entry hashes those bytes).
  std::unordered_map<std::string, std::uint64_t> kept;
  bool rewrite = false;
  Timer open_time;
  auto writer = std::make_unique<CollectionWriter>(target, provenance, resume);
  std::unordered_map<std::string, std::uint64_t> current;  // input name -> hash, for the names the file holds
  {
    std::unordered_set<std::string> held;
    for (const auto& entry : writer->existing()) held.insert(entry.first);
    std::vector<MeshInput> to_hash;
    for (const MeshInput& input : inputs)
      if (held.count(input.name)) to_hash.push_back(input);
    const std::vector<std::uint64_t> hashes = hash_inputs(to_hash, threads);
    for (std::size_t i = 0; i < to_hash.size(); ++i) current.emplace(to_hash[i].name, hashes[i]);
  }
  for (const auto& [name, hash] : writer->existing()) {
    const auto it = current.find(name);
    if (it != current.end() && it->second != hash)
      rewrite = true;
    else
      kept.emplace(name, hash);
  }
  const bool relabel = resume && !classes.empty() && !writer->existing().empty();
  summary.write_seconds += open_time.lap() / 1000;
  const std::filesystem::path rewritten = target.string() + ".rewrite";
  if (rewrite || relabel) {
    writer->close();
    writer.reset();
    const CollectionReader old(target);
    writer = std::make_unique<CollectionWriter>(rewritten, provenance, false);
    for (std::int64_t i = 0; i < old.size(); ++i) {
      const std::string& name = old.names()[static_cast<std::size_t>(i)];
      if (kept.count(name) == 0) continue;
      GraphRecord entry = old.entry(i);
      if (relabel) entry.class_label = class_of(class_of_model, name);
      writer->append(std::move(entry));
    }
    writer->checkpoint();
    summary.write_seconds += open_time.lap() / 1000;
  }
  summary.kept = static_cast<std::int64_t>(kept.size());

  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto it = kept.find(inputs[i].name);
    const auto now = current.find(inputs[i].name);
    if (it != kept.end() && now != current.end() && it->second == now->second)
      ++summary.skipped;
    else
      todo.push_back(i);
  }
  progress.skipped = summary.skipped;

  EntrySink sink(*writer, options, summary, progress, clock);
  std::size_t next = 0;  // todo[next] is the next input to start
  try {
    compute_in_order(
        [&]() -> std::optional<std::size_t> {
          if (next == todo.size() || (options.stop != nullptr && options.stop->load())) return std::nullopt;
          return todo[next++];
        },
        threads, static_cast<std::size_t>(options.batch_size),
        [&](std::size_t i) {
          return compute_entry(inputs[i], class_of(class_of_model, inputs[i].name), options.analysis);
        },
        sink);
    sink.timed([&] { writer->close(); });
  } catch (const Error& e) {
    if (rewrite || relabel) {  // the rewritten copy is dropped: the file stays as it was
      std::error_code ignored;
      std::filesystem::remove(rewritten, ignored);
      throw Error(std::string(e.what()) + "\n" + target.string() +
                  " is left as it was: reeb index --resume starts the update again");
    }
    const std::string previous =
        target == output
            ? ""
            : output.string() + (std::filesystem::exists(output) ? " is left as it was; " : " is not written; ");
    throw Error(std::string(e.what()) + "\n" + previous + target.string() +
                " holds the entries of the last checkpoint: reeb index --resume goes on from there");
  }
  if (rewrite || relabel) std::filesystem::rename(rewritten, target);
  summary.interrupted = next < todo.size();
  if (summary.interrupted) {  // a new collection stays OUTPUT.partial: --resume completes it
    summary.file = target;
    summary.seconds = clock.elapsed() / 1000;
    return summary;
  }
  // A run in which every mesh failed leaves OUTPUT as it was (a collection
  // of failures only is no result, and a bad option must not replace one).
  summary.all_failed = summary.ok == 0 && !summary.failed.empty() && summary.kept == 0;
  if (summary.all_failed && target != output)
    std::filesystem::remove(target);
  else if (target != output)
    std::filesystem::rename(target, output);
  summary.file = output;
  summary.seconds = clock.elapsed() / 1000;
  progress.seconds = summary.seconds;
  if (options.progress && todo.empty()) options.progress(progress);
  return summary;
}

ExtractionSummary extract_shard(const std::vector<MeshInput>& inputs, const std::vector<PsbClass>& classes,
                                const std::filesystem::path& shard, const InputClaim& claim,
                                const ExtractionOptions& options) {
  const Timer clock;
  ExtractionSummary summary;
  ProgressState progress;
  progress.total = static_cast<std::int64_t>(inputs.size());
  const ClassMap class_of_model = class_map(classes);
  Timer open_time;
  CollectionWriter writer(shard, extraction_provenance(classes, options), true);
  summary.kept = static_cast<std::int64_t>(writer.existing().size());
  summary.write_seconds += open_time.lap() / 1000;
  EntrySink sink(writer, options, summary, progress, clock);
  compute_in_order(
      [&]() -> std::optional<std::size_t> {
        const std::optional<std::size_t> i = claim();
        if (i && *i >= inputs.size())
          throw InvalidArgument(shard.string() + ": claimed input " + std::to_string(*i) + " of " +
                                std::to_string(inputs.size()));
        return i;
      },
      options.threads > 0 ? options.threads : omp_get_max_threads(), static_cast<std::size_t>(options.batch_size),
      [&](std::size_t i) {
        return compute_entry(inputs[i], class_of(class_of_model, inputs[i].name), options.analysis);
      },
      sink);
  sink.timed([&] { writer.close(); });
  summary.file = shard;
  summary.seconds = clock.elapsed() / 1000;
  return summary;
}

}  // namespace reebkit

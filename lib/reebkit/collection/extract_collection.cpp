#include "reebkit/collection/extract_collection.h"

#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/content_hash.h"
#include "reebkit/io/json_writer.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/store/collection_file.h"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <sstream>
#include <unordered_map>

namespace reebkit {
namespace {

/// Milliseconds since construction.
class Stopwatch {
 public:
  double elapsed() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// The entry of one mesh; any exception becomes a failed entry.
GraphRecord compute_entry(const MeshInput& input, std::uint64_t hash, const std::string& class_label,
                          const AnalysisOptions& options) {
  try {
    GraphRecord entry = analyze_mesh_file(input.path, input.name, options);
    entry.class_label = class_label;
    entry.content_hash = hash;
    return entry;
  } catch (const std::exception& e) {
    return failed_graph_record(input.name, class_label, hash, e.what());
  }
}

/// The writer's side: appends entries, checkpoints, counts and reports.
class EntrySink {
 public:
  EntrySink(CollectionWriter& writer, const ExtractionOptions& options, ExtractionSummary& summary,
            ProgressState& progress, const Stopwatch& clock)
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
  const Stopwatch& clock_;
  int since_checkpoint_ = 0;
  double last_checkpoint_ = 0;
};

/// Computes entries todo[0..] with `workers` OpenMP threads and hands them
/// to `sink` in order from the calling thread (OpenMP thread 0), which does
/// no computing: the HDF5 calls all come from it. A worker runs at most
/// `window` entries ahead of the writer, which bounds memory.
template <typename Compute>
void compute_in_order(std::size_t count, int workers, std::size_t window, Compute compute, EntrySink& sink) {
  std::vector<std::optional<GraphRecord>> ring(window);
  std::mutex mutex;
  std::condition_variable ready, space;
  std::size_t written = 0;  // entries taken by the writer (guarded by mutex)
  bool abort = false;       // the writer failed: workers stop (guarded by mutex)
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;

#pragma omp parallel num_threads(workers + 1)
  {
    if (omp_get_thread_num() == 0) {
      const bool alone = omp_get_num_threads() == 1;  // no thread to spare: compute and write in turn
      try {
        for (std::size_t k = 0; k < count; ++k) {
          if (alone) {
            sink.write(compute(k));
            continue;
          }
          GraphRecord entry;
          {
            std::unique_lock<std::mutex> lock(mutex);
            ready.wait(lock, [&] { return ring[k % window].has_value(); });
            entry = std::move(*ring[k % window]);
            ring[k % window].reset();
            written = k + 1;
          }
          space.notify_all();
          sink.write(std::move(entry));
        }
      } catch (...) {
        error = std::current_exception();
        const std::lock_guard<std::mutex> lock(mutex);
        abort = true;
      }
      space.notify_all();
    } else {
      // Dynamic schedule: each worker takes the next mesh when it is free.
      for (std::size_t k = next++; k < count; k = next++) {
        {
          std::unique_lock<std::mutex> lock(mutex);
          space.wait(lock, [&] { return abort || k < written + window; });
          if (abort) break;
        }
        GraphRecord entry = compute(k);
        {
          const std::lock_guard<std::mutex> lock(mutex);
          ring[k % window] = std::move(entry);
        }
        ready.notify_one();
      }
    }
  }
  if (error) std::rethrow_exception(error);
}

/// Content hashes of the inputs, read in parallel; 0 for a file that cannot
/// be read (load_mesh then reports why).
std::vector<std::uint64_t> hash_inputs(const std::vector<MeshInput>& inputs, int threads) {
  std::vector<std::uint64_t> hashes(inputs.size(), 0);
  const auto n = static_cast<std::ptrdiff_t>(inputs.size());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    try {
      hashes[static_cast<std::size_t>(i)] = content_hash(inputs[static_cast<std::size_t>(i)].path);
    } catch (const std::exception&) {
      hashes[static_cast<std::size_t>(i)] = 0;
    }
  }
  return hashes;
}

/// Throws Error unless the collection file `path` was analysed with `analysis`.
void refuse_other_analysis(const std::filesystem::path& path, const AnalysisOptions& analysis) {
  const AnalysisOptions indexed = analysis_options_from(CollectionReader(path).provenance().analysis_options);
  const std::vector<OptionDifference> differences = analysis_option_differences(indexed, analysis);
  if (differences.empty()) return;
  std::string message = path.string() + ": cannot resume: the file was indexed with other analysis options:";
  for (const OptionDifference& d : differences)
    message += "\n  " + d.name + ": " + d.first + " in the file, " + d.second + " now";
  throw Error(message + "\n(resume with the file's options, or index into a new file)");
}

}  // namespace

std::string analysis_options_json(const AnalysisOptions& options) {
  std::ostringstream text;
  JsonWriter json(text);
  json.begin_object();
  json.key("holes").begin_object().field("max_loop_length", options.holes.max_loop_length).end_object();
  json.key("features")
      .begin_object()
      .field("epsilon", options.features.epsilon)
      .field("start_vertex", static_cast<long long>(options.features.start_vertex))
      .field("max_extra_sweeps", options.features.max_extra_sweeps)
      .field("extra_seeds", options.features.extra_seeds)
      .field("geodesic", geodesic_name(options.features.geodesic))
      .field("min_persistence", options.features.min_persistence)
      .end_object();
  json.key("reeb")
      .begin_object()
      .field("level_lines", level_lines_name(options.reeb.level_lines))
      .field("all_components", options.reeb.all_components)
      .field("skeleton_levels", static_cast<long long>(options.reeb.skeleton_levels))
      .end_object();
  json.field("reeb_graph", options.reeb_graph).end_object();
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
                                     const std::filesystem::path& output, const ExtractionOptions& options) {
  if (options.batch_size < 1) throw InvalidArgument("extract_collection: batch_size must be >= 1");
  if (options.threads < 0) throw InvalidArgument("extract_collection: threads must be >= 0");
  if (!options.analysis.reeb_graph) throw InvalidArgument("extract_collection: the analysis must build the Reeb graph");
  if (options.resume && std::filesystem::exists(output)) refuse_other_analysis(output, options.analysis);
  const Stopwatch clock;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  ExtractionSummary summary;
  ProgressState progress;
  progress.total = static_cast<std::int64_t>(inputs.size());

  Provenance provenance;
  provenance.options = analysis_options_json(options.analysis);
  provenance.analysis_options = named_analysis_options(options.analysis);
  provenance.command = options.command;
  provenance.classes = classes;
  provenance.classes_file = options.classes_file;
  const ClassMap class_of_model = class_map(classes);

  const std::vector<std::uint64_t> hashes = hash_inputs(inputs, threads);
  std::unordered_map<std::string, std::uint64_t> current;  // input name -> hash
  for (std::size_t i = 0; i < inputs.size(); ++i) current.emplace(inputs[i].name, hashes[i]);

  // Resume: which entries of the file stay, and whether stale ones force a rewrite.
  std::unordered_map<std::string, std::uint64_t> kept;
  bool rewrite = false;
  Timer open_time;
  auto writer = std::make_unique<CollectionWriter>(output, provenance, options.resume);
  for (const auto& [name, hash] : writer->existing()) {
    const auto it = current.find(name);
    if (it != current.end() && it->second != hash)
      rewrite = true;
    else
      kept.emplace(name, hash);
  }
  summary.write_seconds += open_time.lap() / 1000;
  const std::filesystem::path rewritten = output.string() + ".rewrite";
  if (rewrite) {
    writer->close();
    writer.reset();
    const CollectionReader old(output);
    writer = std::make_unique<CollectionWriter>(rewritten, provenance, false);
    for (std::int64_t i = 0; i < old.size(); ++i) {
      const std::string& name = old.names()[static_cast<std::size_t>(i)];
      if (kept.count(name) != 0) writer->append(old.entry(i));
    }
    writer->checkpoint();
    summary.write_seconds += open_time.lap() / 1000;
  }
  summary.kept = static_cast<std::int64_t>(kept.size());

  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto it = kept.find(inputs[i].name);
    if (it != kept.end() && it->second == hashes[i])
      ++summary.skipped;
    else
      todo.push_back(i);
  }
  progress.skipped = summary.skipped;

  EntrySink sink(*writer, options, summary, progress, clock);
  compute_in_order(
      todo.size(), threads, static_cast<std::size_t>(options.batch_size),
      [&](std::size_t k) {
        const MeshInput& input = inputs[todo[k]];
        return compute_entry(input, hashes[todo[k]], class_of(class_of_model, input.name), options.analysis);
      },
      sink);
  sink.timed([&] { writer->close(); });
  if (rewrite) std::filesystem::rename(rewritten, output);
  summary.seconds = clock.elapsed() / 1000;
  progress.seconds = summary.seconds;
  if (options.progress && todo.empty()) options.progress(progress);
  return summary;
}

}  // namespace reebkit

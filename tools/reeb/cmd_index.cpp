// reeb index INPUT... -o collection.h5: the attributed Reeb graph of every
// mesh of a collection in one HDF5 file (docs/command-line.md, "Indexing a collection").
#include "reeb/cli.h"
#include "reeb/cluster.h"
#include "reebkit/collection/extract_collection.h"
#include "reebkit/retrieval/query.h"

#include <time.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>

namespace reebkit::cli {

namespace {

// Ctrl-C (SIGINT) or SIGTERM: the run stops starting meshes, writes the ones
// in progress and ends durable (ExtractionOptions::stop). A second signal a
// second or more later ends the process at once, as without the handler (the
// file then holds the entries of its last checkpoint); one sooner is the
// same request delivered twice (timeout(1) signals the process and then its
// group). Either way --resume completes the file.
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<std::int64_t>::is_always_lock_free,
              "set from a signal handler");
std::atomic<bool> stop_requested{false};
std::atomic<std::int64_t> first_request_ns{0};

std::int64_t monotonic_ns() {  // clock_gettime is async-signal-safe
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<std::int64_t>(now.tv_sec) * 1000000000 + now.tv_nsec;
}

extern "C" void request_stop(int signal) {
  if (!stop_requested.exchange(true)) {
    first_request_ns.store(monotonic_ns());
    constexpr char kMessage[] =
        "\nreeb index: stopping: the meshes in progress are finished and written (again to stop at once)\n";
    [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  } else if (monotonic_ns() - first_request_ns.load() >= 1000000000) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}

}  // namespace

int run_index(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::vector<std::string> inputs;
  std::string output, classes_path;
  ExtractionOptions extraction;
  bool allow_failures = false;
  options.add_options()(
      "input", po::value(&inputs)->required()->multitoken(),
      "a folder (searched recursively for .off .obj .ply .stl), a list file (.txt .lst, one path a line) "
      "or mesh files")("output,o", po::value(&output)->required(), "the collection file to write (HDF5)")(
      "classes", po::value(&classes_path),
      "class labels from a PSB .cla file (model id = file name without extension)")(
      "threads", po::value(&extraction.threads)->default_value(0)->notifier([](int n) {
        if (n < 0) throw po::error("--threads must be >= 0");
      }),
      "worker threads (0: as many as OpenMP offers)")(
      "checkpoint-seconds",
      po::value(&extraction.checkpoint_seconds)->default_value(extraction.checkpoint_seconds)->notifier([](double s) {
        if (!(s >= 0)) throw po::error("--checkpoint-seconds must be a number >= 0");
      }),
      "make the file (under MPI: each process's shard) durable at least this often: what an interruption loses")(
      "resume", po::bool_switch(&extraction.resume),
      "keep the entries already in the file and compute only new or changed meshes (content hash); the "
      "analysis options must be the file's")("allow-failures", po::bool_switch(&allow_failures),
                                             "exit 0 when some meshes failed (they are failed entries of the file), "
                                             "for batch use; a run in which "
                                             "every mesh failed still exits 1");
  options.add(analysis_options(extraction.analysis));
  po::positional_options_description positional;
  positional.add("input", -1);
  po::variables_map vm;
  if (!parse(args,
             "reeb index INPUT... -o collection.h5 [--classes FILE.cla] [--threads N] [--checkpoint-seconds S] "
             "[--resume] "
             "[--allow-failures] "
             "[analysis options]",
             options, positional, vm))
    return 0;

  const std::vector<MeshInput> meshes = list_mesh_inputs(inputs);
  const std::vector<PsbClass> classes = classes_path.empty() ? std::vector<PsbClass>{} : read_psb_classes(classes_path);
  extraction.classes_file = classes_path;
  extraction.command = "reeb index";
  for (const std::string& a : args) extraction.command += " " + a;
  ProgressBar bar = ProgressBar::for_stderr();
  // Under mpirun or srun: every process computes, process 0 hands the meshes
  // out, merges the shards and reports (docs/cluster.md).
  const bool cluster = launched_by_mpi();
  std::optional<ExtractionSummary> result;
  if (cluster) {
    result = extract_collection_on_cluster(meshes, classes, output, extraction);
    if (!result) return 0;  // not process 0: it reports for the job
  } else {
    extraction.progress = [&bar](const ProgressState& state) { bar(state); };
    check_extraction(meshes, classes, output, extraction);  // a refusal before the announcement
    std::cerr << "indexing " << meshes.size() << " meshes into " << output << "\n";
    extraction.stop = &stop_requested;
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    result = extract_collection(meshes, classes, output, extraction);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
  const ExtractionSummary& summary = *result;
  const auto failed = static_cast<std::int64_t>(summary.failed.size());
  ProgressState done;
  done.total = static_cast<std::int64_t>(meshes.size());
  done.ok = summary.ok;
  done.failed = failed;
  done.skipped = summary.skipped;
  done.seconds = summary.seconds;
  bar.finish(done);
  for (const FailedMesh& f : summary.failed) std::cerr << "failed: " << f.name << ": " << f.reason << "\n";
  std::cerr << std::fixed << std::setprecision(2) << (cluster ? "merging the shards: " : "writing the file: ")
            << summary.write_seconds << " s ("
            << (summary.seconds > 0 ? 100 * summary.write_seconds / summary.seconds : 0.0) << " % of the time)\n"
            << std::defaultfloat;
  if (summary.interrupted) {
    std::cerr << "reeb index: interrupted: " << summary.file.string() << " holds " << summary.entries()
              << " entries; the same command with --resume computes the "
              << static_cast<std::int64_t>(meshes.size()) - summary.skipped - summary.computed()
              << " meshes not started\n";
    return 130;  // 128 + SIGINT, as a shell reports a run stopped by Ctrl-C
  }
  if (summary.all_failed) {
    std::cerr << "reeb index: error: every mesh failed (" << failed << "): " << output
              << (std::filesystem::exists(output) ? " left as it was" : " not written") << "\n";
    return 1;
  }
  std::cerr << "wrote " << output << "\n";
  // What a query reads instead of the whole collection (docs/collection-file.md, "The query file").
  write_query_file(CollectionReader(output));
  std::cerr << "wrote " << QueryFile::path_of(output).string() << "\n";
  if (failed == 0 || allow_failures) return 0;
  std::cerr << "reeb index: error: " << failed << " of " << summary.computed()
            << " meshes failed (failed entries of the file; --allow-failures to exit 0)\n";
  return 1;
}

}  // namespace reebkit::cli

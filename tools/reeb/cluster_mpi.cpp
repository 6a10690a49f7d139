// The MPI side of reeb index and reeb distances (cluster.h). Only this file
// calls MPI. A process waiting for a message polls and sleeps instead of
// blocking in MPI: Open MPI's blocking calls spin, and a spinning process
// takes a core from the workers computing beside it.
#include "reeb/cluster.h"

#include "reebkit/collection/shard_merge.h"
#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/file_lock.h"

#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <deque>
#include <exception>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace reebkit::cli {
namespace {

constexpr int kTagRequest = 1;  // a process asks process 0 for an input
constexpr int kTagInput = 2;    // process 0's answer: an input index, -1 for none left
constexpr int kTagDone = 3;     // a process has all its answers and asks no more
constexpr int kTagBlock = 4;    // a block of distances
constexpr auto kPoll = std::chrono::microseconds(1000);
/// Values per message (MPI counts are int).
constexpr std::int64_t kPiece = std::int64_t{1} << 24;

/// Waits for `request` without spinning: polls, sleeping from 20 us up to
/// kPoll between polls.
void wait(MPI_Request& request, MPI_Status* status = MPI_STATUS_IGNORE) {
  auto pause = std::chrono::microseconds(20);
  for (int done = 0;;) {
    MPI_Test(&request, &done, status);
    if (done) return;
    std::this_thread::sleep_for(pause);
    pause = std::min<std::chrono::microseconds>(2 * pause, kPoll);
  }
}

/// MPI for the life of one command: initialised (threads serialized: a
/// worker thread asks for inputs) and finalised at the end. A failure on one
/// process aborts the job: the others may be waiting for it.
class MpiJob {
 public:
  MpiJob() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    if (provided < MPI_THREAD_SERIALIZED)
      fail("this MPI library does not let threads call it in turn (MPI_THREAD_SERIALIZED)");
  }
  ~MpiJob() { MPI_Finalize(); }
  MpiJob(const MpiJob&) = delete;
  MpiJob& operator=(const MpiJob&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Runs `body`; an exception aborts the whole job.
  template <typename Body>
  auto run(Body&& body) {
    try {
      return body();
    } catch (const std::exception& e) {
      fail(e.what());
    }
  }

  [[noreturn]] void fail(const std::string& message) const {
    std::cerr << "reeb: error (process " << rank_ << " of " << size_ << "): " << message << "\n" << std::flush;
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::abort();  // MPI_Abort does not return
  }

  /// Every process's `values` (the same count on each), in rank order, on
  /// process 0; empty on the others. Also a barrier for process 0.
  std::vector<double> gather(std::vector<double> values) const {
    std::vector<double> all(rank_ == 0 ? values.size() * static_cast<std::size_t>(size_) : 0);
    MPI_Request request;
    MPI_Igather(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(), static_cast<int>(values.size()),
                MPI_DOUBLE, 0, MPI_COMM_WORLD, &request);
    wait(request);
    return all;
  }

  /// Process 0's `value` on every process.
  int broadcast(int value) const {
    MPI_Request request;
    MPI_Ibcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
    wait(request);
    return value;
  }

 private:
  int rank_ = 0;
  int size_ = 1;
};

/// Inputs in one answer at most.
constexpr std::size_t kMaxChunk = 64;

/// The meshes still to hand out (process 0), for its own workers one at a
/// time and for the other processes in chunks.
class InputQueue {
 public:
  InputQueue(const std::vector<std::size_t>& todo, int processes)
      : todo_(todo), processes_(static_cast<std::size_t>(processes)) {}

  std::optional<std::size_t> take() {
    const std::lock_guard<std::mutex> hold(mutex_);
    if (next_ == todo_.size()) return std::nullopt;
    return todo_[next_++];
  }

  /// The next inputs for another process: a chunk that shrinks with what is
  /// left (guided self-scheduling: a quarter of a process's share, 1 to
  /// kMaxChunk), so that the requests are few while much is left and the
  /// processes end together. Empty: none left.
  std::vector<std::size_t> take_chunk() {
    const std::lock_guard<std::mutex> hold(mutex_);
    const std::size_t left = todo_.size() - next_;
    const std::size_t count = std::min(left, std::clamp<std::size_t>(left / (4 * processes_), 1, kMaxChunk));
    std::vector<std::size_t> chunk(todo_.begin() + static_cast<std::ptrdiff_t>(next_),
                                   todo_.begin() + static_cast<std::ptrdiff_t>(next_ + count));
    next_ += count;
    return chunk;
  }

 private:
  const std::vector<std::size_t>& todo_;
  std::size_t processes_;
  std::mutex mutex_;
  std::size_t next_ = 0;
};

/// Process 0: answers the other processes' requests for inputs with chunks
/// of `queue` until each of them said it asks no more.
void serve_inputs(InputQueue& queue, int others) {
  while (others > 0) {
    std::int64_t message = 0;
    MPI_Request receive;
    MPI_Irecv(&message, 1, MPI_INT64_T, MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &receive);
    MPI_Status status;
    wait(receive, &status);
    if (status.MPI_TAG == kTagDone) {
      --others;
      continue;
    }
    std::vector<std::int64_t> answer;  // the inputs; none: none left
    for (const std::size_t input : queue.take_chunk()) answer.push_back(static_cast<std::int64_t>(input));
    MPI_Request send;
    MPI_Isend(answer.data(), static_cast<int>(answer.size()), MPI_INT64_T, status.MPI_SOURCE, kTagInput, MPI_COMM_WORLD,
              &send);
    wait(send);
  }
}

/// Another process than 0: the inputs process 0 hands out. `depth` requests
/// are kept out (one per worker thread), so that the answers travel while
/// the workers compute; MPI delivers them in the order asked.
class InputRequests {
 public:
  explicit InputRequests(int depth) : depth_(static_cast<std::size_t>(std::max(1, depth))) {}

  std::optional<std::size_t> operator()() {
    while (!exhausted_ && out_.size() < depth_) post();
    while (ready_.empty()) {
      if (out_.empty()) return std::nullopt;
      Request& first = *out_.front();
      wait(first.send);
      MPI_Status status;
      wait(first.receive, &status);
      int count = 0;
      MPI_Get_count(&status, MPI_INT64_T, &count);
      for (int k = 0; k < count; ++k)
        ready_.push_back(static_cast<std::size_t>(first.answer[static_cast<std::size_t>(k)]));
      out_.pop_front();
      if (count == 0) exhausted_ = true;  // the requests still out get the same answer
      if (!exhausted_) post();
    }
    const std::size_t input = ready_.front();
    ready_.pop_front();
    return input;
  }

  /// Takes the answers still out (none left) and tells process 0 that this
  /// process asks no more.
  void finish() {
    for (const auto& request : out_) {
      wait(request->send);
      wait(request->receive);
    }
    out_.clear();
    std::int64_t done = 0;
    MPI_Request send;
    MPI_Isend(&done, 1, MPI_INT64_T, 0, kTagDone, MPI_COMM_WORLD, &send);
    wait(send);
  }

 private:
  struct Request {  // MPI holds the buffers' addresses until completion
    std::int64_t question = 0;
    std::array<std::int64_t, kMaxChunk> answer{};
    MPI_Request send = MPI_REQUEST_NULL, receive = MPI_REQUEST_NULL;
  };
  void post() {
    auto request = std::make_unique<Request>();
    MPI_Irecv(request->answer.data(), static_cast<int>(kMaxChunk), MPI_INT64_T, 0, kTagInput, MPI_COMM_WORLD,
              &request->receive);
    MPI_Isend(&request->question, 1, MPI_INT64_T, 0, kTagRequest, MPI_COMM_WORLD, &request->send);
    out_.push_back(std::move(request));
  }

  std::size_t depth_;
  std::deque<std::unique_ptr<Request>> out_;
  std::deque<std::size_t> ready_;  // inputs received, not yet claimed
  bool exhausted_ = false;
};

/// Pairs in the upper-triangle rows [first, last) of an n x n matrix.
std::int64_t pairs_in_rows(std::int64_t first, std::int64_t last, std::int64_t n) {
  const auto before = [n](std::int64_t row) { return row * (n - 1) - row * (row - 1) / 2; };
  return before(last) - before(first);
}

/// Wall and CPU time (every thread of the process) since construction.
class Stopwatch {
 public:
  /// `count` things done since construction: {count, wall s, CPU s}.
  std::vector<double> share(std::int64_t count) const {
    return {static_cast<double>(count), wall_.elapsed() / 1000,
            static_cast<double>(std::clock() - cpu_) / CLOCKS_PER_SEC};
  }

 private:
  Timer wall_;
  std::clock_t cpu_ = std::clock();
};

/// Process 0: what each process computed, from the {count, wall s, CPU s}
/// of Stopwatch::share gathered (MpiJob::gather).
void print_shares(const char* what, const std::vector<double>& shares) {
  std::cerr << std::fixed << std::setprecision(2);
  for (std::size_t r = 0; 3 * r < shares.size(); ++r)
    std::cerr << (r == 0 ? "" : "; ") << "process " << r << ": " << static_cast<std::int64_t>(shares[3 * r]) << " "
              << what << " in " << shares[3 * r + 1] << " s (CPU " << shares[3 * r + 2] << " s)";
  std::cerr << std::defaultfloat << "\n";
}

}  // namespace

std::optional<ExtractionSummary> extract_collection_on_cluster(const std::vector<MeshInput>& inputs,
                                                               const std::vector<PsbClass>& classes,
                                                               const std::filesystem::path& requested,
                                                               const ExtractionOptions& options) {
  Timer clock;
  const std::filesystem::path output = resolved_output(requested);  // a link: its file is locked and replaced
  check_extraction(inputs, classes, output, options);  // every process: the same verdict, before MPI starts
  MpiJob mpi;
  // Process 0 holds the lock and plans; a refusal (locked, other analysis
  // options) ends every process cleanly.
  std::unique_ptr<FileLock> lock;
  ShardedJob job;
  std::string refusal;
  if (mpi.rank() == 0) {
    try {
      lock = std::make_unique<FileLock>(output);
      job = plan_sharded_job(inputs, output, options);
    } catch (const std::exception& e) {
      refusal = e.what();
    }
  }
  if (mpi.broadcast(refusal.empty() ? 1 : 0) == 0) {
    if (mpi.rank() == 0) throw Error(refusal);
    return std::nullopt;
  }
  ExtractionOptions shard_options = options;
  shard_options.progress = {};
  return mpi.run([&]() -> std::optional<ExtractionSummary> {
    const std::filesystem::path shard = shard_path(output, mpi.rank());
    const Stopwatch stopwatch;
    if (mpi.rank() != 0) {
      InputRequests requests(options.threads > 0 ? options.threads : omp_get_max_threads());
      const ExtractionSummary done = extract_shard(
          inputs, classes, shard, [&requests] { return requests(); }, shard_options);
      requests.finish();
      mpi.gather(stopwatch.share(done.computed()));  // its shard is closed
      return std::nullopt;
    }
    std::cerr << "indexing " << job.todo.size() << " meshes on " << mpi.size() << " processes"
              << (job.skipped > 0 ? " (" + std::to_string(job.skipped) + " already indexed)" : std::string()) << "\n";
    InputQueue queue(job.todo, mpi.size());
    std::exception_ptr failure;
    ExtractionSummary done;
    std::thread compute([&] {
      try {
        done = extract_shard(
            inputs, classes, shard, [&queue] { return queue.take(); }, shard_options);
      } catch (...) {
        failure = std::current_exception();
      }
    });
    serve_inputs(queue, mpi.size() - 1);
    compute.join();
    if (failure) std::rethrow_exception(failure);
    print_shares("meshes", mpi.gather(stopwatch.share(done.computed())));  // every shard closed
    ExtractionSummary summary = merge_shards(inputs, classes, output, job, options);
    summary.seconds = clock.lap() / 1000;
    return summary;
  });
}

std::optional<PairwiseDistances> all_pairs_on_cluster(const std::vector<GraphRecord>& entries,
                                                      const AllPairsOptions& options) {
  MpiJob mpi;
  return mpi.run([&]() -> std::optional<PairwiseDistances> {
    const auto n = static_cast<std::int64_t>(entries.size());
    const std::vector<std::int64_t> first = balanced_row_blocks(n, mpi.size());
    const auto own = static_cast<std::size_t>(mpi.rank());
    const Stopwatch stopwatch;
    std::vector<double> block = upper_triangle_rows(entries, first[own], first[own + 1], options);
    const std::vector<double> shares = mpi.gather(stopwatch.share(static_cast<std::int64_t>(block.size())));
    if (mpi.rank() != 0) {
      for (std::int64_t at = 0; at < static_cast<std::int64_t>(block.size()); at += kPiece) {
        MPI_Request send;
        MPI_Isend(block.data() + at, static_cast<int>(std::min(kPiece, static_cast<std::int64_t>(block.size()) - at)),
                  MPI_DOUBLE, 0, kTagBlock, MPI_COMM_WORLD, &send);
        wait(send);
      }
      return std::nullopt;
    }
    print_shares("pairs", shares);
    std::vector<double> upper = std::move(block);
    upper.resize(static_cast<std::size_t>(pairs_in_rows(0, n, n)));
    for (int rank = 1; rank < mpi.size(); ++rank) {
      const auto r = static_cast<std::size_t>(rank);
      const std::int64_t start = pairs_in_rows(0, first[r], n), count = pairs_in_rows(first[r], first[r + 1], n);
      for (std::int64_t at = 0; at < count; at += kPiece) {
        MPI_Request receive;
        MPI_Irecv(upper.data() + start + at, static_cast<int>(std::min(kPiece, count - at)), MPI_DOUBLE, rank,
                  kTagBlock, MPI_COMM_WORLD, &receive);
        wait(receive);
      }
    }
    std::vector<std::string> names;
    for (const GraphRecord& e : entries) names.push_back(e.name);
    return matrix_from_upper_triangle(std::move(names), upper);
  });
}

}  // namespace reebkit::cli

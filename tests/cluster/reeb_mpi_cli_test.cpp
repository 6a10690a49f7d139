// reeb index and reeb distances under mpirun (tools/reeb/cluster.h,
// docs/cluster.md): the collection file and the matrix are those of one
// process, whatever the number of processes; a killed process loses only
// what it had not checkpointed, and --resume completes the job. Registered
// only in a build with MPI (REEBKIT_MPI).
#include "io/io_test_util.h"
#include "reebkit/collection/shard_merge.h"
#include "reebkit/store/collection_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

namespace reebkit::test {
namespace {

const std::string kReeb = REEB_BINARY;

/// mpirun starting `processes` processes (as root too), placing more
/// processes than cores when asked or needed.
std::string mpirun(int processes) {
  const bool oversubscribe = processes > static_cast<int>(std::thread::hardware_concurrency());
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 300 " + std::string(MPIEXEC) + " -np " +
         std::to_string(processes) + (oversubscribe ? " --oversubscribe " : " ");
}

/// Runs compare_collections.py (h5py): exit 0 and its output when the two
/// files hold the same content (every dataset but timings).
std::pair<int, std::string> compare_collections(const std::filesystem::path& a, const std::filesystem::path& b) {
  return run_command(std::string(PYTHON) + " " + COMPARE_SCRIPT + " " + shell_quoted(a) + " " + shell_quoted(b) +
                     " 2>&1");
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The 48 meshes of `reeb variants` on the embedded collection, with their
/// classes, and their collection indexed by one process.
class ReebMpiCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    const auto [made, made_out] = run_command(kReeb + " variants " + shell_quoted(embedded_dataset_dir()) + " -o " +
                                              shell_quoted(meshes()) + " 2>&1");
    ASSERT_EQ(made, 0) << made_out;
    const auto [indexed, out] =
        run_command(kReeb + " index " + shell_quoted(meshes()) + " --classes " + shell_quoted(classes()) + " -o " +
                    shell_quoted(single()) + " --threads 2 2>&1");
    ASSERT_EQ(indexed, 0) << out;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::filesystem::path meshes() { return *dir_ / "variants"; }
  static std::filesystem::path classes() { return *dir_ / "variants/variants.cla"; }
  static std::filesystem::path single() { return *dir_ / "single.h5"; }
  /// reeb index of the variants into `output` (no redirection).
  static std::string index_command(const std::filesystem::path& output) {
    return kReeb + " index " + shell_quoted(meshes()) + " --classes " + shell_quoted(classes()) + " -o " +
           shell_quoted(output) + " --threads 1";
  }

  static TempDir* dir_;
};

TempDir* ReebMpiCli::dir_ = nullptr;

/// `reeb distances` of `collection` into `matrix`: the bytes of the matrix.
std::string distances_of(const std::filesystem::path& collection, const std::filesystem::path& matrix) {
  const auto [status, out] =
      run_command(kReeb + " distances " + shell_quoted(collection) + " -o " + shell_quoted(matrix) + " 2>&1");
  EXPECT_EQ(status, 0) << out;
  return file_bytes(matrix);
}

TEST_F(ReebMpiCli, TwoAndThreeProcessesWriteTheCollectionOneProcessWrites) {
  const CollectionReader one(single());
  ASSERT_EQ(one.size(), 48);
  const std::string one_matrix = distances_of(single(), *dir_ / "one.matrix");
  for (const int processes : {2, 3}) {
    SCOPED_TRACE(std::to_string(processes) + " processes");
    const std::filesystem::path output = *dir_ / ("mpi" + std::to_string(processes) + ".h5");
    const auto [status, out] = run_command(mpirun(processes) + index_command(output) + " 2>&1");
    ASSERT_EQ(status, 0) << out;
    EXPECT_NE(out.find("indexing 48 meshes on " + std::to_string(processes) + " processes"), std::string::npos) << out;
    EXPECT_NE(out.find("48 meshes: 48 ok, 0 failed"), std::string::npos) << out;
    const auto [same, report] = compare_collections(single(), output);
    EXPECT_EQ(same, 0) << report;
    // Nothing of the job is left beside the file.
    EXPECT_FALSE(std::filesystem::exists(shard_folder(output)));
    EXPECT_FALSE(std::filesystem::exists(output.string() + ".lock"));
    EXPECT_FALSE(std::filesystem::exists(output.string() + ".partial"));
    // reeb reads it as it reads the single-process file.
    const auto [info, info_out] = run_command(kReeb + " info " + shell_quoted(output));
    EXPECT_EQ(info, 0) << info_out;
    EXPECT_NE(info_out.find("48 meshes: 48 ok, 0 failed"), std::string::npos) << info_out;
    const CollectionReader many(output);
    EXPECT_EQ(many.names(), one.names());
    EXPECT_EQ(many.provenance().classes.size(), one.provenance().classes.size());
    EXPECT_TRUE(distances_of(output, *dir_ / "many.matrix") == one_matrix);
  }
  // The comparison sees a difference: another input order is another file.
  const auto [reversed, out] = run_command(kReeb + " index " + shell_quoted(embedded_dataset_dir()) + " -o " +
                                           shell_quoted(*dir_ / "other.h5") + " --threads 2 2>&1");
  ASSERT_EQ(reversed, 0) << out;
  EXPECT_EQ(compare_collections(single(), *dir_ / "other.h5").first, 1);
}

TEST_F(ReebMpiCli, DistancesOfTwoAndThreeProcessesAreBitIdenticalToOneProcess) {
  const auto [status, out] =
      run_command(kReeb + " distances " + shell_quoted(single()) + " -o " + shell_quoted(*dir_ / "d1.matrix") +
                  " --ascii " + shell_quoted(*dir_ / "d1.txt") + " 2>&1");
  ASSERT_EQ(status, 0) << out;
  const std::string one = file_bytes(*dir_ / "d1.matrix");
  ASSERT_EQ(one.size(), 48u * 48u * 4u);  // float32, no header
  ASSERT_NE(one.find_first_not_of('\0'), std::string::npos);
  for (const int processes : {2, 3}) {
    SCOPED_TRACE(std::to_string(processes) + " processes");
    const std::string matrix = "d" + std::to_string(processes) + ".matrix";
    const std::string ascii = "d" + std::to_string(processes) + ".txt";
    const auto [many, many_out] =
        run_command(mpirun(processes) + kReeb + " distances " + shell_quoted(single()) + " -o " +
                    shell_quoted(*dir_ / matrix) + " --ascii " + shell_quoted(*dir_ / ascii) + " 2>&1");
    ASSERT_EQ(many, 0) << many_out;
    EXPECT_TRUE(file_bytes(*dir_ / matrix) == one) << many_out;
    EXPECT_TRUE(file_bytes(*dir_ / ascii) == file_bytes(*dir_ / "d1.txt")) << many_out;
    // One process prints.
    EXPECT_EQ(many_out.find("rows in the"), many_out.rfind("rows in the")) << many_out;
  }
}

/// The text of /proc/PID/`file`; empty when the process is gone, also while
/// it is read (libstdc++ throws on the read that fails with ESRCH).
std::string proc_text(const std::filesystem::path& process, const char* file) {
  try {
    std::ifstream in(process / file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  } catch (const std::ios_base::failure&) {
    return {};
  }
}

/// The parent of process `pid`; 0 when it is gone.
pid_t parent_of(pid_t pid) {
  const std::string text = proc_text("/proc/" + std::to_string(pid), "stat");
  const auto close = text.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream fields(text.substr(close + 2));
  char state = 0;
  pid_t parent = 0;
  fields >> state >> parent;
  return parent;
}

/// The pid of the process of rank `rank` (OMPI_COMM_WORLD_RANK in its
/// environment) among the descendants of process `ancestor`; 0 when there
/// is none (yet).
pid_t rank_pid(pid_t ancestor, int rank) {
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const auto pid = static_cast<pid_t>(std::stol(name));
    pid_t up = parent_of(pid);
    while (up > 1 && up != ancestor) up = parent_of(up);
    if (up != ancestor) continue;
    const std::string variables = proc_text(entry.path(), "environ");
    if (variables.find(std::string("OMPI_COMM_WORLD_RANK=") + std::to_string(rank) + '\0') != std::string::npos)
      return pid;
  }
  return 0;
}

/// Committed entries of the collection file `path`; 0 when it does not open (yet).
std::int64_t committed(const std::filesystem::path& path) {
  try {
    return CollectionReader(path).size();
  } catch (const Error&) {
    return 0;
  }
}

TEST_F(ReebMpiCli, AKilledProcessLosesOnlyItsUnfinishedMeshesAndResumeCompletesTheJob) {
  const std::filesystem::path output = *dir_ / "killed.h5";
  const std::filesystem::path log = *dir_ / "killed.log";
  // A checkpoint after every mesh: what a kill loses is the meshes in progress.
  const auto [started, pid_text] = run_command(mpirun(2) + index_command(output) + " --checkpoint-seconds 0 > " +
                                               shell_quoted(log) + " 2>&1 & echo $!");
  ASSERT_EQ(started, 0);
  const auto job = static_cast<pid_t>(std::stol(pid_text));  // timeout, mpirun's parent
  // Kill process 1 once its shard holds some meshes.
  pid_t victim = 0;
  std::int64_t before = 0;
  for (int k = 0; k < 6000 && before < 3; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (victim == 0) victim = rank_pid(job, 1);
    before = committed(shard_path(output, 1));
  }
  ASSERT_GT(victim, 0) << file_bytes(log);
  ASSERT_GE(before, 3) << file_bytes(log);
  ASSERT_EQ(::kill(victim, SIGKILL), 0);
  for (int k = 0; k < 6000 && ::kill(job, 0) == 0; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_NE(::kill(job, 0), 0) << "mpirun did not end after its process 1 was killed";
  // The job stopped before its file: the shards keep their checkpoints.
  EXPECT_FALSE(std::filesystem::exists(output)) << file_bytes(log);
  const std::int64_t kept = committed(shard_path(output, 0)) + committed(shard_path(output, 1));
  EXPECT_GE(committed(shard_path(output, 1)), before);
  EXPECT_LT(kept, 48) << "the job ended before the kill: " << file_bytes(log);

  const auto [resumed, out] = run_command(mpirun(2) + index_command(output) + " --resume 2>&1");
  ASSERT_EQ(resumed, 0) << out;
  EXPECT_NE(out.find("(" + std::to_string(kept) + " already indexed)"), std::string::npos) << out;
  EXPECT_NE(out.find("indexing " + std::to_string(48 - kept) + " meshes on 2 processes"), std::string::npos) << out;
  const auto [same, report] = compare_collections(single(), output);
  EXPECT_EQ(same, 0) << report;
  EXPECT_FALSE(std::filesystem::exists(shard_folder(output)));
}

TEST_F(ReebMpiCli, ARefusedJobEndsEveryProcessWithOneMessage) {
  // Resuming with other analysis options: process 0 refuses, every process ends.
  const std::filesystem::path output = *dir_ / "refused.h5";
  std::filesystem::copy_file(single(), output);
  const auto [status, out] = run_command(mpirun(2) + index_command(output) + " --resume --epsilon 0.1 2>&1");
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("epsilon: 0.15 in the file, 0.1 now"), std::string::npos) << out;
  EXPECT_EQ(out.find("cannot resume"), out.rfind("cannot resume")) << out;
  EXPECT_EQ(compare_collections(single(), output).first, 0);
  // Resuming a complete file computes nothing and gives it back.
  const auto [again, again_out] = run_command(mpirun(2) + index_command(output) + " --resume 2>&1");
  EXPECT_EQ(again, 0) << again_out;
  EXPECT_NE(again_out.find("indexing 0 meshes on 2 processes (48 already indexed)"), std::string::npos) << again_out;
  EXPECT_EQ(compare_collections(single(), output).first, 0);
}

// Before: every process printed the error of the command line.
TEST_F(ReebMpiCli, AnOptionErrorIsPrintedOnce) {
  const auto [status, out] = run_command(mpirun(2) + kReeb + " index " + shell_quoted(embedded_dataset_dir()) + " -o " +
                                         shell_quoted(*dir_ / "x.h5") + " --checkpoint-seconds -3 2>&1");
  EXPECT_NE(status, 0) << out;
  const std::string message = "reeb index: --checkpoint-seconds must be a number >= 0";
  ASSERT_NE(out.find(message), std::string::npos) << out;
  EXPECT_EQ(out.find(message), out.rfind(message)) << out;
}

TEST(ReebMpiShrec07, TwoProcessesWriteTheCollectionOneProcessWrites) {
  REEBKIT_REQUIRE_DATASET(shrec, "shrec07_watertight");
  const TempDir dir;
  const std::string inputs = shell_quoted(shrec) + " --classes " + shell_quoted(shrec / "shrec07_watertight.cla");
  const auto [one, one_out] =
      run_command(kReeb + " index " + inputs + " -o " + shell_quoted(dir / "one.h5") + " --threads 2 2>&1");
  ASSERT_EQ(one, 0) << one_out;
  const auto [two, two_out] =
      run_command(mpirun(2) + kReeb + " index " + inputs + " -o " + shell_quoted(dir / "two.h5") + " --threads 1 2>&1");
  ASSERT_EQ(two, 0) << two_out;
  EXPECT_EQ(CollectionReader(dir / "two.h5").size(), 400);
  const auto [same, report] = compare_collections(dir / "one.h5", dir / "two.h5");
  EXPECT_EQ(same, 0) << report;
}

}  // namespace
}  // namespace reebkit::test

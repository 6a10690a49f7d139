// End to end: the `reeb` binary indexes the embedded collection (datasets/),
// `reeb info` reports it and `reeb export` prints a graph as `reeb graph` does.
#include "io/io_test_util.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/file_lock.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/store/collection_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

namespace reebkit::test {
namespace {

/// The lines of a graph JSON file without the ones that differ between
/// `reeb graph` and `reeb export` by design: the mesh path and the timings.
std::vector<std::string> comparable_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  bool in_timings = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("\"timings_ms\"") != std::string::npos) in_timings = true;
    if (!in_timings && line.find("\"mesh\":") == std::string::npos) out.push_back(line);
    if (in_timings && line.find('}') != std::string::npos) in_timings = false;
  }
  return out;
}

TEST(ReebIndexCli, IndexInfoExportOnTheEmbeddedCollection) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path datasets = embedded_dataset_dir();
  const std::size_t meshes = list_mesh_inputs({datasets.string()}).size();
  ASSERT_GT(meshes, 0u);

  const auto [indexed, index_out] = run_command(reeb + " index " + shell_quoted(datasets) + " -o " +
                                                shell_quoted(dir / "c.h5") + " --threads 2 2>&1");
  ASSERT_EQ(indexed, 0) << index_out;
  EXPECT_NE(index_out.find(std::to_string(meshes) + " meshes: " + std::to_string(meshes) + " ok, 0 failed"),
            std::string::npos)
      << index_out;
  // Progress into a pipe (as into a log file or CI): whole lines, no
  // carriage returns or terminal escapes, the last one at the last mesh.
  EXPECT_NE(index_out.find("indexed " + std::to_string(meshes) + "/" + std::to_string(meshes) + " "), std::string::npos)
      << index_out;
  EXPECT_EQ(index_out.find('\r'), std::string::npos) << index_out;
  EXPECT_EQ(index_out.find('\033'), std::string::npos) << index_out;

  const auto [info_status, info] = run_command(reeb + " info " + shell_quoted(dir / "c.h5"));
  ASSERT_EQ(info_status, 0) << info;
  EXPECT_NE(info.find(std::to_string(meshes) + " meshes: " + std::to_string(meshes) + " ok, 0 failed"),
            std::string::npos)
      << info;
  EXPECT_NE(info.find("layout " + std::to_string(kCollectionLayoutVersion)), std::string::npos) << info;
  EXPECT_NE(info.find("command: reeb index"), std::string::npos) << info;
  std::string analysis = "analysis options:";
  for (const NamedOption& option : named_analysis_options(AnalysisOptions{}))
    analysis += " " + option.name + "=" + option_text(option.value);
  EXPECT_NE(info.find(analysis + "\n"), std::string::npos) << info;

  // The same document from the collection and from the mesh (timings and path aside).
  const auto [exported, export_out] = run_command(reeb + " export " + shell_quoted(dir / "c.h5") +
                                                  " elk.off --json -o " + shell_quoted(dir / "export.json") + " 2>&1");
  ASSERT_EQ(exported, 0) << export_out;
  const auto [graphed, graph_out] =
      run_command(reeb + " graph " + shell_quoted(datasets / "elk.off") + " -o " + shell_quoted(dir / "graph.json"));
  ASSERT_EQ(graphed, 0) << graph_out;
  const std::vector<std::string> a = comparable_lines(dir / "export.json");
  EXPECT_GT(a.size(), 100u);
  EXPECT_EQ(a, comparable_lines(dir / "graph.json"));

  const auto [missing, missing_out] =
      run_command(reeb + " export " + shell_quoted(dir / "c.h5") + " nothing.off --json 2>&1");
  EXPECT_EQ(missing, 1);
  EXPECT_NE(missing_out.find("no mesh named 'nothing.off'"), std::string::npos) << missing_out;

  // --resume on an unchanged folder computes nothing.
  const auto [resumed, resume_out] =
      run_command(reeb + " index " + shell_quoted(datasets) + " -o " + shell_quoted(dir / "c.h5") + " --resume 2>&1");
  ASSERT_EQ(resumed, 0) << resume_out;
  EXPECT_NE(resume_out.find("0 ok, 0 failed, " + std::to_string(meshes) + " already indexed"), std::string::npos)
      << resume_out;
}

const std::string kReeb = REEB_BINARY;

/// `reeb ARGS 2>&1`: exit status and output.
std::pair<int, std::string> reeb(const std::string& args) { return run_command(kReeb + " " + args + " 2>&1"); }

/// A folder of meshes copied from datasets/ (and `bad.off`, which no reader
/// takes, when asked).
std::filesystem::path mesh_folder(const TempDir& dir, const std::vector<std::string>& meshes, bool bad = false) {
  const std::filesystem::path folder = dir / "meshes";
  std::filesystem::create_directories(folder);
  for (const std::string& mesh : meshes) std::filesystem::copy_file(embedded_dataset_dir() / mesh, folder / mesh);
  if (bad) write_bytes(folder / "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
  return folder;
}

std::string q(const std::filesystem::path& path) { return shell_quoted(path); }

TEST(ReebIndexCli, ASecondWriterIsRefusedNamingTheFirstOnesPidAndReadersStillWork) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"elk.off", "eight.off"});
  const auto c = dir / "c.h5";
  ASSERT_EQ(reeb("index " + q(folder) + " -o " + q(c)).first, 0);
  {
    const FileLock lock(c);  // this process writes it
    const auto [status, out] = reeb("index " + q(folder) + " -o " + q(c) + " --resume");
    EXPECT_EQ(status, 1) << out;
    const std::string pid = std::to_string(::getpid());
    EXPECT_TRUE(contains(out, {c.string() + ": another process (pid " + pid + ") is writing it"})) << out;
    EXPECT_EQ(reeb("info " + q(c)).first, 0);
  }

  // Two reeb index processes: the second is refused, the first completes.
  // Before: both wrote the file, which then did not open.
  const std::filesystem::path many = dir / "many";
  std::filesystem::create_directories(many);
  for (int k = 0; k < 60; ++k)
    std::filesystem::copy_file(embedded_dataset_dir() / "cow.off", many / ("cow" + std::to_string(k) + ".off"));
  const auto [started, pid] = run_command(kReeb + " index " + q(many) + " -o " + q(c) + " --threads 1 > " +
                                          q(dir / "first.log") + " 2>&1 & echo $!");
  ASSERT_EQ(started, 0);
  const std::string first_pid = pid.substr(0, pid.find('\n'));
  for (int wait = 0; wait < 1000 && !std::filesystem::exists(dir / "c.h5.lock"); ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const auto [second, second_out] = reeb("index " + q(many) + " -o " + q(c));
  const auto [reader, reader_out] = reeb("info " + q(c));  // the previous collection, while the first writes
  EXPECT_EQ(second, 1) << second_out;
  EXPECT_TRUE(contains(second_out, {"another process (pid " + first_pid + ")"})) << second_out;
  EXPECT_EQ(reader, 0) << reader_out;
  EXPECT_TRUE(contains(reader_out, {"2 meshes: 2 ok"})) << reader_out;
  for (int wait = 0; wait < 6000 && run_command("kill -0 " + first_pid + " 2>/dev/null").first == 0; ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const auto [info, info_out] = reeb("info " + q(c));
  EXPECT_EQ(info, 0) << info_out;
  EXPECT_TRUE(contains(info_out, {"60 meshes: 60 ok"})) << info_out << read_file_bytes(dir / "first.log");
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.lock"));
}

// Ctrl-C: reeb index finishes and writes the meshes it started, says which
// file holds them and exits 130; that file opens, and --resume completes it.
// Before: SIGINT's default action killed the process, and every mesh since
// the last checkpoint (up to --checkpoint-seconds of work) was lost.
TEST(ReebIndexCli, CtrlCWritesTheMeshesStartedSaysWhereAndResumeCompletes) {
  const TempDir dir;
  const std::filesystem::path many = dir / "many";
  std::filesystem::create_directories(many);
  constexpr int kMeshes = 40;
  for (int k = 0; k < kMeshes; ++k)
    std::filesystem::copy_file(embedded_dataset_dir() / "cow.off", many / ("cow" + std::to_string(k) + ".off"));
  const auto c = dir / "c.h5";
  const std::string log = (dir / "index.log").string();
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ASSERT_GE(fd, 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // only async-signal-safe calls until exec: this process may have had threads
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::execl(kReeb.c_str(), kReeb.c_str(), "index", many.c_str(), "-o", c.c_str(), "--threads", "2",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fd);
  // The first progress line comes after the first mesh is written.
  for (int wait = 0; wait < 6000 && read_file_bytes(log).find("indexed ") == std::string::npos; ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(child, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  const std::string out = read_file_bytes(log);
  ASSERT_TRUE(WIFEXITED(status)) << out;
  EXPECT_EQ(WEXITSTATUS(status), 130) << out;
  const auto partial = dir / "c.h5.partial";
  const std::int64_t entries = CollectionReader(partial).size();
  EXPECT_GE(entries, 1);
  EXPECT_LT(entries, kMeshes) << out;
  EXPECT_TRUE(contains(out, {"stopping: the meshes in progress are finished and written",
                             "interrupted: " + partial.string() + " holds " + std::to_string(entries) + " entries",
                             "--resume computes the " + std::to_string(kMeshes - entries) + " meshes not started"}))
      << out;
  EXPECT_FALSE(std::filesystem::exists(c));
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.lock"));

  const auto [resumed, resume_out] = reeb("index " + q(many) + " -o " + q(c) + " --threads 2 --resume");
  EXPECT_EQ(resumed, 0) << resume_out;
  EXPECT_TRUE(contains(resume_out, {std::to_string(kMeshes - entries) + " ok, 0 failed, " + std::to_string(entries) +
                                    " already indexed"}))
      << resume_out;
  EXPECT_EQ(CollectionReader(c).size(), kMeshes);
  EXPECT_FALSE(std::filesystem::exists(partial));
}

TEST(ReebIndexCli, BadOutputsOptionsAndClassesAreRefusedBeforeAnyWork) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"elk.off", "eight.off"});
  const auto c = dir / "c.h5";
  ASSERT_EQ(reeb("index " + q(folder) + " -o " + q(c)).first, 0);
  const std::string collection = read_file_bytes(c), mesh = read_file_bytes(folder / "eight.off");

  // Before: the input mesh overwritten with HDF5; the collection replaced by
  // one of failed entries, exit 0; the classes silently unused.
  write_bytes(dir / "none.cla", "PSB 1\n1 1\n\nthings 0 1\nnothing\n");
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"index " + q(folder) + " -o " + q(folder / "eight.off"), (folder / "eight.off").string() + ": is an input"},
      {"index " + q(folder) + " -o " + q(c) + " --epsilon 5", "analysis option epsilon: 5 is out of its range (0, 1]"},
      {"index " + q(folder) + " -o " + q(c) + " --skeleton-levels 0",
       "skeleton_levels: 0 is out of its range [1, inf)"},
      {"index " + q(folder) + " -o " + q(dir / "no" / "c.h5"),
       "the folder " + (dir / "no").string() + " does not exist"},
      {"index " + q(folder) + " -o " + q(c) + " --classes " + q(dir / "none.cla"),
       (dir / "none.cla").string() + ": none of its 1 models names one of the 2 input meshes"},
      {"index " + q(folder) + " -o " + q(dir / "none.cla") + " --classes " + q(dir / "none.cla"), "is an input"},
  };
  for (const auto& [args, message] : refused) {
    const auto [status, out] = reeb(args);
    EXPECT_EQ(status, 1) << args << "\n" << out;
    EXPECT_TRUE(contains(out, {message})) << out;
    EXPECT_EQ(out.find("indexed"), std::string::npos) << out;  // no mesh was read
  }
  EXPECT_EQ(read_file_bytes(c), collection);
  EXPECT_EQ(read_file_bytes(folder / "eight.off"), mesh);
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
}

// Before: an empty folder gave a collection of 0 meshes (exit 0);
// --checkpoint-seconds -3 was refused after "indexing N meshes" under the
// library's name of the option.
TEST(ReebIndexCli, NoInputAndBadIndexingOptionsAreRefusedBeforeTheAnnouncement) {
  const TempDir dir;
  std::filesystem::create_directories(dir / "empty");
  const auto [empty, empty_out] = reeb("index " + q(dir / "empty") + " -o " + q(dir / "c.h5"));
  EXPECT_EQ(empty, 1) << empty_out;
  EXPECT_TRUE(contains(empty_out, {"no mesh to index"})) << empty_out;
  EXPECT_EQ(empty_out.find("indexing"), std::string::npos) << empty_out;
  const std::filesystem::path folder = mesh_folder(dir, {"eight.off"});
  for (const std::string option : {"--checkpoint-seconds -3", "--checkpoint-seconds nan", "--threads -1"}) {
    const auto [status, out] = reeb("index " + q(folder) + " -o " + q(dir / "c.h5") + " " + option);
    EXPECT_EQ(status, 2) << option << "\n" << out;
    EXPECT_TRUE(contains(out, {"reeb index: " + option.substr(0, option.find(' ')) + " must be"})) << out;
    EXPECT_EQ(out.find("indexing"), std::string::npos) << out;
  }
  EXPECT_EQ(files_in(dir / ""), (std::vector<std::string>{"empty", "meshes"}));
}

// Before: a link to the collection was a second name that skipped its lock,
// and the write replaced the link by a file.
TEST(ReebIndexCli, ALinkToTheOutputIsLockedAndWrittenAsItsFile) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"eight.off"});
  const auto c = dir / "c.h5", link = dir / "link.h5";
  ASSERT_EQ(reeb("index " + q(folder) + " -o " + q(c)).first, 0);
  std::filesystem::create_symlink("c.h5", link);
  {
    const FileLock lock(c);  // this process writes c.h5
    const auto [status, out] = reeb("index " + q(folder) + " -o " + q(link));
    EXPECT_EQ(status, 1) << out;
    EXPECT_TRUE(contains(out, {"another process (pid " + std::to_string(::getpid()) + ") is writing it"})) << out;
  }
  std::filesystem::copy_file(embedded_dataset_dir() / "elk.off", folder / "elk.off");
  const auto [status, out] = reeb("index " + q(folder) + " -o " + q(link));
  EXPECT_EQ(status, 0) << out;
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(CollectionReader(c).size(), 2);
  EXPECT_EQ(files_in(dir / ""), (std::vector<std::string>{"c.h5", "c.query.h5", "link.h5", "meshes"}));
}

// Before: under a file-size limit with SIGXFSZ at its default action (a
// shell without `trap '' XFSZ`), reeb index died without a word, leaving
// c.h5.partial and c.h5.lock. with_file_size_limit leaves the signal at its
// default: the same message as on a full disk.
TEST(ReebIndexCli, AFileSizeLimitIsAWriteErrorNotADeath) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"elk.off", "eight.off", "cow.off"});
  const auto c = dir / "c.h5";
  const auto [status, out] = run_command(
      with_file_size_limit(kReeb + " index " + q(folder) + " -o " + q(c) + " --threads 1", 20000) + " 2>&1");
  EXPECT_EQ(status, 1) << out;
  EXPECT_TRUE(contains(out, {"reeb index: error: " + c.string() + ".partial: ", "File too large"})) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.lock"));
}

TEST(ReebIndexCli, ExitStatusSaysWhetherMeshesFailed) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"elk.off", "eight.off"}, true);
  const auto c = dir / "c.h5";
  const auto [failed, failed_out] = reeb("index " + q(folder) + " -o " + q(c));
  EXPECT_EQ(failed, 1) << failed_out;  // before: 0
  EXPECT_TRUE(contains(failed_out, {"wrote " + c.string(), "1 of 3 meshes failed", "--allow-failures"})) << failed_out;
  const auto [allowed, allowed_out] = reeb("index " + q(folder) + " -o " + q(c) + " --allow-failures");
  EXPECT_EQ(allowed, 0) << allowed_out;
  const std::string collection = read_file_bytes(c);

  // Every mesh failed: exit 1 whatever the flag, and the collection stays as it was.
  for (const std::string flag : {"", " --allow-failures"}) {
    const auto [status, out] = reeb("index " + q(folder / "bad.off") + " -o " + q(c) + flag);
    EXPECT_EQ(status, 1) << out;
    EXPECT_TRUE(contains(out, {"every mesh failed (1): " + c.string() + " left as it was"})) << out;
  }
  EXPECT_EQ(read_file_bytes(c), collection);
  const auto [none, none_out] = reeb("index " + q(folder / "bad.off") + " -o " + q(dir / "new.h5"));
  EXPECT_EQ(none, 1) << none_out;
  EXPECT_TRUE(contains(none_out, {"not written"})) << none_out;
  EXPECT_EQ(files_in(dir / ""), (std::vector<std::string>{"c.h5", "c.query.h5", "meshes"}));

  // info --list names every entry; distances says how failed rows are filled.
  const auto [info, info_out] = reeb("info " + q(c) + " --list");
  EXPECT_EQ(info, 0) << info_out;
  EXPECT_TRUE(contains(info_out, {"name\tclass\tstatus\tnodes\tfeatures\tcycles\tcommon\n",
                                  "bad.off\t-\tfailed\t0\t0\t0\t-\n", "elk.off\t-\tok\t"}))
      << info_out;
  const auto [distances, distances_out] = reeb("distances " + q(c) + " -o " + q(dir / "d.matrix"));
  EXPECT_EQ(distances, 0) << distances_out;
  // Progress into a pipe: a line now and then and one when every pair is matched.
  EXPECT_TRUE(contains(distances_out,
                       {"warning: 1 of 3 entries failed when indexed", "largest float", "bad.off", "matched 3/3  "}))
      << distances_out;
}

TEST(ReebIndexCli, AFullDiskGivesOneClearErrorKeepsThePreviousFileAndResumeGoesOn) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"elk.off", "eight.off", "cow.off", "hand.off", "bunny.off"});
  const auto c = dir / "c.h5";
  ASSERT_EQ(reeb("index " + q(folder / "elk.off") + " -o " + q(c)).first, 0);
  const std::string previous = read_file_bytes(c);
  // Before: the error, 17 "H5Dclose failed" lines, a segfault at exit (139).
  for (const std::string verbose : {"", " --verbose"}) {
    const auto [status, out] = run_command(
        with_file_size_limit(kReeb + " index " + q(folder) + " -o " + q(c) + " --threads 1" + verbose, 60000) +
        " 2>&1");
    EXPECT_EQ(status, 1) << out;
    EXPECT_TRUE(contains(out, {"reeb index: error: " + c.string() + ".partial: writing: File too large (HDF5: ",
                               c.string() + " is left as it was; " + c.string() +
                                   ".partial holds the entries of the last checkpoint"}))
        << out;
    EXPECT_EQ(out.find("H5Dclose"), std::string::npos) << out;
    EXPECT_EQ(out.find("HDF5-DIAG") == std::string::npos, verbose.empty()) << out;
    EXPECT_EQ(read_file_bytes(c), previous);
  }
  // The partial file opens; resume completes it and puts it in place.
  const std::int64_t committed = CollectionReader(dir / "c.h5.partial").size();
  const auto [resumed, resumed_out] = reeb("index " + q(folder) + " -o " + q(c) + " --resume");
  EXPECT_EQ(resumed, 0) << resumed_out;
  EXPECT_TRUE(contains(resumed_out, {std::to_string(5 - committed) + " ok, 0 failed, " + std::to_string(committed) +
                                     " already indexed"}))
      << resumed_out;
  EXPECT_EQ(CollectionReader(c).size(), 5);
  EXPECT_EQ(files_in(dir / ""), (std::vector<std::string>{"c.h5", "c.query.h5", "meshes"}));

  // The commands that read a collection and write files: the same (before:
  // distances and export -o reported the error but left partial files).
  write_bytes(dir / "out", "previous\n");
  const std::vector<std::pair<std::string, int>> writers =
      {{"distances " + q(c) + " -o " + q(dir / "out"), 50},  // the 5 x 5 float32 matrix: 100 bytes
       {"distances " + q(c) + " -o " + q(dir / "d.matrix") + " --ascii " + q(dir / "out"), 100},
       {"export " + q(c) + " elk.off --json -o " + q(dir / "out"), 100}};
  for (const auto& [args, limit] : writers) {
    const auto [status, out] = run_command(with_file_size_limit(kReeb + " " + args, limit) + " 2>&1");
    EXPECT_EQ(status, 1) << args << "\n" << out;
    EXPECT_TRUE(contains(out, {(dir / "out").string() + ": write error: File too large"})) << out;
    EXPECT_EQ(read_file_bytes(dir / "out"), "previous\n");
  }
  EXPECT_EQ(files_in(dir / ""), (std::vector<std::string>{"c.h5", "c.query.h5", "d.matrix", "meshes", "out"}));
}

TEST(ReebIndexCli, ResumeLabelsEveryEntryWithTheClassesGivenAndKeepsThemOtherwise) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"elk.off", "eight.off"});
  const auto c = dir / "c.h5";
  ASSERT_EQ(reeb("index " + q(folder) + " -o " + q(c)).first, 0);
  write_bytes(dir / "k.cla", "PSB 1\n2 4\n\nanimal 0 3\nelk\ncow\nhand\n\nshape 0 1\neight\n");
  std::filesystem::copy_file(embedded_dataset_dir() / "cow.off", folder / "cow.off");
  const auto [resumed, resumed_out] =
      reeb("index " + q(folder) + " -o " + q(c) + " --resume --classes " + q(dir / "k.cla"));
  ASSERT_EQ(resumed, 0) << resumed_out;
  std::filesystem::copy_file(embedded_dataset_dir() / "hand.off", folder / "hand.off");
  const auto [again, again_out] = reeb("index " + q(folder) + " -o " + q(c) + " --resume");
  ASSERT_EQ(again, 0) << again_out;
  // Before: elk and eight, indexed before the classes, had none.
  const auto [info, info_out] = reeb("info " + q(c) + " --list");
  EXPECT_TRUE(contains(info_out, {"eight.off\tshape\tok\t", "elk.off\tanimal\tok\t", "cow.off\tanimal\tok\t",
                                  "hand.off\tanimal\tok\t", "classes from " + (dir / "k.cla").string()}))
      << info_out;
}

// reeb info: per class, how many graphs have the class's most common
// (feature points, nodes, cycles). A rotated and scaled copy of the elk has
// the elk's graph (the invariance of sections 4.1.1 and 5.3); the cow (genus
// 0) cannot have the elk's (genus 1: one cycle).
TEST(ReebIndexCli, InfoCountsTheGraphsThatHaveTheirClassesMostCommonShape) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"elk.off", "cow.off", "eight.off"});
  ASSERT_EQ(reeb("perturb " + q(folder / "elk.off") + " -o " + q(folder / "elk_turned.off") +
                 " --rotate random --scale 3 --seed 5")
                .first,
            0);
  std::filesystem::remove(folder / "elk_turned.corr");
  write_bytes(dir / "k.cla", "PSB 1\n2 4\n\nanimal 0 3\nelk\nelk_turned\ncow\n\nshape 0 1\neight\n");
  const auto c = dir / "c.h5";
  const auto [index, index_out] = reeb("index " + q(folder) + " -o " + q(c) + " --classes " + q(dir / "k.cla"));
  ASSERT_EQ(index, 0) << index_out;
  const auto [info, info_out] = reeb("info " + q(c));
  ASSERT_EQ(info, 0) << info_out;
  EXPECT_TRUE(contains(info_out, {"2 classes (meshes; graphs with the class's most common feature points / nodes / "
                                  "cycles):\n",
                                  "  animal\t3\t2 with ", " / 1\n", "  shape\t1\t1 with ",
                                  "graphs with their class's most common shape: 3 of 4 (75.0 %)\n"}))
      << info_out;
  // --list marks which graphs those are: the elk and its copy, and the eight alone in its class.
  const auto [listed, listed_out] = reeb("info " + q(c) + " --list");
  ASSERT_EQ(listed, 0) << listed_out;
  EXPECT_TRUE(contains(listed_out, {"\t1\tyes\n", "cow.off\tanimal\tok\t", "\t0\tno\n"})) << listed_out;
  for (const std::string name : {"elk.off", "elk_turned.off", "eight.off"}) {
    const std::size_t at = listed_out.find("\n" + name + "\t");
    ASSERT_NE(at, std::string::npos) << name << "\n" << listed_out;
    EXPECT_EQ(listed_out.substr(listed_out.find('\n', at + 1) - 4, 4), "\tyes") << name << "\n" << listed_out;
  }
}

TEST(ReebIndexCli, ADamagedCollectionIsAClearErrorForEveryCommandThatOpensIt) {
  const TempDir dir;
  const std::filesystem::path folder = mesh_folder(dir, {"elk.off", "eight.off"});
  const auto c = dir / "c.h5";
  ASSERT_EQ(reeb("index " + q(folder) + " -o " + q(c)).first, 0);
  const std::string bytes = read_file_bytes(c);
  std::string flipped = bytes;  // every byte of the metadata after the superblock inverted
  for (std::size_t i = 48; i < std::min<std::size_t>(flipped.size(), 4096); ++i)
    flipped[i] = static_cast<char>(~flipped[i]);
  const std::vector<std::pair<std::string, std::string>> damaged = {
      {"truncated.h5", bytes.substr(0, bytes.size() / 2)},
      {"header.h5", bytes.substr(0, 40)},
      {"flipped.h5", flipped},
      {"empty.h5", ""},
  };
  for (const auto& [name, content] : damaged) {
    const auto path = dir / name;
    write_bytes(path, content);
    for (const std::string& args :
         {"info " + q(path), "info " + q(path) + " --list", "export " + q(path) + " elk.off --json",
          "query " + q(path) + " elk.off", "distances " + q(path) + " -o " + q(dir / "d.matrix"),
          "match " + q(path) + ":elk.off " + q(folder / "elk.off"),
          "index " + q(folder) + " -o " + q(path) + " --resume"}) {
      const auto [status, out] = reeb(args);
      EXPECT_EQ(status, 1) << args << "\n" << out;
      EXPECT_TRUE(contains(out, {": error: " + path.string() + ": "})) << args << "\n" << out;
      EXPECT_EQ(out.find("HDF5-DIAG"), std::string::npos) << args << "\n" << out;
    }
  }
}

}  // namespace
}  // namespace reebkit::test

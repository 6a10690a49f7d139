#include "reebkit/collection/extract_collection.h"

#include "collection/collection_test_util.h"
#include "io/io_test_util.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/content_hash.h"
#include "reebkit/io/off.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/store/collection_file.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <random>
#include <thread>

namespace reebkit::test {
namespace {

/// The entry of `input` computed directly, without the extractor.
GraphRecord direct_entry(const MeshInput& input) {
  const MeshAnalysis analysis = analyze_mesh(load_mesh(input.path).components.front());
  GraphRecord entry = make_graph_record(analysis, compute_attributes(analysis));
  entry.name = input.name;
  entry.content_hash = content_hash(input.path);
  return entry;
}

// The provenance's JSON is made from the table of analysis options: every
// option under its own name, nothing under another (before: written by hand
// under other names, "max_loop_length" for max_hole_loop).
TEST(ExtractCollection, TheOptionsJsonHoldsEveryAnalysisOptionByItsTableName) {
  AnalysisOptions options;
  options.features.geodesic = Geodesic::Dijkstra;
  const std::string json = analysis_options_json(options);
  std::size_t keys = 0;
  for (std::size_t at = json.find("\":"); at != std::string::npos; at = json.find("\":", at + 1)) ++keys;
  EXPECT_EQ(keys, analysis_option_fields().size() + 2) << json;  // + all_components, reeb_graph
  for (const NamedOption& option : named_analysis_options(options)) {
    const std::string text = std::holds_alternative<std::string>(option.value) ? "\"" + option_text(option.value) + "\""
                                                                               : option_text(option.value);
    EXPECT_NE(json.find("\"" + option.name + "\": " + text), std::string::npos) << option.name << " in " << json;
  }
  EXPECT_EQ(json.find('\n'), std::string::npos) << json;
}

TEST(ExtractCollection, BrokenMeshIsRecordedAndTheOthersMatchTheDirectPipeline) {
  const TempDir dir;
  const std::vector<MeshInput> inputs = write_collection(dir);
  ASSERT_EQ(inputs.size(), 8u);
  ASSERT_EQ(inputs[0].name, "broken.off");
  const std::vector<PsbClass> classes = {{"star", "0", {"m1"}}, {"torus", "0", {"m6"}}};
  const ExtractionSummary summary = extract_collection(inputs, classes, dir / "c.h5", with_threads(2));
  EXPECT_EQ(summary.ok, 7);
  ASSERT_EQ(summary.failed.size(), 1u);
  EXPECT_EQ(summary.failed[0].name, "broken.off");
  EXPECT_NE(summary.failed[0].reason.find("broken.off"), std::string::npos) << summary.failed[0].reason;
  EXPECT_EQ(summary.skipped, 0);
  EXPECT_GE(summary.seconds, summary.write_seconds);

  const CollectionReader reader(dir / "c.h5");
  ASSERT_EQ(reader.size(), 8);
  const GraphRecord broken = reader.entry(0);
  EXPECT_FALSE(broken.ok);
  EXPECT_EQ(broken.error, summary.failed[0].reason);
  EXPECT_EQ(broken.num_nodes(), 0);
  EXPECT_EQ(broken.content_hash, content_hash(inputs[0].path));  // read and hashed, then refused
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    GraphRecord expected = direct_entry(inputs[i]);
    expected.class_label = i == 1 ? "star" : i == 6 ? "torus" : "";
    expect_same(reader.entry(static_cast<std::int64_t>(i)), expected);
    EXPECT_EQ(reader.names()[i], inputs[i].name);
  }
  // A torus's graph has one cycle (its genus), a star's none.
  for (int arms = 1; arms <= 5; ++arms) EXPECT_EQ(independent_cycles(reader.entry(arms)), 0);
  EXPECT_EQ(independent_cycles(reader.entry(6)), 1);
  EXPECT_EQ(independent_cycles(reader.entry(7)), 1);
}

/// Bytes this process has read so far (Linux: rchar of /proc/self/io,
/// every read system call, from files or not); nullopt elsewhere.
std::optional<std::int64_t> bytes_read_by_process() {
  std::ifstream io("/proc/self/io");
  for (std::string key; io >> key;) {
    std::int64_t value = 0;
    io >> value;
    if (key == "rchar:") return value;
  }
  return std::nullopt;
}

// Each mesh file is read once: parsed and hashed from the same bytes, not
// hashed first and parsed after (which read the inputs twice).
TEST(ExtractCollection, EachFileIsReadOnce) {
  if (!bytes_read_by_process()) GTEST_SKIP() << "no /proc/self/io to count the bytes read";
  const TempDir dir;
  std::filesystem::create_directories(dir / "meshes");
  std::int64_t input_bytes = 0;
  for (int k = 0; k < 3; ++k) {  // about 0.4 MB of OFF text each, far above the HDF5 file's own reads
    const std::filesystem::path path = dir / ("meshes/t" + std::to_string(k) + ".off");
    write_off(path, make_torus(120 + 10 * k, 60));
    input_bytes += static_cast<std::int64_t>(std::filesystem::file_size(path));
  }
  const std::vector<MeshInput> inputs = list_mesh_inputs({(dir / "meshes").string()});
  const std::int64_t before = *bytes_read_by_process();
  const ExtractionSummary summary = extract_collection(inputs, {}, dir / "c.h5", with_threads(1));
  const std::int64_t read = *bytes_read_by_process() - before;
  EXPECT_EQ(summary.ok, 3);
  EXPECT_GE(read, input_bytes);
  EXPECT_LT(read, input_bytes + input_bytes / 4) << read << " bytes read for " << input_bytes << " bytes of meshes";
  // The hashes are those of the files, as --resume compares them.
  const CollectionReader reader(dir / "c.h5");
  for (std::size_t i = 0; i < inputs.size(); ++i)
    EXPECT_EQ(reader.content_hashes()[i], content_hash(inputs[i].path)) << inputs[i].name;
}

TEST(ExtractCollection, SerialAndParallelFilesAreTheSame) {
  const TempDir dir;
  const std::vector<MeshInput> inputs = write_collection(dir);
  extract_collection(inputs, {}, dir / "serial.h5", with_threads(1));
  extract_collection(inputs, {}, dir / "parallel.h5", with_threads(2));
  expect_same_files(dir / "serial.h5", dir / "parallel.h5");
}

/// Indexes `inputs` into `output` and dies (like kill -9: no destructor, no
/// flush) right after the 5th entry was handed to the writer, with a
/// checkpoint every 2 entries and none by time.
[[noreturn]] void index_and_die(const std::vector<MeshInput>& inputs, const std::filesystem::path& output) {
  ExtractionOptions options = with_threads(2);
  options.checkpoint_entries = 2;
  options.checkpoint_seconds = 1e9;
  options.progress = [](const ProgressState& s) {
    if (s.done() == 5) std::_Exit(3);
  };
  extract_collection(inputs, {}, output, options);
  std::_Exit(0);
}

TEST(ExtractCollection, ResumeAfterACrashComputesOnlyTheRestAndGivesTheSameFile) {
  // The death test child re-runs this test binary (no fork of OpenMP
  // threads) up to EXPECT_EXIT; it finds the parent's folder in the
  // environment and indexes the parent's meshes.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  constexpr const char* kShared = "REEBKIT_CRASH_TEST_DIR";
  std::optional<TempDir> own;  // in the parent only
  if (std::getenv(kShared) == nullptr) {
    own.emplace();
    write_collection(*own);
    ::setenv(kShared, (*own / "").c_str(), 1);
  }
  const std::filesystem::path dir = std::getenv(kShared);
  const std::vector<MeshInput> inputs = list_mesh_inputs({(dir / "meshes").string()});
  EXPECT_EXIT(index_and_die(inputs, dir / "c.h5"), ::testing::ExitedWithCode(3), "");
  ::unsetenv(kShared);
  // The checkpoints after entries 2 and 4 are on disk, the 5th is not, in
  // c.h5.partial: a new collection is renamed into place at the end only.
  ASSERT_EQ(CollectionReader(dir / "c.h5.partial").size(), 4);
  ASSERT_FALSE(std::filesystem::exists(dir / "c.h5"));

  ExtractionOptions resume = with_threads(2);
  resume.resume = true;
  const ExtractionSummary summary = extract_collection(inputs, {}, dir / "c.h5", resume);
  EXPECT_EQ(summary.skipped, 4);
  EXPECT_EQ(summary.kept, 4);
  EXPECT_EQ(summary.computed(), 4);  // the analyses run: only the meshes not in the file
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.partial"));

  extract_collection(inputs, {}, dir / "whole.h5", with_threads(2));
  expect_same_files(dir / "c.h5", dir / "whole.h5");

  // Resuming a complete file computes nothing and changes nothing.
  const ExtractionSummary again = extract_collection(inputs, {}, dir / "c.h5", resume);
  EXPECT_EQ(again.computed(), 0);
  EXPECT_EQ(again.skipped, 8);
  expect_same_files(dir / "c.h5", dir / "whole.h5");
}

/// Indexes `inputs` into `output` with a checkpoint after every entry and is
/// killed with SIGKILL `delay_ms` after the start by a thread of its own (no
/// destructor, no flush: wherever the writer was).
[[noreturn]] void index_and_get_killed(const std::vector<MeshInput>& inputs, const std::filesystem::path& output,
                                       int delay_ms) {
  std::thread([delay_ms] {
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    ::raise(SIGKILL);
  }).detach();
  ExtractionOptions options = with_threads(2);
  options.checkpoint_entries = 1;
  extract_collection(inputs, {}, output, options);
  for (;;) ::pause();  // done before the kill: it comes all the same
}

TEST(ExtractCollection, KilledAtRandomMomentsThenResumedGivesTheUninterruptedFile) {
  // As above, the death test children re-run this test binary; only the
  // parent (which owns the folder) measures, resumes and compares.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  constexpr const char* kShared = "REEBKIT_KILL_TEST_DIR";
  constexpr const char* kDelay = "REEBKIT_KILL_TEST_DELAY_MS";
  std::optional<TempDir> own;
  if (std::getenv(kShared) == nullptr) {
    own.emplace();
    write_collection(*own);
    ::setenv(kShared, (*own / "").c_str(), 1);
  }
  const bool parent = own.has_value();
  const std::filesystem::path dir = std::getenv(kShared);
  const std::vector<MeshInput> inputs = list_mesh_inputs({(dir / "meshes").string()});
  double run_ms = 0;
  if (parent) {
    Timer timer;
    extract_collection(inputs, {}, dir / "whole.h5", with_threads(2));
    run_ms = timer.lap();
  }
  std::mt19937 rng(20261125);
  for (int trial = 0; trial < 12; ++trial) {
    const auto output = dir / ("killed" + std::to_string(trial) + ".h5");
    if (parent) {
      // From before the first entry to past the end (the rename, the lock): a
      // child, a fresh process, runs slower than the parent's warm run.
      const int delay = std::uniform_int_distribution<int>(0, static_cast<int>(4 * run_ms) + 50)(rng);
      ::setenv(kDelay, std::to_string(delay).c_str(), 1);
    }
    EXPECT_EXIT(index_and_get_killed(inputs, output, std::atoi(std::getenv(kDelay))),
                ::testing::KilledBySignal(SIGKILL), "");
    if (!parent) continue;
    SCOPED_TRACE("trial " + std::to_string(trial) + ", killed after " + std::getenv(kDelay) + " ms of " +
                 std::to_string(run_ms));
    const std::filesystem::path partial = output.string() + ".partial";
    const std::filesystem::path left = std::filesystem::exists(partial) ? partial : output;
    std::int64_t committed = 0;  // none either when killed while creating the file (it does not open)
    std::string state = "missing";
    try {
      committed = CollectionReader(left).size();
      state = "opens";
    } catch (const Error&) {
      if (std::filesystem::exists(left)) state = "does not open";
    }
    std::printf("killed after %s ms (a run: %.0f ms): %s %s, %lld entries\n", std::getenv(kDelay), run_ms,
                left.filename().c_str(), state.c_str(), static_cast<long long>(committed));
    ExtractionOptions resume = with_threads(2);
    resume.resume = true;
    const ExtractionSummary resumed = extract_collection(inputs, {}, output, resume);
    EXPECT_EQ(resumed.skipped, committed);
    expect_same_files(output, dir / "whole.h5");
    EXPECT_FALSE(std::filesystem::exists(output.string() + ".partial"));
    EXPECT_FALSE(std::filesystem::exists(output.string() + ".lock"));
  }
  ::unsetenv(kShared);
  ::unsetenv(kDelay);
}

// A stop request (reeb index's Ctrl-C): the meshes started are finished and
// written, none after them; the new collection stays OUTPUT.partial, durable,
// and --resume completes it into the file of an uninterrupted run.
TEST(ExtractCollection, AStopRequestKeepsEveryEntryComputedAndResumeCompletesTheFile) {
  const TempDir dir;
  const std::vector<MeshInput> inputs = write_collection(dir);
  std::atomic<bool> stop{false};
  ExtractionOptions options = with_threads(2);
  options.stop = &stop;
  options.checkpoint_seconds = 1e9;  // no checkpoint before the stop: what is kept is the stop's doing
  options.checkpoint_entries = 1000;
  options.progress = [&stop](const ProgressState& s) {
    if (s.done() == 3) stop = true;
  };
  const ExtractionSummary summary = extract_collection(inputs, {}, dir / "c.h5", options);
  EXPECT_TRUE(summary.interrupted);
  // Started before the request: the three written and at most batch_size (2) ahead of the writer.
  EXPECT_GE(summary.computed(), 3);
  EXPECT_LE(summary.computed(), 5);
  EXPECT_EQ(summary.file, dir / "c.h5.partial");
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5"));
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.lock"));
  const CollectionReader partial(dir / "c.h5.partial");
  ASSERT_EQ(partial.size(), summary.computed());
  for (std::int64_t i = 0; i < partial.size(); ++i)
    EXPECT_EQ(partial.names()[static_cast<std::size_t>(i)], inputs[static_cast<std::size_t>(i)].name);

  ExtractionOptions resume = with_threads(2);
  resume.resume = true;
  const ExtractionSummary resumed = extract_collection(inputs, {}, dir / "c.h5", resume);
  EXPECT_FALSE(resumed.interrupted);
  EXPECT_EQ(resumed.skipped, summary.computed());
  EXPECT_EQ(resumed.computed(), static_cast<std::int64_t>(inputs.size()) - summary.computed());
  EXPECT_EQ(resumed.file, dir / "c.h5");
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.partial"));
  extract_collection(inputs, {}, dir / "whole.h5", with_threads(2));
  expect_same_files(dir / "c.h5", dir / "whole.h5");
}

TEST(ExtractCollection, ReindexingRecomputesOnlyChangedFilesAndKeepsNamesUnique) {
  const TempDir dir;
  const std::vector<MeshInput> inputs = write_collection(dir);
  extract_collection(inputs, {}, dir / "c.h5", with_threads(2));
  // m3 becomes a 4-armed star: same name, new bytes.
  write_off(dir / "meshes/m3.off", make_star(StarOptions{4, 2, 2.0, 0.2, 0.5}));
  ExtractionOptions resume = with_threads(2);
  resume.resume = true;
  const ExtractionSummary summary = extract_collection(inputs, {}, dir / "c.h5", resume);
  EXPECT_EQ(summary.computed(), 1);
  EXPECT_EQ(summary.ok, 1);
  EXPECT_EQ(summary.skipped, 7);
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.rewrite"));

  const CollectionReader reader(dir / "c.h5");
  ASSERT_EQ(reader.size(), 8);
  std::vector<std::string> names = reader.names();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << "a name twice";
  // The old entries keep their order; the recomputed one comes last.
  const auto m3 = reader.find("m3.off");
  ASSERT_TRUE(m3.has_value());
  EXPECT_EQ(*m3, 7);
  expect_same(reader.entry(*m3), direct_entry(inputs[3]));
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(reader.names()[i], inputs[i < 3 ? i : i + 1].name);
}

TEST(ExtractCollection, TheFileKeepsItsAnalysisOptionsAndClassesAndResumeRefusesOthers) {
  const TempDir dir;
  const std::vector<MeshInput> inputs = write_collection(dir);
  const std::vector<PsbClass> classes = {{"torus", "0", {"m7", "m6"}}, {"star", "0", {"m2", "m1"}}};
  ExtractionOptions options = with_threads(2);
  options.analysis.features.epsilon = 0.1;
  options.analysis.features.geodesic = Geodesic::Dijkstra;
  options.analysis.features.min_persistence = 0.02;
  options.classes_file = "two.cla";
  extract_collection(inputs, classes, dir / "c.h5", options);
  {
    const CollectionReader reader(dir / "c.h5");
    const Provenance& provenance = reader.provenance();
    EXPECT_TRUE(
        analysis_option_differences(analysis_options_from(provenance.analysis_options), options.analysis).empty());
    ASSERT_EQ(provenance.classes.size(), 2u);
    EXPECT_EQ(provenance.classes[0].models, classes[0].models);
    EXPECT_EQ(provenance.classes[1].models, classes[1].models);
    EXPECT_EQ(provenance.classes_file, "two.cla");
    EXPECT_EQ(reader.class_labels()[7], "torus");
  }

  // Other options: refused before any work, naming each option with both values.
  const std::uint64_t before = content_hash(dir / "c.h5");
  ExtractionOptions other = options;
  other.resume = true;
  other.analysis.features.epsilon = 0.05;
  other.analysis.features.geodesic = Geodesic::FastMarching;  // the default
  try {
    extract_collection(inputs, classes, dir / "c.h5", other);
    ADD_FAILURE() << "resumed with other analysis options";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find((dir / "c.h5").string() + ": cannot resume"), std::string::npos) << message;
    EXPECT_NE(message.find("epsilon: 0.1 in the file, 0.05 now"), std::string::npos) << message;
    EXPECT_NE(message.find("geodesic: dijkstra in the file, fmm now"), std::string::npos) << message;
    EXPECT_EQ(message.find("min_persistence"), std::string::npos) << message;
  }
  EXPECT_EQ(content_hash(dir / "c.h5"), before);
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.resume-tmp"));

  // The same options: nothing to compute.
  ExtractionOptions same = options;
  same.resume = true;
  const ExtractionSummary summary = extract_collection(inputs, classes, dir / "c.h5", same);
  EXPECT_EQ(summary.computed(), 0);
  EXPECT_EQ(summary.skipped, 8);
}

}  // namespace
}  // namespace reebkit::test

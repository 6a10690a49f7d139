// The shards of a multi-process extraction, merged (shard_merge.h), give the
// file one process writes, whatever went to which shard and in what order;
// resume plans only what no shard holds. The processes are played here by
// calls in one process: the MPI side is tested in tests/cluster/.
#include "reebkit/collection/shard_merge.h"

#include "collection/collection_test_util.h"
#include "reebkit/core/error.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <deque>
#include <thread>

namespace reebkit::test {
namespace {

/// An InputClaim handing out `inputs` in this order, then none.
InputClaim claims(std::deque<std::size_t> inputs) {
  return [queue = std::move(inputs)]() mutable -> std::optional<std::size_t> {
    if (queue.empty()) return std::nullopt;
    const std::size_t next = queue.front();
    queue.pop_front();
    return next;
  };
}

TEST(ShardMerge, ShardsMergedInInputOrderAreTheFileOfOneProcess) {
  const TempDir dir;
  const std::vector<MeshInput> inputs = write_collection(dir);  // broken.off, m1 ... m7
  const std::vector<PsbClass> classes = {{"star", "0", {"m1", "m3"}}, {"torus", "0", {"m6"}}};
  extract_collection(inputs, classes, dir / "one.h5", with_threads(2));

  const std::filesystem::path output = dir / "many.h5";
  const ExtractionOptions options = with_threads(2);
  check_extraction(inputs, classes, output, options);
  const ShardedJob job = plan_sharded_job(inputs, output, options);
  ASSERT_EQ(job.todo.size(), inputs.size());
  EXPECT_EQ(job.skipped, 0);
  EXPECT_TRUE(job.base.empty());
  // Three "processes", with inputs out of order and one with none.
  const ExtractionSummary first = extract_shard(inputs, classes, shard_path(output, 0), claims({7, 0, 3}), options);
  extract_shard(inputs, classes, shard_path(output, 1), claims({5, 1, 2, 6, 4}), with_threads(1));
  extract_shard(inputs, classes, shard_path(output, 2), claims({}), options);
  EXPECT_EQ(first.ok, 2);
  ASSERT_EQ(first.failed.size(), 1u);
  EXPECT_EQ(CollectionReader(shard_path(output, 0)).names(),
            (std::vector<std::string>{"m7.off", "broken.off", "m3.off"}));

  const ExtractionSummary merged = merge_shards(inputs, classes, output, job, options);
  EXPECT_EQ(merged.ok, 7);
  ASSERT_EQ(merged.failed.size(), 1u);
  EXPECT_EQ(merged.failed[0].name, "broken.off");
  EXPECT_EQ(merged.kept, 0);
  expect_same_files(dir / "one.h5", output);
  const CollectionReader one(dir / "one.h5"), many(output);
  EXPECT_EQ(many.provenance().classes.size(), 2u);
  EXPECT_EQ(many.provenance().options, one.provenance().options);
  EXPECT_EQ(many.class_labels()[3], "star");
  EXPECT_FALSE(std::filesystem::exists(shard_folder(output)));
}

TEST(ShardMerge, ResumePlansWhatNoShardHoldsWithItsContentAndTheMergeKeepsNamesUnique) {
  const TempDir dir;
  const std::vector<MeshInput> inputs = write_collection(dir);
  const std::filesystem::path output = dir / "c.h5";
  ExtractionOptions options = with_threads(2);
  plan_sharded_job(inputs, output, options);
  // A killed job: two shards holding four meshes.
  extract_shard(inputs, {}, shard_path(output, 0), claims({1, 3}), options);
  extract_shard(inputs, {}, shard_path(output, 1), claims({2, 4}), options);
  // m2 changes meanwhile; a shard that was killed while being created does not open.
  write_off(dir / "meshes/m2.off", make_star(StarOptions{2, 3}));
  std::ofstream(shard_path(output, 5)) << "not HDF5";

  options.resume = true;
  const ShardedJob job = plan_sharded_job(inputs, output, options);
  EXPECT_EQ(job.todo, (std::vector<std::size_t>{0, 2, 5, 6, 7}));
  EXPECT_EQ(job.skipped, 3);
  EXPECT_FALSE(std::filesystem::exists(shard_path(output, 5)));
  extract_shard(inputs, {}, shard_path(output, 0), claims({0, 2, 5, 6, 7}), options);  // resumes shard 0
  const ExtractionSummary merged = merge_shards(inputs, {}, output, job, options);
  EXPECT_EQ(merged.ok, 4);
  EXPECT_EQ(merged.failed.size(), 1u);
  EXPECT_EQ(merged.kept, 3);
  EXPECT_EQ(merged.skipped, 3);

  extract_collection(inputs, {}, dir / "one.h5", with_threads(1));
  expect_same_files(dir / "one.h5", output);  // m2 once, with its new content

  // The same analysis options or nothing.
  options.analysis.features.epsilon = 0.1;
  plan_sharded_job(inputs, dir / "d.h5", with_threads(1));
  extract_shard(inputs, {}, shard_path(dir / "d.h5", 0), claims({1}), with_threads(1));
  const std::string message = thrown_message<Error>([&] { plan_sharded_job(inputs, dir / "d.h5", options); });
  EXPECT_NE(message.find("rank-0.h5: cannot resume"), std::string::npos) << message;
  EXPECT_NE(message.find("epsilon: 0.15 in the file, 0.1 now"), std::string::npos) << message;
}

TEST(ShardMerge, ResumingOntoAFinishedFileKeepsItsEntriesFirstInItsOrder) {
  const TempDir dir;
  const std::vector<MeshInput> all = write_collection(dir);
  const std::filesystem::path output = dir / "c.h5";
  // The file holds m4 ... m7 (and broken.off); the job adds m1 ... m3.
  const std::vector<MeshInput> earlier(all.begin() + 4, all.end());
  extract_collection(earlier, {}, output, with_threads(2));
  ExtractionOptions options = with_threads(2);
  options.resume = true;
  const ShardedJob job = plan_sharded_job(all, output, options);
  EXPECT_EQ(job.base, output);
  EXPECT_EQ(job.todo, (std::vector<std::size_t>{0, 1, 2, 3}));
  extract_shard(all, {}, shard_path(output, 0), claims({3, 1}), options);
  extract_shard(all, {}, shard_path(output, 1), claims({0, 2}), options);
  merge_shards(all, {}, output, job, options);
  // What one process resuming the file writes.
  extract_collection(earlier, {}, dir / "one.h5", with_threads(2));
  extract_collection(all, {}, dir / "one.h5", options);
  expect_same_files(dir / "one.h5", output);
  EXPECT_EQ(CollectionReader(output).names().front(), "m4.off");

  // An input no shard holds: a clear error, the file left as it was.
  const ShardedJob again = plan_sharded_job(all, dir / "e.h5", with_threads(1));
  const std::string message =
      thrown_message<Error>([&] { merge_shards(all, {}, dir / "e.h5", again, with_threads(1)); });
  EXPECT_NE(message.find("no shard holds the mesh 'broken.off'"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(dir / "e.h5"));
}

}  // namespace
}  // namespace reebkit::test

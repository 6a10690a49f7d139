// Whole-file writes: atomic replacement (temporary file + rename), a failed
// write (file size limit, as on a full disk) leaves the previous file
// untouched and no temporary file, devices are written in place, and outputs
// are checked before any work.
#include "reebkit/io/file_bytes.h"

#include "io/io_test_util.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <unistd.h>

namespace reebkit::test {
namespace {

TEST(FileBytes, WriteReplacesTheFileAndLeavesNoTemporaryFile) {
  const TempDir dir;
  write_file_bytes(dir / "a.txt", "first");
  write_file_bytes(dir / "a.txt", "second, longer");
  EXPECT_EQ(read_file_bytes(dir / "a.txt"), "second, longer");
  write_file_bytes(dir / "a.txt", "");
  EXPECT_EQ(read_file_bytes(dir / "a.txt"), "");
  EXPECT_EQ(files_in(dir / ""), std::vector<std::string>{"a.txt"});
}

TEST(FileBytes, AFailedWriteLeavesThePreviousFileAndNoPartialFile) {
  const TempDir dir;
  const auto path = dir / "big.txt";
  write_file_bytes(path, "the previous content\n");
  // The child may write 1000 bytes per file: the new content cannot be written.
  const auto [status, message] = run_with_file_size_limit(1000, [&](int fd) {
    try {
      write_file_bytes(path, std::string(5000, 'x'));
    } catch (const MeshFileError& e) {
      const std::string what = e.what();
      (void)!::write(fd, what.data(), what.size());
    }
  });
  EXPECT_EQ(status, 0);
  EXPECT_TRUE(contains(message, {path.string(), "write error", "File too large"})) << message;
  EXPECT_EQ(read_file_bytes(path), "the previous content\n");
  EXPECT_EQ(files_in(dir / ""), std::vector<std::string>{"big.txt"});
}

TEST(FileBytes, AMissingFolderIsAnErrorNamingThePath) {
  const TempDir dir;
  const auto path = dir / "no_such_folder" / "a.txt";
  const std::string message = thrown_message<MeshFileError>([&] { write_file_bytes(path, "x"); });
  EXPECT_TRUE(contains(message, {path.string(), "cannot open for writing: No such file or directory"})) << message;
}

TEST(FileBytes, ADeviceIsWrittenInPlaceNeverReplaced) {
  write_file_bytes("/dev/null", "nothing");
  EXPECT_FALSE(std::filesystem::is_regular_file("/dev/null"));
  const std::string full = thrown_message<MeshFileError>([] { write_file_bytes("/dev/full", "x"); });
  EXPECT_TRUE(contains(full, {"/dev/full", "No space left on device"})) << full;
  EXPECT_FALSE(std::filesystem::is_regular_file("/dev/full"));
}

TEST(FileBytes, CheckOutputFileRefusesInputsFoldersAndMissingFolders) {
  const TempDir dir;
  write_file_bytes(dir / "in.off", "OFF\n");
  std::filesystem::create_symlink(dir / "in.off", dir / "link.off");
  check_output_file(dir / "out.json", {dir / "in.off"});
  check_output_file("/dev/null", {});
  for (const auto& input : {dir / "in.off", dir / "link.off"}) {
    const std::string message = thrown_message<InvalidArgument>([&] { check_output_file(input, {dir / "in.off"}); });
    EXPECT_TRUE(contains(message, {input.string(), "is an input"})) << message;
  }
  const std::string folder = thrown_message<InvalidArgument>([&] { check_output_file(dir / "", {}); });
  EXPECT_TRUE(contains(folder, {"is a folder"})) << folder;
  const auto missing = dir / "missing" / "out.json";
  const std::string message = thrown_message<InvalidArgument>([&] { check_output_file(missing, {}); });
  EXPECT_TRUE(contains(message, {missing.string(), "does not exist"})) << message;
  if (::geteuid() != 0) {  // root writes into read-only folders
    std::filesystem::create_directory(dir / "read_only");
    std::filesystem::permissions(dir / "read_only",
                                 std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    const std::string read_only =
        thrown_message<InvalidArgument>([&] { check_output_file(dir / "read_only" / "a", {}); });
    EXPECT_TRUE(contains(read_only, {"is not writable"})) << read_only;
  }
  const std::string proc = thrown_message<InvalidArgument>([&] { check_output_file("/proc/reebkit_out.json", {}); });
  EXPECT_TRUE(contains(proc, {"/proc/reebkit_out.json", "is not writable"})) << proc;
}

TEST(FileBytes, TwoOutputsOnOneFileAreRefusedByAnyOfTheirNames) {
  const TempDir dir;
  std::filesystem::create_directories(dir / "sub");
  std::filesystem::create_symlink("a.json", dir / "link.json");
  const std::vector<std::pair<std::filesystem::path, std::filesystem::path>> same = {{dir / "a.json", dir / "a.json"},
                                                                                     {dir / "a.json",
                                                                                      dir / "sub" / ".." / "a.json"},
                                                                                     {dir / "a.json",
                                                                                      dir / "link.json"}};
  for (const auto& pair : same) {
    const std::filesystem::path &first = pair.first, &second = pair.second;  // a lambda captures no binding in C++17
    const std::string message = thrown_message<InvalidArgument>([&] { check_output_files({first, "", second}); });
    EXPECT_TRUE(contains(message, {second.string() + ": is also the output " + first.string()})) << message;
  }
  EXPECT_NO_THROW(check_output_files({dir / "a.json", "", dir / "b.json"}));
}

TEST(FileBytes, AWriteThroughALinkReplacesItsFileAndKeepsTheLink) {
  const TempDir dir;
  write_file_bytes(dir / "a.json", "old\n");
  std::filesystem::create_symlink("a.json", dir / "link.json");
  EXPECT_EQ(resolved_output(dir / "link.json"), std::filesystem::weakly_canonical(dir / "a.json"));
  EXPECT_EQ(resolved_output(dir / "a.json"), dir / "a.json");
  write_file_bytes(dir / "link.json", "new\n");
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.json"));
  EXPECT_EQ(read_file_bytes(dir / "a.json"), "new\n");
  EXPECT_EQ(files_in(dir / ""), (std::vector<std::string>{"a.json", "link.json"}));
}

}  // namespace
}  // namespace reebkit::test

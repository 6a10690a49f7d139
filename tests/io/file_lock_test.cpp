// One writer per output: a second process asking for the lock is refused
// with the first one's pid; the lock file goes when the lock is released.
#include "reebkit/io/file_lock.h"

#include "io/io_test_util.h"
#include "reebkit/io/file_bytes.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <unistd.h>

namespace reebkit::test {
namespace {

/// What another process gets asking for the lock of `path`: "locked" or the error message.
std::string lock_in_another_process(const std::filesystem::path& path) {
  const auto [status, output] = run_with_file_size_limit(1 << 20, [&](int fd) {
    std::string result;
    try {
      const FileLock lock(path);
      result = "locked";
    } catch (const Error& e) {
      result = e.what();
    }
    (void)!::write(fd, result.data(), result.size());
  });
  EXPECT_EQ(status, 0);
  return output;
}

TEST(FileLock, ASecondWriterIsRefusedWithTheFirstOnesPid) {
  const TempDir dir;
  const auto path = dir / "c.h5";
  {
    const FileLock lock(path);
    EXPECT_EQ(lock.lock_file(), dir / "c.h5.lock");
    EXPECT_TRUE(std::filesystem::exists(lock.lock_file()));
    const std::string refused = lock_in_another_process(path);
    EXPECT_TRUE(contains(refused, {path.string(), "another process (pid " + std::to_string(::getpid()) + ")",
                                   (dir / "c.h5.lock").string()}))
        << refused;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "c.h5.lock"));
  EXPECT_EQ(lock_in_another_process(path), "locked");
  const FileLock again(path);  // released by the other process too
}

TEST(FileLock, AStaleLockFileIsNoLock) {
  const TempDir dir;
  write_bytes(dir / "c.h5.lock", "12345\n");  // left by a process killed with -9: no flock holds it
  const FileLock lock(dir / "c.h5");
  EXPECT_EQ(read_file_bytes(dir / "c.h5.lock"), std::to_string(::getpid()) + "\n");
}

TEST(FileLock, AFolderThatCannotHoldTheLockIsAnError) {
  const auto path = std::filesystem::path("/proc/no_such_folder/c.h5");
  const std::string message = thrown_message<Error>([&] { const FileLock lock(path); });
  EXPECT_TRUE(contains(message, {path.string(), "cannot create the lock file"})) << message;
}

}  // namespace
}  // namespace reebkit::test

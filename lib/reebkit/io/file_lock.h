// One writer per output: an advisory lock (flock) on the file PATH.lock,
// taken before the output is created or truncated and held for the writer's
// whole life. A second writer is refused at once, told the first one's pid;
// readers never take it, so they keep working while a file is written.
#pragma once

#include <filesystem>

namespace reebkit {

class FileLock {
 public:
  /// Takes the lock of `path` (the file `path` + ".lock", created, holding
  /// this process's pid). Throws Error naming `path`, the lock file and the
  /// pid of the process that holds it, or the reason the lock file cannot
  /// be created.
  explicit FileLock(const std::filesystem::path& path);
  /// Removes the lock file and releases the lock.
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  /// The lock file: `path` + ".lock".
  const std::filesystem::path& lock_file() const { return lock_file_; }

 private:
  std::filesystem::path lock_file_;
  int fd_ = -1;
};

}  // namespace reebkit

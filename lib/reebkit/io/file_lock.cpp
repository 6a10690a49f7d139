#include "reebkit/io/file_lock.h"

#include "reebkit/core/error.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace reebkit {

namespace {

/// The pid written in the lock file open as `fd`, or "unknown".
std::string holder_pid(int fd) {
  char text[32] = {};
  const ::ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string pid = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string();
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.empty() ? "unknown" : pid;
}

}  // namespace

FileLock::FileLock(const std::filesystem::path& path) : lock_file_(path.string() + ".lock") {
  // The holder removes the lock file when done: a lock taken on a file that
  // was removed (or replaced) meanwhile is no lock, so take it again then.
  for (;;) {
    const int fd = ::open(lock_file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0)
      throw Error(path.string() + ": cannot create the lock file " + lock_file_.string() + ": " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string pid = holder_pid(fd);
      ::close(fd);
      if (error == EWOULDBLOCK)
        throw Error(path.string() + ": another process (pid " + pid + ") is writing it (lock file " +
                    lock_file_.string() + "); wait for it to end or stop it");
      throw Error(path.string() + ": cannot lock " + lock_file_.string() + ": " + std::strerror(error));
    }
    struct stat held = {}, named = {};
    if (::fstat(fd, &held) == 0 && ::stat(lock_file_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      fd_ = fd;
      break;
    }
    ::close(fd);
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<::ssize_t>(pid.size())) {
    const std::string reason = std::strerror(errno);
    ::unlink(lock_file_.c_str());
    ::close(fd_);
    throw Error(path.string() + ": cannot write the lock file " + lock_file_.string() + ": " + reason);
  }
}

FileLock::~FileLock() {
  ::unlink(lock_file_.c_str());
  ::close(fd_);
}

}  // namespace reebkit

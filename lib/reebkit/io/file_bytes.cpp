#include "reebkit/io/file_bytes.h"

#include "reebkit/core/error.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <utility>

namespace reebkit {

namespace fs = std::filesystem;

namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

std::string system_reason() { return std::strerror(errno); }

fs::path folder_of(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

/// A new, empty file beside `path` (same folder, so that rename is atomic),
/// created exclusively; returns its descriptor and sets `name`.
int create_temporary_beside(const fs::path& path, fs::path& name) {
  static std::atomic<unsigned> counter{0};
  for (;;) {
    name = folder_of(path) /
           ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
}

/// Writes all of `bytes` to `fd`; false (errno set) on failure.
bool write_all(int fd, std::string_view bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ::ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) errno = EIO;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

std::string read_file_bytes(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw MeshFileError(path.string(), "file not found");
  if (!fs::is_regular_file(path, ec)) throw MeshFileError(path.string(), "not a regular file");
  const File file(std::fopen(path.c_str(), "rb"));
  if (!file) throw MeshFileError(path.string(), "cannot open for reading: " + system_reason());

  std::string bytes;
  const auto size = fs::file_size(path, ec);
  if (!ec) bytes.reserve(static_cast<std::size_t>(size));
  char chunk[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) bytes.append(chunk, got);
  if (std::ferror(file.get())) throw MeshFileError(path.string(), "read error: " + system_reason());
  return bytes;
}

void write_file_bytes(const fs::path& requested, std::string_view bytes) {
  const fs::path path = resolved_output(requested);
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec) && !fs::is_directory(path, ec)) {
    // A device or a pipe (/dev/stdout, a FIFO) is written to, never replaced.
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw MeshFileError(path.string(), "cannot open for writing: " + system_reason());
    const bool written = write_all(fd, bytes);
    const int error = errno;
    if (::close(fd) == 0 && written) return;
    if (!written) errno = error;
    throw MeshFileError(path.string(), "write error: " + system_reason());
  }
  fs::path temporary;
  const int fd = create_temporary_beside(path, temporary);
  if (fd < 0)
    throw MeshFileError(path.string(), "cannot open for writing: " + system_reason() + " (a new file in " +
                                           folder_of(path).string() + ")");
  const auto fail = [&](const std::string& doing) {
    const std::string reason = system_reason();
    ::unlink(temporary.c_str());
    throw MeshFileError(path.string(), doing + ": " + reason);
  };
  if (!write_all(fd, bytes) || ::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    errno = error;
    fail("write error");
  }
  if (::close(fd) != 0) fail("write error");
  if (::rename(temporary.c_str(), path.c_str()) != 0) fail("cannot replace it");
}

void check_output_file(const fs::path& path, const std::vector<fs::path>& inputs) {
  if (path.empty()) throw InvalidArgument("an output file name is empty");
  const auto refuse = [&](const std::string& problem) { throw InvalidArgument(path.string() + ": " + problem); };
  std::error_code ec;
  if (fs::exists(path, ec)) {
    if (fs::is_directory(path, ec)) refuse("is a folder, not a file");
    for (const fs::path& input : inputs)
      if (fs::equivalent(path, input, ec)) refuse("is an input of this command: refusing to overwrite it");
    if (!fs::is_regular_file(path, ec)) {  // a device or a pipe: written to in place
      if (::access(path.c_str(), W_OK) != 0) refuse("cannot write it: " + system_reason());
      return;
    }
  }
  const fs::path folder = folder_of(path);
  if (!fs::is_directory(folder, ec))
    refuse("cannot write it: " + (fs::exists(folder, ec) ? folder.string() + " is a file, not a folder"
                                                         : "the folder " + folder.string() + " does not exist"));
  // Creating a file there tells (access() says yes to root on a folder that cannot hold files, e.g. /proc).
  fs::path probe;
  const int fd = create_temporary_beside(path, probe);
  if (fd < 0) refuse("cannot write it: the folder " + folder.string() + " is not writable (" + system_reason() + ")");
  ::close(fd);
  ::unlink(probe.c_str());
}

void check_output_files(const std::vector<fs::path>& outputs, const std::vector<fs::path>& inputs) {
  std::vector<std::pair<fs::path, fs::path>> checked;  // as given, resolved
  for (const fs::path& output : outputs) {
    if (output.empty()) continue;
    check_output_file(output, inputs);
    std::error_code ec;
    fs::path resolved = fs::weakly_canonical(resolved_output(output), ec);
    if (ec) resolved = fs::absolute(output);
    for (const auto& [other, other_resolved] : checked)
      if (resolved == other_resolved)
        throw InvalidArgument(output.string() + ": is also the output " + other.string() +
                              " of this command: give each output its own file");
    checked.emplace_back(output, resolved);
  }
}

fs::path resolved_output(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_symlink(path, ec)) return path;
  // Followed link by link: a link to a file not created yet is resolved too.
  fs::path target = path;
  for (int hops = 0; hops < 40 && fs::is_symlink(target, ec); ++hops) {
    const fs::path next = fs::read_symlink(target, ec);
    if (ec) return path;
    target = next.is_absolute() ? next : folder_of(target) / next;
  }
  const fs::path resolved = fs::weakly_canonical(target, ec);
  return ec ? path : resolved;
}

}  // namespace reebkit

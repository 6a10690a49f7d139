#include "reebkit/io/file_bytes.h"

#include "reebkit/core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace reebkit {

namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

std::string system_reason() { return std::strerror(errno); }

}  // namespace

std::string read_file_bytes(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw MeshFileError(path.string(), "file not found");
  if (!std::filesystem::is_regular_file(path, ec)) throw MeshFileError(path.string(), "not a regular file");
  const File file(std::fopen(path.c_str(), "rb"));
  if (!file) throw MeshFileError(path.string(), "cannot open for reading: " + system_reason());

  std::string bytes;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec) bytes.reserve(static_cast<std::size_t>(size));
  char chunk[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) bytes.append(chunk, got);
  if (std::ferror(file.get())) throw MeshFileError(path.string(), "read error: " + system_reason());
  return bytes;
}

void write_file_bytes(const std::filesystem::path& path, std::string_view bytes) {
  const File file(std::fopen(path.c_str(), "wb"));
  if (!file) throw MeshFileError(path.string(), "cannot open for writing: " + system_reason());
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size() || std::fflush(file.get()) != 0) {
    throw MeshFileError(path.string(), "write error: " + system_reason());
  }
}

}  // namespace reebkit

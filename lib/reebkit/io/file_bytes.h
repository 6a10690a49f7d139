// Whole-file reads and writes shared by every mesh format: a reader gets the
// file's bytes in one piece, a writer hands over one finished buffer.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace reebkit {

/// The complete contents of `path`.
/// Throws MeshFileError when the file is missing, is not a regular file or cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

/// Replaces the contents of `path` by `bytes`.
/// Throws MeshFileError when the file cannot be created or written.
void write_file_bytes(const std::filesystem::path& path, std::string_view bytes);

}  // namespace reebkit

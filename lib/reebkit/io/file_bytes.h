// Whole-file reads and writes shared by every format: a reader gets the
// file's bytes in one piece, a writer hands over one finished buffer, which
// replaces the file atomically (temporary file beside it, rename), so that a
// failed write never leaves a partial file nor touches the previous one.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace reebkit {

/// The complete contents of `path`.
/// Throws MeshFileError when the file is missing, is not a regular file or cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

/// Replaces the contents of `path` by `bytes`, atomically: the bytes go to a
/// new file in the same folder (`.NAME.tmp-PID-N`), every write checked,
/// fsync'd and closed, then renamed over `path`. On any failure the
/// temporary file is removed and `path` is left as it was. An existing
/// `path` that is a device or a pipe (/dev/null, /dev/stdout, a FIFO) is
/// written to in place, never replaced.
/// A symbolic link is followed: the file it points to is replaced
/// (resolved_output), the link stays.
/// Throws MeshFileError naming `path` and the reason (e.g. "No space left on device").
void write_file_bytes(const std::filesystem::path& path, std::string_view bytes);

/// Checks, before any work, that `path` can be written as an output file:
/// not empty, not a folder, none of `inputs` (same file, by path or by
/// link), and its folder exists and is writable (a device or a pipe: it is
/// writable itself). Throws InvalidArgument
/// naming `path` and the problem.
void check_output_file(const std::filesystem::path& path, const std::vector<std::filesystem::path>& inputs = {});

/// The same for several outputs of one command, which must moreover name
/// different files (two outputs on one file: one would be lost). Empty
/// paths in `outputs` are skipped (an output not asked for).
void check_output_files(const std::vector<std::filesystem::path>& outputs,
                        const std::vector<std::filesystem::path>& inputs = {});

/// The file a write to `path` reaches: when `path` is a symbolic link, the
/// file it points to (links followed to the end, folders made absolute),
/// otherwise `path` itself. Outputs are locked, compared and replaced under
/// this name, so that a link is no second name of a file that skips its
/// lock, and is not itself replaced by a file.
std::filesystem::path resolved_output(const std::filesystem::path& path);

}  // namespace reebkit

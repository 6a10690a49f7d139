// Helpers shared by the test executables: where test data lives, and skipping
// with a clear message when the shared datasets are absent.
#pragma once

#include "reebkit/core/mesh.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace reebkit::test {

/// Folder of hand-written fixtures committed under tests/data.
std::filesystem::path fixture_dir();
/// Path of a committed fixture under tests/data.
std::filesystem::path fixture(const std::string& name);
/// Folder of the committed meshes under datasets/.
std::filesystem::path embedded_dataset_dir();

/// Unpacked shared dataset folder (e.g. "cgal_meshes", "shrec07_watertight",
/// "tosca_dev"), or nullopt when ../shared/datasets is not beside the checkout.
std::optional<std::filesystem::path> shared_dataset(const std::string& folder);

/// The message of the exception of type E that `action` throws; a test
/// failure and "" when it throws none.
template <typename E, typename Action>
std::string thrown_message(Action&& action) {
  try {
    action();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an exception";
  return "";
}

/// Exit status and standard output of a shell command (for end-to-end tests
/// of the `reeb` binary); -1 when it did not exit normally.
std::pair<int, std::string> run_command(const std::string& command);
/// `path` in single quotes, for a shell command line.
std::string shell_quoted(const std::filesystem::path& path);
/// The names of the files (and folders) in `folder`, sorted.
std::vector<std::string> files_in(const std::filesystem::path& folder);

/// A shell command line that runs `command` (one program and its arguments,
/// no redirections) with files limited to `bytes` (RLIMIT_FSIZE) and SIGXFSZ
/// at its default action, which kills the process at a write past the
/// limit unless it ignores the signal: `reeb` does, so that the write fails
/// with EFBIG as on a full disk.
std::string with_file_size_limit(const std::string& command, std::uint64_t bytes);

/// Runs `body` in a forked child with files limited to `bytes`
/// (RLIMIT_FSIZE, SIGXFSZ ignored) and returns its exit status (-1 when it
/// was killed by a signal) and what it wrote to the pipe end it is given
/// and to its standard error (which goes to that pipe too).
/// The child leaves with exit(0) after `body` (HDF5 and the C++ runtime
/// clean up as in a real program), exit(3) when `body` throws.
std::pair<int, std::string> run_with_file_size_limit(std::uint64_t bytes, const std::function<void(int fd)>& body);

/// A capsule along z: a cylinder of radius r from z = -half_length to
/// +half_length closed by two hemispheres, `sides` vertices per ring, rings
/// about `sides`/2pi per unit of length on the cylinder and `cap_rings` per
/// hemisphere (its equator included), a pole at each end.
Mesh make_capsule(double r, double half_length, int sides, int cap_rings);

}  // namespace reebkit::test

/// Binds `var` to the unpacked shared dataset `folder`, or skips the test with
/// a message saying which folder is missing.
#define REEBKIT_REQUIRE_DATASET(var, folder)                                                            \
  const auto var##_opt = ::reebkit::test::shared_dataset(folder);                                       \
  if (!var##_opt) {                                                                                     \
    GTEST_SKIP() << "shared dataset '" << folder << "' not found (expected " << REEBKIT_SHARED_DATASETS \
                 << " unpacked into " << REEBKIT_UNPACKED_DATASETS << "); skipping";                    \
  }                                                                                                     \
  const std::filesystem::path var = *var##_opt

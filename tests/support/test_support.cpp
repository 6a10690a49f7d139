#include "support/test_support.h"

#include <sys/wait.h>

#include <cstdio>

namespace reebkit::test {

std::filesystem::path fixture_dir() { return REEBKIT_TEST_DATA_DIR; }

std::filesystem::path fixture(const std::string& name) { return fixture_dir() / name; }

std::filesystem::path embedded_dataset_dir() {
  return std::filesystem::path(REEBKIT_SOURCE_DIR) / "datasets";
}

std::optional<std::filesystem::path> shared_dataset(const std::string& folder) {
  const std::filesystem::path unpacked = std::filesystem::path(REEBKIT_UNPACKED_DATASETS) / folder;
  if (std::filesystem::is_directory(unpacked)) return unpacked;
  return std::nullopt;
}

std::pair<int, std::string> run_command(const std::string& command) {
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return {-1, "popen failed"};
  std::string output;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

std::string shell_quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

}  // namespace reebkit::test

#include "support/test_support.h"

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

}  // namespace reebkit::test

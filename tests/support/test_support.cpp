#include "support/test_support.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

namespace reebkit::test {

std::filesystem::path fixture_dir() { return REEBKIT_TEST_DATA_DIR; }

std::filesystem::path fixture(const std::string& name) { return fixture_dir() / name; }

std::filesystem::path embedded_dataset_dir() { return std::filesystem::path(REEBKIT_SOURCE_DIR) / "datasets"; }

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

std::vector<std::string> files_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

std::string with_file_size_limit(const std::string& command, std::uint64_t bytes) {
  const std::string limit = std::to_string(bytes);
  return "exec prlimit --fsize=" + limit + ":" + limit + " env --default-signal=XFSZ " + command;
}

std::pair<int, std::string> run_with_file_size_limit(std::uint64_t bytes, const std::function<void(int fd)>& body) {
  int fds[2];
  if (::pipe(fds) != 0) return {-1, "pipe failed"};
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) return {-1, "fork failed"};
  if (child == 0) {
    ::close(fds[0]);
    ::dup2(fds[1], STDERR_FILENO);
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit = {bytes, bytes};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      body(fds[1]);
    } catch (...) {
      std::exit(3);
    }
    std::exit(0);
  }
  ::close(fds[1]);
  std::string output;
  char buffer[4096];
  for (::ssize_t n = 0; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;)
    output.append(buffer, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

Mesh make_capsule(double r, double half_length, int sides, int cap_rings) {
  std::vector<std::pair<double, double>> rings;  // (radius, z), south to north
  for (int j = 1; j <= cap_rings; ++j) {
    const double theta = 0.5 * static_cast<double>(EIGEN_PI) * j / cap_rings;
    rings.emplace_back(r * std::sin(theta), -half_length - r * std::cos(theta));
  }
  const int cylinder =
      static_cast<int>(std::lround(2.0 * half_length * sides / (2.0 * static_cast<double>(EIGEN_PI) * r)));
  for (int j = 1; j < cylinder; ++j) rings.emplace_back(r, -half_length + 2.0 * half_length * j / cylinder);
  for (int j = cap_rings; j >= 1; --j) {
    const double theta = 0.5 * static_cast<double>(EIGEN_PI) * j / cap_rings;
    rings.emplace_back(r * std::sin(theta), half_length + r * std::cos(theta));
  }
  const Index ring_count = static_cast<Index>(rings.size());
  Mesh m;
  m.vertices.resize(ring_count * sides + 2, 3);
  for (Index i = 0; i < ring_count; ++i)
    for (int j = 0; j < sides; ++j) {
      const double phi = 2.0 * static_cast<double>(EIGEN_PI) * j / sides;
      m.vertices.row(i * sides + j) << rings[i].first * std::cos(phi), rings[i].first * std::sin(phi), rings[i].second;
    }
  const Index south = ring_count * sides, north = south + 1;
  m.vertices.row(south) << 0, 0, -half_length - r;
  m.vertices.row(north) << 0, 0, half_length + r;
  std::vector<Index> t;
  const auto at = [&](Index ring, int j) { return ring * sides + (j % sides); };
  for (int j = 0; j < sides; ++j) {
    t.insert(t.end(), {south, at(0, j + 1), at(0, j)});
    for (Index i = 0; i + 1 < ring_count; ++i)
      t.insert(t.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    t.insert(t.end(), {north, at(ring_count - 1, j), at(ring_count - 1, j + 1)});
  }
  m.triangles = Eigen::Map<Triangles>(t.data(), static_cast<Index>(t.size() / 3), 3);
  return m;
}

}  // namespace reebkit::test

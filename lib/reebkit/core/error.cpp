#include "reebkit/core/error.h"

#include <utility>

namespace reebkit {

namespace {
std::string located(const std::string& file, std::uint64_t line, const std::string& problem) {
  std::string where = file.empty() ? std::string("<memory>") : file;
  if (line > 0) where += ":" + std::to_string(line);
  return where + ": " + problem;
}
}  // namespace

MeshFileError::MeshFileError(std::string file, std::uint64_t line, std::string problem)
    : Error(located(file, line, problem)), file_(std::move(file)), line_(line), problem_(std::move(problem)) {}

MeshFileError::MeshFileError(std::string file, std::string problem)
    : MeshFileError(std::move(file), 0, std::move(problem)) {}

InvalidMeshError::InvalidMeshError(std::string source, std::string problem)
    : Error(located(source, 0, problem)), source_(std::move(source)), problem_(std::move(problem)) {}

}  // namespace reebkit

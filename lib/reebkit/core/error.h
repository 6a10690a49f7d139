// The exception types of reebkit. Every message names the file (when there is
// one) and the problem; parse errors also name the line or element.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace reebkit {

/// Base class of every error reebkit throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A mesh file that cannot be opened or parsed.
/// what() reads "<file>:<line>: <problem>" (line 0 = not line-based, e.g. binary).
class MeshFileError : public Error {
 public:
  MeshFileError(std::string file, std::uint64_t line, std::string problem);
  MeshFileError(std::string file, std::string problem);

  const std::string& file() const { return file_; }
  std::uint64_t line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  std::uint64_t line_ = 0;
  std::string problem_;
};

/// A mesh that parsed but cannot be used (no faces, every face degenerate,
/// non-finite coordinates, ...). what() reads "<source>: <problem>".
class InvalidMeshError : public Error {
 public:
  InvalidMeshError(std::string source, std::string problem);

  const std::string& source() const { return source_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string source_;
  std::string problem_;
};

/// A caller broke a documented precondition (bad option value, vertex id out
/// of range, ...).
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

}  // namespace reebkit

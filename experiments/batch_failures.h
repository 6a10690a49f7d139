// The meshes a batch tool of experiments/ could not describe. One bad mesh
// in a batch is reported and skipped, never the end of the run (a failed
// entry of `reeb distances` gets the largest distance and the matrix is
// still written): each failure is reported on standard error when it
// happens and all are listed again at the end; the run fails only when
// every mesh did.
#pragma once

#include <cstddef>
#include <iostream>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

class BatchFailures {
 public:
  explicit BatchFailures(std::string tool) : tool_(std::move(tool)) {}

  /// Reports that `mesh` failed and why (safe from several threads); the
  /// mesh is named first unless `why` names it already.
  void add(const std::string& why, const std::string& mesh = "") {
    const std::string line = mesh.empty() || why.find(mesh) != std::string::npos ? why : mesh + ": " + why;
    const std::lock_guard<std::mutex> lock(mutex_);
    std::cerr << tool_ << ": skipped: " << line << "\n";
    failures_.push_back(line);
  }

  std::size_t size() const { return failures_.size(); }

  /// Lists the failures on standard error and returns the exit status: 1
  /// when all `attempted` meshes failed, else 0.
  int finish(std::size_t attempted) const {
    if (!failures_.empty()) {
      std::cerr << tool_ << ": " << failures_.size() << " of " << attempted << " meshes failed:\n";
      for (const std::string& why : failures_) std::cerr << "  " << why << "\n";
    }
    return attempted > 0 && failures_.size() == attempted ? 1 : 0;
  }

 private:
  std::string tool_;
  std::mutex mutex_;
  std::vector<std::string> failures_;
};

// Wall-clock timing of pipeline steps, in milliseconds.
#pragma once

#include <chrono>

namespace reebkit {

class Timer {
 public:
  Timer() : start_(std::chrono::steady_clock::now()) {}
  /// Milliseconds since construction or the last lap().
  double lap() {
    const double ms = elapsed();
    start_ = std::chrono::steady_clock::now();
    return ms;
  }
  /// Milliseconds since construction or the last lap(), without starting a new lap.
  double elapsed() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace reebkit

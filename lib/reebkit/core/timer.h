// Wall-clock timing of pipeline steps, in milliseconds.
#pragma once

#include <chrono>

namespace reebkit {

class Timer {
 public:
  Timer() : start_(std::chrono::steady_clock::now()) {}
  /// Milliseconds since construction or the last lap().
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - start_).count();
    start_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace reebkit

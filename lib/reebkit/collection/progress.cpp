#include "reebkit/collection/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>

namespace reebkit {
namespace {

/// "1:05:03", "4:07" or "9 s".
std::string clock_text(double seconds) {
  const long s = std::lround(seconds);
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else if (s >= 60)
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld s", s);
  return text;
}

std::string counts_text(const ProgressState& state, const std::string& unit) {
  char text[200];
  std::snprintf(text, sizeof text, "%lld/%lld  %.1f %s/s  ETA %s", static_cast<long long>(state.done()),
                static_cast<long long>(state.total), state.rate(), unit.c_str(),
                state.eta() < 0 ? "?" : clock_text(state.eta()).c_str());
  std::string out = text;
  if (state.failed > 0) out += "  " + std::to_string(state.failed) + " failed";
  if (state.skipped > 0) out += "  " + std::to_string(state.skipped) + " already indexed";
  return out;
}

}  // namespace

double ProgressState::rate() const {
  const std::int64_t computed = ok + failed;
  return seconds > 0 && computed > 0 ? static_cast<double>(computed) / seconds : 0.0;
}

double ProgressState::eta() const {
  const double r = rate();
  if (done() >= total) return 0.0;
  return r > 0 ? static_cast<double>(total - done()) / r : -1.0;
}

ProgressBar::ProgressBar(std::ostream& out, bool terminal, double line_seconds, std::string verb, std::string unit)
    : out_(&out), terminal_(terminal), line_seconds_(line_seconds), verb_(std::move(verb)), unit_(std::move(unit)) {}

ProgressBar ProgressBar::for_stderr(std::string verb, std::string unit) {
  return ProgressBar(std::cerr, ::isatty(STDERR_FILENO) != 0, 10.0, std::move(verb), std::move(unit));
}

void ProgressBar::operator()(const ProgressState& state) {
  if (state.seconds - last_ < (terminal_ ? 0.1 : line_seconds_) && state.done() < state.total) return;
  last_ = state.seconds;
  if (!terminal_) {
    *out_ << verb_ << " " << counts_text(state, unit_) << "\n" << std::flush;
    return;
  }
  constexpr int kWidth = 30;
  const double fraction = state.total > 0 ? static_cast<double>(state.done()) / static_cast<double>(state.total) : 1.0;
  const int filled = static_cast<int>(fraction * kWidth);
  *out_ << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
        << std::string(static_cast<std::size_t>(kWidth - filled), '.') << "] " << counts_text(state, unit_) << "\033[K"
        << std::flush;
}

void ProgressBar::clear() {
  if (terminal_) *out_ << "\r\033[K" << std::flush;
}

void ProgressBar::finish(const ProgressState& state) {
  clear();
  char text[200];
  std::snprintf(text, sizeof text,
                "%lld meshes: %lld ok, %lld failed, %lld already indexed, in %.2f s (%.1f meshes/s)\n",
                static_cast<long long>(state.total), static_cast<long long>(state.ok),
                static_cast<long long>(state.failed), static_cast<long long>(state.skipped), state.seconds,
                state.rate());
  *out_ << text << std::flush;
}

}  // namespace reebkit

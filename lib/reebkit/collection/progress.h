// Progress of a long batch (reeb index, reeb distances): a bar with the count, the rate and
// the time left, redrawn in place on a terminal, or plain lines now and then
// when stderr goes to a file or a pipe, and a summary line at the end.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

namespace reebkit {

/// Where a batch stands.
struct ProgressState {
  std::int64_t total = 0;    ///< items in the batch
  std::int64_t ok = 0;       ///< computed
  std::int64_t failed = 0;   ///< computed and failed
  std::int64_t skipped = 0;  ///< already done (resume): not computed
  double seconds = 0;        ///< since the batch started
  std::int64_t done() const { return ok + failed + skipped; }
  /// Items computed per second (skipped ones excluded); 0 before any.
  double rate() const;
  /// Seconds left at the current rate; negative when unknown.
  double eta() const;
};

/// Receives the state after each step of a batch.
using ProgressSink = std::function<void(const ProgressState&)>;

/// A ProgressSink that draws on `out`.
class ProgressBar {
 public:
  /// `terminal`: redraw one line in place (at most every 0.1 s); otherwise
  /// print a line every `line_seconds` (and at the end). The lines say
  /// "<verb> <done>/<total>  <rate> <unit>/s  ETA ...".
  ProgressBar(std::ostream& out, bool terminal, double line_seconds = 10.0, std::string verb = "indexed",
              std::string unit = "meshes");
  /// A bar for std::cerr, in place when stderr is a terminal (isatty).
  static ProgressBar for_stderr(std::string verb = "indexed", std::string unit = "meshes");

  void operator()(const ProgressState& state);
  /// The final line: "<n> meshes: <ok> ok, <failed> failed, <skipped>
  /// already indexed, in <s> s (<rate> meshes/s)".
  void finish(const ProgressState& state);
  /// Clears the line drawn in place (nothing to clear on plain lines).
  void clear();

 private:
  std::ostream* out_;
  bool terminal_;
  double line_seconds_;
  std::string verb_, unit_;
  double last_ = -1e300;  ///< state.seconds of the last drawing
};

}  // namespace reebkit

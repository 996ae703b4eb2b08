#pragma once
// Progress with ETA: a redrawn line on a terminal (stderr), or one JSON object per line on
// stdout for schedulers and dashboards (--progress=json; docs/batch.md).

#include <chrono>
#include <string>

namespace systole::clip {

enum class ProgressStyle {
  kNone,      ///< Every call is a no-op (pipes, tests).
  kTerminal,  ///< One line on stderr, redrawn at most ~10 times a second, cleared at the end.
  kJson,      ///< {"job":..,"frame":..,"frames":..,"fps":..,"eta_s":..} lines on stdout,
              ///< at most ~2 a second plus the last frame.
};

class Progress {
 public:
  Progress(std::string label, int total, ProgressStyle style);
  /// Reports `done` of `total` frames finished.
  void update(int done);
  /// Clears the terminal line.
  void finish();

  /// True when stderr is a terminal.
  static bool stderr_is_terminal();

 private:
  std::string label_;
  int total_;
  ProgressStyle style_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace systole::clip

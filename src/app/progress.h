#pragma once
// A one-line progress report with ETA on stderr, only when stderr is a terminal.

#include <chrono>
#include <string>

namespace systole::app {

class Progress {
 public:
  /// `enabled` false makes every call a no-op (batch runs, pipes, tests).
  Progress(std::string label, int total, bool enabled);
  /// Reports `done` of `total` units finished; redraws at most ~10 times a second.
  void update(int done);
  /// Clears the line.
  void finish();

  /// True when stderr is a terminal.
  static bool stderr_is_terminal();

 private:
  std::string label_;
  int total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace systole::app

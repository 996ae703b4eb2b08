#pragma once
// Output that appears whole or not at all. Data goes to a temporary file beside the
// target (same directory, so the final rename is atomic on POSIX file systems);
// commit() renames it over the target. Destroyed without commit() - an error, an
// exception, an interrupt - the temporary is removed and any earlier output stays
// untouched.

#include <filesystem>

namespace systole {

class AtomicOutput {
 public:
  /// Checks that the target's directory exists and is writable; throws
  /// Error(kCannotCreate) naming the path otherwise. Creates no file yet.
  explicit AtomicOutput(std::filesystem::path target);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& target() const { return target_; }
  /// Where to write: `.<name>.partial-<pid>-<n><ext>` beside the target (the extension
  /// is kept so libraries that guess a format from it still do).
  const std::filesystem::path& temp_path() const { return temp_; }

  /// Renames the temporary over the target. Throws Error(kIoError) on failure.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  bool committed_ = false;
  int slot_ = -1;  // Entry in the signal-safe table of pending temporaries.
};

/// Removes every temporary file still registered by a live AtomicOutput. Safe to call
/// from a signal handler (it uses only unlink on pre-built paths).
void remove_pending_outputs_signal_safe();

}  // namespace systole

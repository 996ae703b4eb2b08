#pragma once
// Output that appears whole or not at all, written by one process at a time, and whose
// leftovers the next run cleans up.
//
// Data goes to a temporary file beside the target (same directory, so the final rename is
// atomic on POSIX file systems); commit() renames it over the target. Destroyed without
// commit() - an error, an exception, an interrupt (common/interrupt.h) - the temporary is
// removed and any earlier output stays untouched. A set of files that must replace their
// namesakes in a folder together (a PNG sequence) is common/folder_update.h's job.
//
// While it lives, an AtomicOutput holds an exclusive lock on `.<name>.lock` beside the
// target (flock: released by the kernel when the process dies, however it dies; on NFS
// Linux maps it to a byte-range lock the server arbitrates, so nodes sharing a folder see
// each other). A second writer of the same target is refused (ExitCode::kBusy). A
// temporary or lock file whose lock nobody holds belongs to a process that died (SIGKILL,
// an OOM kill, a lost node): the first output written in a folder, and
// sweep_stale_outputs(), remove it.

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string_view>

namespace systole {

/// The exclusive right to write `target`: the lock on `.<name>.lock` beside it, held while
/// this lives. A run claims its outputs before its costly set-up (building the world), so a
/// second run of the same target is refused at once; the AtomicOutput it makes later on the
/// same thread joins the claim instead of being refused by it. Another thread or process is
/// refused (Error(kBusy), naming the holder), as is a second writer (`as_writer`, what
/// AtomicOutput passes) of one target. Throws Error(kCannotCreate) if the lock file cannot
/// be made. A folder's lock (a PNG sequence) is its own `.<folder>.lock` beside it.
class OutputLock {
 public:
  explicit OutputLock(std::filesystem::path target, bool as_writer = false);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  std::filesystem::path lock_path_;
  bool writer_;
};

class AtomicOutput {
 public:
  /// Checks that the target's directory exists and is writable and takes the target's
  /// lock; throws Error(kCannotCreate) naming the path, or Error(kBusy) naming the process
  /// that holds the lock. Creates no data file yet.
  explicit AtomicOutput(std::filesystem::path target);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& target() const { return target_; }
  /// Where to write: `.<name>.partial-<pid>-<n><ext>` beside the target (the extension
  /// is kept so libraries that guess a format from it still do).
  const std::filesystem::path& temp_path() const { return temp_; }

  /// Renames the temporary over the target and releases the lock. Throws Error(kIoError)
  /// on failure.
  void commit();

 private:
  void release();

  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::optional<OutputLock> lock_;
  bool committed_ = false;
  int temp_slot_ = -1;  // Entry in the signal-safe table of pending files.
};

/// Writes the file `target` whole or not at all, its contents streamed by `fill` into an
/// AtomicOutput's temporary (a large file need not sit in memory whole). Throws
/// Error(kCannotCreate) when the folder cannot take it, Error(kBusy) when another writer
/// holds it, Error(kIoError) when writing fails part-way; whatever `fill` throws passes
/// through. On any failure the earlier target stays and no temporary is left.
void write_atomically(const std::filesystem::path& target, const std::function<void(std::ostream&)>& fill);

/// The same with the contents in memory.
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

/// The lock file that guards `target`: `.<name>.lock` beside it.
std::filesystem::path lock_path_of(const std::filesystem::path& target);

/// Removes, in `dir`, every temporary and lock file of an AtomicOutput whose lock nobody
/// holds (its writer died). Files of live writers, here or on another node, are left.
/// Returns how many files it removed; errors reading the folder are ignored (a sweep is
/// housekeeping, never a reason to fail a run).
int sweep_stale_outputs(const std::filesystem::path& dir);

}  // namespace systole

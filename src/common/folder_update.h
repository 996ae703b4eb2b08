#pragma once
// Files that replace their namesakes in a folder together, when a run completes, or not at
// all: a PNG sequence (encode/png.h). The folder's other files are never touched.
//
// The new files are written to a staging folder beside the folder,
// `.<name>.staging-<pid>-<n>` (inside it when the folder is a mount point: a rename cannot
// leave a file system). commit() puts them in place:
// - a folder that does not exist yet is the staging folder renamed: it appears whole;
// - otherwise the journal `.<name>.journal` beside the folder, naming the staging folder,
//   is written first. From then on the update is decided: each file is renamed over its
//   namesake (300 renames take milliseconds), and the journal goes last.
// A run that dies before the journal leaves the folder as it was; after it, the folder is
// finishable: the next update of that folder finishes the renames before anything else,
// and removes every staging folder a dead run left. SIGINT and SIGTERM wait for the
// renames (common/interrupt.h), so only SIGKILL or a lost machine can leave the mix, and
// only until that next run. Like AtomicOutput, nothing is fsync'ed: this is about the
// process dying, not the machine.
//
// Per-file renames rather than one renameat2(RENAME_EXCHANGE) of the whole folder with a
// copy of it (the new files plus hard links of the others): that works on any file system
// with rename(2), NFS included (which has no RENAME_EXCHANGE), and it leaves the folder
// itself - its inode, owner, mode, subfolders, an open shell in it - as it was; an exchange
// would need hard links (not everywhere), copies of subfolders, and the folder's metadata
// copied by hand. docs/robustness.md, "An interrupted PNG sequence".

#include <filesystem>
#include <functional>
#include <string>

#include "common/atomic_output.h"

namespace systole {

/// The folder that an update of `dir` writes, and whose lock guards it: "frames/" is
/// "frames", "." and ".." are made absolute (a folder needs a name and a parent to have a
/// lock and a staging folder beside it), and a symbolic link is followed (so the staging
/// folder is on the folder's own file system). A run's claim (OutputLock) and its
/// FolderUpdate name it alike. Throws Error(kCannotCreate) for "/" or an empty path.
std::filesystem::path update_folder_of(std::filesystem::path dir);

class FolderUpdate {
 public:
  /// Makes `folder`'s parents, takes its lock (joining the run's claim on this thread,
  /// else refused with Error(kBusy) while another run holds it), finishes an update a
  /// killed run had committed to, removes the staging folders dead runs left, and makes this
  /// update's staging folder. The folder itself is made only by commit(). Throws
  /// Error(kCannotCreate) when the folder cannot be written (a file has its name, it is
  /// read-only), Error(kIoError) when a killed update cannot be finished.
  explicit FolderUpdate(const std::filesystem::path& folder);
  /// Without commit(): removes the staging folder; the folder stays as it was.
  ~FolderUpdate();
  FolderUpdate(const FolderUpdate&) = delete;
  FolderUpdate& operator=(const FolderUpdate&) = delete;

  /// The folder being updated, as update_folder_of() gives it.
  const std::filesystem::path& folder() const { return folder_; }
  /// Where to write the new file `name` (a plain file name). Safe from any thread.
  std::filesystem::path staged_path(const std::string& name) const { return staging_ / name; }

  /// Puts every staged file in the folder, over its namesake, as described above, and notes
  /// the folder as written (common/interrupt.h). `after_each_move` is called with the count
  /// moved so far: tests stop a commit part-way with it. Throws Error(kCannotCreate) when a
  /// staged name is a folder's in the folder (before anything moves), Error(kIoError) when
  /// the journal or a rename fails (a failed rename leaves the journal, so the next update
  /// finishes the move).
  void commit(const std::function<void(int moved)>& after_each_move = nullptr);

 private:
  void write_journal() const;

  std::filesystem::path folder_;
  OutputLock lock_;
  std::filesystem::path staging_;
  int staging_slot_ = -1;  // Entry in the signal handler's table (common/interrupt.h).
  bool decided_ = false;   // The journal is written: the staging folder belongs to the folder now.
  bool committed_ = false;
};

/// The journal of `folder`'s update: `.<name>.journal` beside it.
std::filesystem::path journal_path_of(const std::filesystem::path& folder);

}  // namespace systole

#pragma once
// What a SIGINT/SIGTERM handler may rely on (cli/main.cpp has the handler): the temporaries
// it removes, the moments it must wait for, and the outputs it can say were written.
//
// - Pending files and folders: every temporary and lock file of a live writer is kept in a
//   fixed table of plain paths, so the handler removes them without allocating or locking.
// - Commits: while an output is put in place (a rename; a PNG sequence's moves), a signal
//   waits for it to end (InterruptsWait), so no output is left half put in place by Ctrl-C
//   and what the handler then says is true.
// - Written outputs: every committed output is noted, so the handler can name them instead
//   of claiming that nothing was written.
//
// Everything a handler calls here is async-signal-safe: lock-free atomics, and only
// open/getdents64/unlink/unlinkat/rmdir/close on paths built beforehand.

#include <filesystem>
#include <string_view>

namespace systole {

/// Registers a temporary or lock file for the handler to unlink. Returns its slot, or -1
/// when the table is full (the owner's destructor still removes it; only a signal misses it).
int register_pending_file(const std::filesystem::path& file);

/// Registers a temporary folder holding only files (a PNG sequence's staging folder): the
/// handler unlinks its files, then removes it.
int register_pending_folder(const std::filesystem::path& folder);

/// Forgets slot `slot` (-1 is ignored): its file was committed or removed.
void unregister_pending(int slot);

/// Removes every temporary and lock file, and every temporary folder, still registered.
/// Safe to call from a signal handler.
void remove_pending_outputs_signal_safe();

/// For the handler, first thing: true when an output is being put in place. The signal is
/// then kept, the handler returns at once, and the commit raises it again when it ends.
bool interrupt_deferred_signal_safe(int sig);

/// While one lives, SIGINT and SIGTERM wait (through a handler that asks
/// interrupt_deferred_signal_safe). Its destructor raises a signal that came meanwhile, on
/// this thread, once no other InterruptsWait is alive.
class InterruptsWait {
 public:
  InterruptsWait();
  ~InterruptsWait();
  InterruptsWait(const InterruptsWait&) = delete;
  InterruptsWait& operator=(const InterruptsWait&) = delete;
};

/// Notes that `output` is complete, for the handler's message. Call it inside the commit's
/// InterruptsWait, so a signal cannot come between the output and the note.
void note_output_written(const std::filesystem::path& output);

/// The outputs noted so far in this process, quoted and separated by ", " (the first
/// 2 KiB; "..." ends a list that did not fit); empty if none. Safe in a signal handler.
std::string_view outputs_written_signal_safe();

}  // namespace systole

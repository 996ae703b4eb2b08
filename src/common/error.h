#pragma once
// Errors that reach the user. Every module below cli/ reports failure by throwing
// systole::Error with the exit code the command line should return; only cli/ exits.

#include <stdexcept>
#include <string>

namespace systole {

/// Process exit codes (sysexits.h where one fits; docs/cli.md lists them).
enum class ExitCode : int {
  kOk = 0,
  kDiffers = 1,        ///< `compare`: the images differ beyond the tolerances.
  kUsage = 64,         ///< Bad command-line usage.
  kDataError = 65,     ///< Bad scene or mesh data.
  kNoInput = 66,       ///< An input file is missing or unreadable.
  kInternal = 70,      ///< A bug or an unexpected library failure.
  kOutOfMemory = 71,   ///< The machine could not give the memory the run needed (EX_OSERR).
  kCannotCreate = 73,  ///< An output cannot be created.
  kIoError = 74,       ///< Reading or writing failed part-way.
  kBusy = 75,          ///< Another run is writing the same output (EX_TEMPFAIL: try again later).
  kDiverged = 80,      ///< The simulation blew up; the message gives frame, cause and remedy.
  kInterrupted = 130,  ///< SIGINT (128 + 2); SIGTERM gives 143.
};

class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

/// What a run that ran out of memory (std::bad_alloc) tells the user: the parse and size
/// limits keep scenes from asking for absurd amounts, so this is a big scene on a small or
/// busy machine.
inline Error out_of_memory_error() {
  return Error(ExitCode::kOutOfMemory,
               "out of memory: this machine could not give the run the memory it needed; lower output.width and "
               "output.height, the mesh detail or the number of organs, render fewer jobs at once (--jobs), or use a "
               "machine with more free memory");
}

}  // namespace systole

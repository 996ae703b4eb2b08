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
  kCannotCreate = 73,  ///< An output cannot be created.
  kIoError = 74,       ///< Reading or writing failed part-way.
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

}  // namespace systole

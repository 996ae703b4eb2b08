#pragma once
// The exit code a call throws (systole::Error), or kOk when it returns, and its message:
// for tests that check which error a bad input gets.

#include <functional>
#include <string>

#include "common/error.h"

namespace systole::test {

inline ExitCode code_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.code();
  }
  return ExitCode::kOk;
}

/// The message of the Error `f` throws, or "" when it throws none.
inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace systole::test

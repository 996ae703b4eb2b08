#pragma once
// The exit code a call throws (systole::Error), or kOk when it returns: for tests that
// check which error a bad input gets.

#include <functional>

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

}  // namespace systole::test

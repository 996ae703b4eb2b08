#pragma once
// Helpers for scene tests: run the loader and capture the error it throws.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "scene/load.h"

namespace systole::scene::testing {

/// A minimal valid organ list, to which tests add the keys they exercise.
inline constexpr const char* kMinimalOrgans = "organs:\n  - name: heart\n    mesh: {procedural: heart}\n";

struct Failure {
  ExitCode code = ExitCode::kOk;
  std::string message;  ///< Empty when loading succeeded.
};

/// Loads `yaml` (labelled scenes/test.yaml) and returns the error, or an empty message.
inline Failure load_error(const std::string& yaml, const std::vector<std::string>& overrides = {},
                          const std::string& label = "scenes/test.yaml") {
  try {
    load_from_string(yaml, label, overrides);
  } catch (const Error& e) {
    return {e.code(), e.what()};
  }
  return {};
}

/// A fresh folder under the test scratch directory.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(SYSTOLE_TEST_SCRATCH) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

}  // namespace systole::scene::testing

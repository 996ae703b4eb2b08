#pragma once
// Running the systole binary (and ffprobe) from tests, capturing output and exit code.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace systole::test {

struct RunResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together.
};

inline RunResult run(const std::string& command) {
  RunResult r;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) r.output += buf.data();
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

/// The systole binary with MESA's shader cache off and a quiet environment.
inline std::string systole() { return std::string("MESA_SHADER_CACHE_DISABLE=true ") + SYSTOLE_BINARY; }

inline std::string source(const std::string& relative) { return std::string(SYSTOLE_SOURCE_DIR) + "/" + relative; }

/// A fresh scratch folder for one test.
inline std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::path(SYSTOLE_TEST_SCRATCH) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

}  // namespace systole::test

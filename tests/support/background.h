#pragma once
// The systole binary run in the background (its stderr to a log file), for tests that
// interrupt it: they wait for a moment in its run, then send a signal.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/run.h"

extern char** environ;

namespace systole::test {

struct Background {
  pid_t pid = -1;
  std::filesystem::path log;

  /// Starts `systole <args>` with its stderr in `log`.
  Background(std::vector<std::string> args, std::filesystem::path log_file) : log(std::move(log_file)) {
    args.insert(args.begin(), SYSTOLE_BINARY);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (posix_spawn(&pid, SYSTOLE_BINARY, &actions, nullptr, argv.data(), environ) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  /// True once the run has ended (it is then reaped).
  bool ended() {
    if (int status = 0; pid > 0 && ::waitpid(pid, &status, WNOHANG) == pid) pid = -1;
    return pid <= 0;
  }
  /// Sends `sig` (if given), waits for the exit, and returns the exit code as a shell gives it.
  int finish(int sig = 0) {
    if (pid <= 0) return -1;
    if (sig != 0) ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    pid = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  std::string stderr_text() const { return read_file(log); }
  ~Background() {
    finish(SIGKILL);
    std::error_code ec;
    std::filesystem::remove(log, ec);
  }
  Background(const Background&) = delete;
  Background& operator=(const Background&) = delete;
};

}  // namespace systole::test

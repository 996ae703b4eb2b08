// What the SIGINT/SIGTERM handler relies on: the outputs written so far, listed in a
// fixed buffer, and a signal kept while an output is put in place. Each test that raises a
// signal does it in a forked child.

#include "common/interrupt.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <string>

#include "common/atomic_output.h"

namespace systole {
namespace {

namespace fs = std::filesystem;

TEST(InterruptHandler, WrittenOutputsAreListedAndALongListEndsWithAnEllipsis) {
  const pid_t pid = ::fork();
  if (pid == 0) {  // A fresh list: this process may have noted outputs already.
    const std::size_t start = outputs_written_signal_safe().size();
    note_output_written("clip.mp4");
    note_output_written("frames");
    const std::string_view two = outputs_written_signal_safe().substr(start);
    if (two != (start == 0 ? "" : ", ") + std::string("'clip.mp4', 'frames'")) ::_exit(1);
    for (int i = 0; i < 200; ++i) note_output_written("a/rather/long/path/to/an/output_" + std::to_string(i) + ".png");
    const std::string_view all = outputs_written_signal_safe();
    if (all.size() > 2048 || !all.ends_with("', ...")) ::_exit(2);
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(InterruptHandler, ACommittedFileIsNoted) {
  const fs::path dir = fs::path(SYSTOLE_TEST_SCRATCH) / "interrupt_noted";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_file_atomically(dir / "a.txt", "a");
  EXPECT_NE(outputs_written_signal_safe().find("'" + (dir / "a.txt").string() + "'"), std::string_view::npos);
}

extern "C" void exit_with_signal(int sig) {
  if (interrupt_deferred_signal_safe(sig)) return;
  ::_exit(128 + sig);
}

TEST(InterruptHandler, ASignalWaitsForTheOutermostCommit) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    struct sigaction action {};
    action.sa_handler = exit_with_signal;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGTERM, &action, nullptr);
    {
      const InterruptsWait outer;
      {
        const InterruptsWait inner;
        ::kill(::getpid(), SIGTERM);
      }
      ::_exit(3);  // Reached: the outer commit is still under way, so the signal still waits.
    }
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 3) << "the inner commit's end does not raise it";

  const pid_t second = ::fork();
  if (second == 0) {
    struct sigaction action {};
    action.sa_handler = exit_with_signal;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGTERM, &action, nullptr);
    {
      const InterruptsWait commit;
      ::kill(::getpid(), SIGTERM);
    }
    ::_exit(0);  // Not reached: the commit's end raised it.
  }
  ::waitpid(second, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << status;
}

}  // namespace
}  // namespace systole

#pragma once
// Another process holding an output's lock (common/atomic_output.h), as a first run would
// while it renders: forked, it takes the lock, says so, and waits to be killed when this
// goes out of scope (or by release()).

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "common/atomic_output.h"

namespace systole::test {

class LockHeldElsewhere {
 public:
  explicit LockHeldElsewhere(const std::filesystem::path& target) {
    int ready[2];
    if (::pipe(ready) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      const OutputLock held(target);
      const char byte = 1;
      [[maybe_unused]] auto n = ::write(ready[1], &byte, 1);
      for (;;) ::pause();
    }
    ::close(ready[1]);
    char byte = 0;
    held_ = ::read(ready[0], &byte, 1) == 1;
    ::close(ready[0]);
  }
  ~LockHeldElsewhere() { release(); }
  LockHeldElsewhere(const LockHeldElsewhere&) = delete;
  LockHeldElsewhere& operator=(const LockHeldElsewhere&) = delete;

  bool held() const { return held_; }  ///< The child took the lock.
  pid_t pid() const { return pid_; }
  /// Kills the holder (SIGKILL: the kernel releases its lock).
  void release() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

 private:
  pid_t pid_ = -1;
  bool held_ = false;
};

}  // namespace systole::test

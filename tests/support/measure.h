#pragma once
// Runs the systole binary as a child and measures what it cost, as the kernel counts it
// (wait4's rusage): CPU time, not wall time, so a busy machine does not make a bound flaky,
// and peak resident memory. Optionally under an address-space cap (RLIMIT_AS), as a small
// machine or a batch system's job limit would impose.

#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace systole::test {

struct Measured {
  int exit_code = -1;  ///< 128 + the signal when one ended it.
  double cpu_s = 0;    ///< User and system time. unit: s
  double peak_mb = 0;  ///< Peak resident memory. unit: MB
  std::string errors;  ///< What it wrote to stderr (the first 64 KiB).
};

/// Runs SYSTOLE_BINARY with `args`; `cap_bytes` > 0 caps its address space.
inline Measured measure(std::vector<std::string> args, long long cap_bytes = 0) {
  args.insert(args.begin(), SYSTOLE_BINARY);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int err[2];
  Measured m;
  if (::pipe(err) != 0) return m;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(err[1], 2);
    ::close(err[0]);
    ::close(err[1]);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    if (cap_bytes > 0) {
      const rlimit cap{static_cast<rlim_t>(cap_bytes), static_cast<rlim_t>(cap_bytes)};
      ::setrlimit(RLIMIT_AS, &cap);
    }
    ::execv(SYSTOLE_BINARY, argv.data());
    ::_exit(127);
  }
  ::close(err[1]);
  char buffer[4096];
  for (ssize_t n; (n = ::read(err[0], buffer, sizeof buffer)) > 0;) {
    if (m.errors.size() < 65536) m.errors.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(err[0]);
  int status = 0;
  rusage usage{};
  ::wait4(pid, &status, 0, &usage);
  m.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  m.cpu_s = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  m.peak_mb = usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux.
  return m;
}

}  // namespace systole::test

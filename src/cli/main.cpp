// systole: the command line. A thin layer over the modules: it parses arguments (the app is
// built by command_line.cpp), maps errors to exit codes and is the only place that exits.

#include <unistd.h>

#include <csignal>
#include <iostream>
#include <new>

#include "cli/command_line.h"
#include "common/atomic_output.h"
#include "common/error.h"

namespace {

using systole::Error;
using systole::ExitCode;

/// SIGINT / SIGTERM: remove every temporary output (earlier outputs were never touched)
/// and exit with 128 + signal, as shells expect.
extern "C" void on_interrupt(int sig) {
  systole::remove_pending_outputs_signal_safe();
  static const char msg[] = "\nsystole: interrupted; no output was written\n";
  [[maybe_unused]] auto n = ::write(STDERR_FILENO, msg, sizeof msg - 1);
  ::_exit(128 + sig);
}

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  install_signal_handlers();
  systole::cli::CommandLine command_line;
  CLI::App& app = command_line.app;

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(ExitCode::kUsage);
  }

  try {
    for (const auto& command : command_line.commands) {
      if (command.parser->parsed()) return command.run();
    }
  } catch (const Error& e) {
    std::cerr << "systole: " << e.what() << "\n";
    return static_cast<int>(e.code());
  } catch (const std::bad_alloc&) {
    const Error e = systole::out_of_memory_error();
    std::cerr << "systole: " << e.what() << "\n";
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::cerr << "systole: internal error: " << e.what() << "\n";
    return static_cast<int>(ExitCode::kInternal);
  }
  return static_cast<int>(ExitCode::kUsage);
}

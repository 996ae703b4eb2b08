// systole: the command line. A thin layer over the modules: it parses arguments (the app is
// built by command_line.cpp), maps errors to exit codes and is the only place that exits.

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <iostream>
#include <new>
#include <string_view>

#include "cli/command_line.h"
#include "common/error.h"
#include "common/interrupt.h"

namespace {

using systole::Error;
using systole::ExitCode;

void write_text(std::string_view text) { [[maybe_unused]] auto n = ::write(STDERR_FILENO, text.data(), text.size()); }

/// SIGINT / SIGTERM: remove every temporary output (earlier outputs were never touched), say
/// which outputs were finished before, and exit with 128 + signal, as shells expect. An
/// output being put in place (a rename, a PNG sequence's moves) is let finish first.
extern "C" void on_interrupt(int sig) {
  if (systole::interrupt_deferred_signal_safe(sig)) return;  // Raised again when the commit ends.
  static std::atomic<bool> handling{false};
  if (handling.exchange(true)) {
    for (;;) ::pause();  // A second signal on another thread: the first one exits.
  }
  systole::remove_pending_outputs_signal_safe();
  const std::string_view written = systole::outputs_written_signal_safe();
  if (written.empty()) {
    write_text("\nsystole: interrupted; no output was written\n");
  } else {
    write_text("\nsystole: interrupted; written before it: ");
    write_text(written);
    write_text("; what was being written was not\n");
  }
  ::_exit(128 + sig);
}

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  // The handler may return (a deferred signal): interrupted system calls resume.
  action.sa_flags = SA_RESTART;
  // One handler at a time on a thread: a second signal waits for the first to exit.
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
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

#pragma once
// The whole command line: the CLI11 app with every subcommand registered on it. `systole`
// (main.cpp) parses and runs it; `systole-manual` (cli/manual/) walks the same app to write
// the man page and the shell completions, so `--help`, `man systole` and <TAB> cannot disagree.

#include <CLI/CLI.hpp>
#include <vector>

#include "cli/command.h"

namespace systole::cli {

/// One line on what Systole is: the app's description and the man page's NAME line.
inline constexpr const char* kSummary = "self-driven soft-body organ animations, from a YAML scene to a video";

struct CommandLine {
  CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  CLI::App app;
  std::vector<Command> commands;  ///< In the order `systole --help` lists them.
};

}  // namespace systole::cli

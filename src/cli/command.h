#pragma once
// One subcommand of `systole`: registered on the CLI11 app, run when parsed. Each lives in
// its own file (render_command.cpp, ...) so commands grow without touching each other.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace systole::cli {

struct Command {
  CLI::App* parser = nullptr;
  std::function<int()> run;  ///< Returns the exit code; throws systole::Error on failure.
};

Command add_render_command(CLI::App& app);
Command add_validate_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_compare_command(CLI::App& app);

/// Adds the repeatable `-D key.path=value` option every scene-reading command takes.
void add_define_option(CLI::App& command, std::vector<std::string>& defines);

}  // namespace systole::cli

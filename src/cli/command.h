#pragma once
// One subcommand of `systole`: registered on the CLI11 app, run when parsed. Each lives in
// its own file (render_command.cpp, ...) so commands grow without touching each other.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "clip/progress.h"

namespace systole::cli {

/// What an option's value is, as its CLI11 type name: `--help` and the man page show it, and
/// the shell completions complete by it (cli/manual/completion.cpp): scene files (and the
/// folders that hold them), any file, folders, and -D's scene keys.
inline constexpr const char* kSceneValue = "SCENE";
inline constexpr const char* kFileValue = "FILE";
inline constexpr const char* kFolderValue = "DIR";
inline constexpr const char* kSceneKeyValue = "KEY=VALUE";

struct Command {
  CLI::App* parser = nullptr;
  std::function<int()> run;  ///< Returns the exit code; throws systole::Error on failure.
};

Command add_render_command(CLI::App& app);
Command add_validate_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_bake_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_tune_command(CLI::App& app);
Command add_motion_command(CLI::App& app);
Command add_export_command(CLI::App& app);

/// What `systole export` (and `render --export`) is asked to write.
struct ExportRequest {
  std::string scene;
  std::vector<std::filesystem::path> outputs;  ///< Format by extension (export/exporter.h).
  std::string encoding = "compact", max_error = "2%", from_bake;
  std::vector<std::string> defines;
  bool html = false;
};
/// Records the scene (or reads the bake) once per kind of recording the outputs need and
/// writes each output, printing its report on stdout (export_command.cpp).
void run_export(const ExportRequest& request);
/// Adds --encoding and --max-error.
void add_export_options(CLI::App& command, ExportRequest& request);

/// Adds the repeatable `-D key.path=value` option every scene-reading command takes.
void add_define_option(CLI::App& command, std::vector<std::string>& defines);

/// Adds `--progress auto|none|json` (render_command.cpp).
void add_progress_option(CLI::App& command, std::string& progress);
/// The style --progress asks for; "auto" draws a line only when stderr is a terminal.
clip::ProgressStyle progress_style(const std::string& progress);

/// Adds `--allow-large`, which lifts the resource limits (app/limits.h).
void add_allow_large_flag(CLI::App& command, bool& allow_large);

}  // namespace systole::cli

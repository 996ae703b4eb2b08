#pragma once
// What the command line says about itself, read from the CLI11 app that `systole` parses
// with (cli/command_line.h): its subcommands and every option CLI11 would list in --help,
// with names, value, checks, default and description. The man page (man_page.h) and the
// shell completions (completion.h) are written from this one walk.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace systole::cli::manual {

/// What an option's value is, for completion: a scene (YAML files and folders), any file, a
/// folder, a -D scene key, or something no path completion helps with (a number, a list).
enum class ValueKind { kNone, kScene, kFile, kFolder, kSceneKey, kOther };

/// One option or positional argument as `--help` lists it.
struct OptionReference {
  std::vector<std::string> names;  ///< "-o", "--output" (short first); empty for a positional.
  std::string positional_name;     ///< "scene" for a positional; empty for an option.
  std::string value_name;          ///< "FILE", "INT", "TEXT"; empty for a flag.
  std::string checks;              ///< CLI11's validator text: "{auto,none,json}", "INT in [1 - 64]".
  std::vector<std::string> choices;  ///< The allowed values of an IsMember check, else empty.
  std::string default_value;       ///< As --help shows it; empty when there is none.
  std::string description;
  ValueKind kind = ValueKind::kNone;
  bool required = false;
  bool repeatable = false;  ///< Takes any number of values (a vector), or may be given again.

  bool positional() const { return names.empty(); }
  bool flag() const { return value_name.empty() && !positional(); }
};

struct CommandReference {
  std::string name;  ///< "render"
  std::string description;
  std::vector<OptionReference> positionals;  ///< In the order they are given.
  std::vector<OptionReference> options;      ///< In the order --help lists them, -h,--help first.
};

struct AppReference {
  std::string name;     ///< "systole"
  std::string version;  ///< "0.1.0"
  std::string description;
  std::vector<OptionReference> options;  ///< Options before the subcommand: --help, --version.
  std::vector<CommandReference> commands;
};

/// Walks the app: every visible subcommand and every visible option of each (hidden ones,
/// those with no group, are left out, as --help leaves them out).
AppReference describe(const CLI::App& app, const std::string& version);

}  // namespace systole::cli::manual

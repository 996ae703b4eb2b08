#pragma once
// Shell completion for systole, written from the same walk of the CLI11 app as the man page
// (reference.h): the commands, every option of each, the values of options with a fixed set,
// scene files (*.yaml, *.yml) and their folders where a scene goes, files or folders where a
// path goes, and the scene keys after -D.

#include <string>
#include <vector>

#include "cli/manual/reference.h"

namespace systole::cli::manual {

/// A bash completion script (`complete -F _systole systole`), self-contained: it needs only
/// bash's compgen, not the bash-completion package's helpers.
std::string bash_completion(const AppReference& app, const std::vector<std::string>& scene_keys);

/// A zsh completion function (#compdef systole) for zsh's compsys (`_arguments`).
std::string zsh_completion(const AppReference& app, const std::vector<std::string>& scene_keys);

}  // namespace systole::cli::manual

#pragma once
// Reading a scene: YAML -> validated scene::Scene. Every problem is reported as
// Error(kDataError) whose message starts with `file:line:column: key.path:` and says what
// was expected (and, for an unknown key, which keys are allowed). A missing file is
// Error(kNoInput).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace systole::scene {

/// Loads and validates a scene file. `overrides` are "key.path=value" strings from the
/// command line (-D), applied to the YAML tree before validation so they pass the same
/// checks; list items are addressed by index (organs.0) or by their name (organs.heart).
Scene load(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

/// The same from text in memory; `file_label` names it in messages and resolves relative
/// mesh paths (its parent folder).
Scene load_from_string(std::string_view yaml, const std::string& file_label,
                       const std::vector<std::string>& overrides = {});

}  // namespace systole::scene

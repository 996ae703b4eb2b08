#pragma once
// Command-line overrides, -D key.path=value, applied to the YAML tree before validation
// so an overridden value passes exactly the checks a written one does.

#include <string>

#include "scene/tree.h"

namespace systole::scene {

/// Applies "key.path=value" to `root`. Segments are map keys, list indices (organs.0) or
/// the `name` of a list item (organs.heart). The value is parsed as YAML and its nodes
/// are labelled "-D key.path=value" for messages. A missing map key is created when the
/// schema allows it; any other missing step is Error(kDataError).
void apply_override(Node& root, const std::string& assignment);

}  // namespace systole::scene

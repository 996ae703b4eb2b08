#pragma once
// The scene schema: one declarative table of every key (type, unit, default, range, doc)
// in schema.cpp. The same table reads and validates the YAML tree, names the allowed keys
// in unknown-key messages, guides -D override paths, and generates the key reference in
// docs/scenes.md (a test keeps the two in step).

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/tree.h"

namespace systole::scene {

/// What the schema says about one key, for people (docs, messages) and for -D paths.
struct KeySpec {
  std::string name;          ///< "mass"
  std::string type;          ///< "mass", "whole number", "map", "list of regions", ...
  std::string default_text;  ///< As the docs show it; "required" for required keys.
  std::string range;         ///< "(0, 1000] kg", "`none`, `sine`", ... or "" (any).
  std::string doc;           ///< One line.
  std::vector<KeySpec> keys; ///< The keys of this map, or of each map item of this list.

  /// The child key called `key`, or nullptr.
  const KeySpec* find(const std::string& key) const;
  /// The children's names, in schema order (for "allowed keys: ...").
  std::vector<std::string> key_names() const;
};

/// The root of the schema (its `keys` are the top-level keys: seed, gravity, organs, ...).
const KeySpec& scene_schema();

/// Reads and validates a whole scene tree (overrides already applied). Relative mesh
/// files are resolved against `base_dir` and must exist (else Error(kNoInput)).
/// Fills everything except Scene::path and Scene::name.
Scene read_scene(const Node& root, const std::filesystem::path& base_dir);

/// Every key's documentation path, depth first: "seed", "organs", "organs[].name", ...
std::vector<std::string> key_paths();

/// The Markdown key reference (one table per map) that docs/scenes.md embeds.
std::string reference_markdown();

}  // namespace systole::scene

#pragma once
// Writing a scene back as YAML (systole tune's tuned scene): the scene's own file re-read
// and edited, so everything the user wrote stays, and every value is written the way the
// schema reads it (quantities with their units, full precision).

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace systole::scene {

/// New drives and stiffness for the regions of one organ.
struct OrganRegions {
  std::string organ;
  std::vector<Region> regions;
};

/// The YAML text of `scene` (re-read from scene.path, its -D overrides applied as load applies
/// them, so the text plays what was tuned) with, for each organ in `changes`,
/// the drive and stiffness of its regions (pinned ones left alone) replaced, relative file
/// paths rebased for a file written at `output`, and `note` (comment lines) after the
/// file's leading comment block. Comments inside the document are lost (yaml-cpp drops
/// them). Throws Error(kNoInput) when the scene file cannot be read again.
std::string scene_yaml_with_regions(const Scene& scene, const std::vector<OrganRegions>& changes,
                                    const std::filesystem::path& output, const std::string& note);

}  // namespace systole::scene

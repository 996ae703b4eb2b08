#pragma once
// The tuned scene as YAML: the original file's tree with each trained region's drive and
// stiffness replaced, so everything else the user wrote (camera, output, materials, the
// target itself, flow or block style) stays as it was. Relative paths are rewritten to
// stay valid from the new file's folder.

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "train/tune.h"

namespace systole::train {

/// The YAML text of `scene` (read from scene.path) with the tunings applied, for a file to
/// be written at `output`. Comments inside the document are lost (yaml-cpp drops them);
/// the file's leading comment block is kept, followed by a note of what was tuned.
std::string tuned_scene_yaml(const scene::Scene& scene, const std::vector<OrganTuning>& tunings,
                             const std::filesystem::path& output);

}  // namespace systole::train

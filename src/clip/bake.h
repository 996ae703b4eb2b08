#pragma once
// `systole bake`: one run of the clip's simulation written as a bake file (world/bake.h), so
// a long clip can be rendered by frame ranges on many machines without anyone simulating
// twice (frame k needs every step before it).
// See also: clip::RenderRequest::from_bake, scripts/render-segments, docs/bake-format.md.

#include <filesystem>
#include <string>

#include "clip/progress.h"
#include "scene/scene.h"

namespace systole::clip {

/// Simulates every frame of the clip and writes the bake atomically. Returns the wall
/// time. unit: s. Throws what build_world/advance_to_frame throw, and Error(kIoError).
double bake_clip(const scene::Scene& scene, const std::filesystem::path& file, ProgressStyle progress,
                 const std::string& label);

}  // namespace systole::clip

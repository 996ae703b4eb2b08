#pragma once
// What a scene's output depends on, as one number: the scene file's bytes and every mesh
// file it names. Bakes record it (provenance) and batch manifests compare it (skip-if-done).

#include <cstdint>

#include "scene/scene.h"

namespace systole::scene {

/// FNV-1a 64 of the scene file, then each organ's mesh file in order. Throws
/// Error(kNoInput) when one of them cannot be read.
std::uint64_t scene_content_hash(const Scene& scene);

}  // namespace systole::scene

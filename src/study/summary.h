#pragma once
// What `systole validate` prints: the model that a scene builds, before any frame.

#include <string>

#include "scene/scene.h"
#include "world/world.h"

namespace systole::study {

/// Vertices, triangles, regions with their vertex counts, constraints, mesh findings,
/// step size and frame count, one fact per line.
std::string summarize(const scene::Scene& scene, const world::World& world);

}  // namespace systole::study

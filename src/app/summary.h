#pragma once
// What `systole validate` prints: the model that a scene builds, before any frame.

#include <string>

#include "app/world.h"
#include "scene/scene.h"

namespace systole::app {

/// Vertices, triangles, regions with their vertex counts, constraints, mesh findings,
/// step size and frame count, one fact per line.
std::string summarize(const scene::Scene& scene, const World& world);

}  // namespace systole::app

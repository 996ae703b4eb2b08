#pragma once
// Named cuts of the anatomical heart (clip: {section: four_chamber | short_axis}): the plane
// comes from the heart's landmarks at rest (mesh/anatomy.h), so the cut follows the
// generator, and a view with such a cut and no camera position of its own looks square at it.

#include "scene/scene.h"
#include "world/world.h"

namespace systole::clip {

/// Sets point and normal of every named section in the scene's organs and views, and the
/// camera of each view cut by one that has no position: on the removed side, looking along
/// the normal, filling `fill` of the view (`aspect`: the views' width over height, one per
/// view). Throws Error(kDataError) naming the view or organ when none of its organs is a
/// generated anatomical heart.
void place_sections(scene::Scene& scene, const world::World& world, const std::vector<double>& aspect);

}  // namespace systole::clip

#pragma once
// Cameras that frame the organs themselves, and the check that the clip's first frame shows
// an organ at all. A wrong unit, a mesh far from the origin or a camera looking away would
// otherwise render a clip of empty background and exit 0.

#include <vector>

#include "render/camera_matrices.h"
#include "scene/scene.h"
#include "world/world.h"

namespace systole::clip {

/// The organs' rest surfaces: their bounding box's centre, and the radius about it that
/// holds them all.
/// How far from the centre of `sphere` `camera` must stand for the sphere to fill
/// camera.fill of the smaller angle of view of a view `aspect` wide over high. unit: m
double framing_distance(const scene::Camera& camera, const render::BoundingSphere& sphere, double aspect);

render::BoundingSphere bounding_sphere(const world::World& world, const std::vector<std::size_t>& organs);

/// `scene` with every automatic camera (scene::Camera::automatic: the scene's and each
/// view's) placed: looking along -z at the centre of the bounding sphere of the organs it
/// shows (at rest), from where that sphere fills camera.fill of the view's smaller angle of
/// view. So a 1 cm organ and a 1 m organ fill the frame alike. Named sections of the
/// anatomical heart are placed first (clip/sections.h).
scene::Scene with_cameras_placed(scene::Scene scene, const world::World& world);

/// Throws Error(kDataError) when no organ covers a pixel of the clip's first frame in any
/// view, naming the cause for each organ: behind the camera, outside the view (with where
/// the organ is and where the camera looks), or smaller than a pixel; and what to change.
/// Cameras must be placed (with_cameras_placed) first.
void check_organs_in_view(const scene::Scene& scene, const world::World& world);

}  // namespace systole::clip

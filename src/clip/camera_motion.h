#pragma once
// The camera at a time: a pure function of the scene's camera, so any frame can be
// rendered alone (render --frames) with the same bits.

#include "scene/scene.h"

namespace systole::clip {

/// The camera's pose at time t_s (unit: s): as written when fixed; turned about
/// orbit.axis through the target by orbit.speed x t for an orbit (a turntable, period
/// 2 pi / |speed|); on the Catmull-Rom curves through the path's positions and targets for
/// a path (passing through every key, held before the first and after the last). The
/// returned camera has no motion left (orbit disabled, path empty).
scene::Camera camera_at(const scene::Camera& camera, double t_s);

}  // namespace systole::clip

#include "clip/camera_motion.h"

#include <Eigen/Geometry>

#include "sim/interactions.h"

namespace systole::clip {

scene::Camera camera_at(const scene::Camera& camera, double t_s) {
  scene::Camera now = camera;
  now.orbit = scene::Orbit{};
  now.path.clear();
  if (camera.orbit.enabled) {
    const double angle = camera.orbit.speed_rad_per_s * t_s;
    const Eigen::AngleAxisd turn(angle, camera.orbit.axis.normalized());
    now.position_m = camera.target_m + turn * (camera.position_m - camera.target_m);
    // The up vector turns too, so an axis other than up keeps the picture upright relative to it.
    now.up = turn * camera.up;
  } else if (!camera.path.empty()) {
    // The same curve as grabs and kinematic regions (sim/interactions.h), for eye and target.
    std::vector<scene::PathKey> eye, target;
    eye.reserve(camera.path.size());
    target.reserve(camera.path.size());
    for (const scene::CameraKey& k : camera.path) {
      eye.push_back({k.time_s, k.position_m});
      target.push_back({k.time_s, k.target_m});
    }
    now.position_m = sim::path_position(eye, t_s);
    now.target_m = sim::path_position(target, t_s);
  }
  return now;
}

}  // namespace systole::clip

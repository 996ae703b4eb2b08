#include "clip/camera_motion.h"

#include <Eigen/Geometry>

#include "common/spline.h"

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
    // The same curve as grabs and kinematic regions (common/spline.h), for eye and target.
    using Key = scene::CameraKey;
    now.position_m = keyed_curve(camera.path, t_s, [](const Key& k) -> const Eigen::Vector3d& { return k.position_m; });
    now.target_m = keyed_curve(camera.path, t_s, [](const Key& k) -> const Eigen::Vector3d& { return k.target_m; });
  }
  return now;
}

}  // namespace systole::clip

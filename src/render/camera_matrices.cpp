#include "render/camera_matrices.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"

namespace systole::render {

Eigen::Matrix4d look_at(const scene::Camera& camera) {
  const Eigen::Vector3d eye = camera.position_m;
  Eigen::Vector3d forward = camera.target_m - eye;
  const double distance = forward.norm();
  if (!(distance > 0) || !std::isfinite(distance)) {
    throw Error(ExitCode::kDataError, "camera position and target must differ and be finite");
  }
  forward /= distance;
  Eigen::Vector3d side = forward.cross(camera.up);
  if (side.norm() < 1e-9 * std::max(1.0, camera.up.norm())) {
    // Up is parallel to the view direction (or zero): any perpendicular up keeps a valid frame.
    const Eigen::Vector3d axis =
        std::abs(forward.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
    side = forward.cross(axis);
  }
  side.normalize();
  const Eigen::Vector3d up = side.cross(forward);

  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = side.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = -forward.transpose();
  view(0, 3) = -side.dot(eye);
  view(1, 3) = -up.dot(eye);
  view(2, 3) = forward.dot(eye);
  return view;
}

DepthRange fit_depth_range(const scene::Camera& camera, const BoundingSphere& bounds) {
  const Eigen::Vector3d forward = (camera.target_m - camera.position_m).normalized();
  const double center_depth = forward.dot(bounds.center - camera.position_m);
  // A small margin so the sphere's own surface is never clipped by rounding.
  const double radius = bounds.radius * 1.02 + 1e-6;
  DepthRange range;
  range.far_m = center_depth + radius;
  if (!(range.far_m > 0) || !std::isfinite(range.far_m)) return DepthRange{};  // All behind.
  range.near_m = std::max(center_depth - radius, range.far_m * 1e-3);
  return range;
}

Eigen::Matrix4d perspective(double fov_rad, double aspect, const DepthRange& depth) {
  const double f = 1.0 / std::tan(fov_rad / 2);
  const double n = depth.near_m;
  const double d = depth.far_m;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (d + n) / (n - d);
  p(2, 3) = 2 * d * n / (n - d);
  p(3, 2) = -1;
  return p;
}

}  // namespace systole::render

#pragma once
// The camera's view and projection matrices (OpenGL conventions: right-handed eye space
// looking down -z, clip depth in [-1, 1]), with near and far planes fitted to what is drawn.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "scene/scene.h"

namespace systole::render {

/// A sphere enclosing everything drawn. unit: m
struct BoundingSphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0;
};

struct DepthRange {
  double near_m = 0.01;  ///< unit: m, > 0
  double far_m = 100;    ///< unit: m, > near_m
};

/// World to eye space: eye at camera.position_m looking at camera.target_m with camera.up
/// (any up not parallel to the view direction; a parallel one is replaced by a
/// perpendicular axis). Throws Error(kDataError) when position and target coincide.
Eigen::Matrix4d look_at(const scene::Camera& camera);

/// The tightest depth range holding `bounds` seen from `camera`, so the 24-bit depth
/// buffer spends its precision on the organ: near is never below far / 1000.
DepthRange fit_depth_range(const scene::Camera& camera, const BoundingSphere& bounds);

/// Symmetric perspective with vertical field of view fov_rad and aspect = width / height.
Eigen::Matrix4d perspective(double fov_rad, double aspect, const DepthRange& depth);

}  // namespace systole::render

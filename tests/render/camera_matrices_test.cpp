#include "render/camera_matrices.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace systole::render {
namespace {

scene::Camera camera(const Eigen::Vector3d& position, const Eigen::Vector3d& target,
                     const Eigen::Vector3d& up = Eigen::Vector3d::UnitY()) {
  scene::Camera c;
  c.position_m = position;
  c.target_m = target;
  c.up = up;
  return c;
}

Eigen::Vector3d transform(const Eigen::Matrix4d& m, const Eigen::Vector3d& p) {
  const Eigen::Vector4d h = m * p.homogeneous();
  return h.head<3>() / h.w();
}

TEST(LookAt, PutsTheEyeAtTheOriginLookingDownMinusZ) {
  const scene::Camera c = camera({1, 2, 3}, {1, 2, -1});
  const Eigen::Matrix4d view = look_at(c);
  EXPECT_TRUE(transform(view, c.position_m).isZero(1e-12));
  EXPECT_TRUE(transform(view, c.target_m).isApprox(Eigen::Vector3d(0, 0, -4), 1e-12));
  EXPECT_GT(transform(view, {1, 3, 3}).y(), 0.5);  // Up stays up.
  EXPECT_GT(transform(view, {2, 2, 3}).x(), 0.5);  // +x is to the right looking down -z.
}

TEST(LookAt, SurvivesAnUpParallelToTheView) {
  const Eigen::Matrix4d view = look_at(camera({0, 5, 0}, {0, 0, 0}, {0, 1, 0}));
  EXPECT_TRUE(view.allFinite());
  EXPECT_TRUE(transform(view, {0, 0, 0}).isApprox(Eigen::Vector3d(0, 0, -5), 1e-12));
}

TEST(LookAt, RejectsAnEyeOnTheTarget) {
  EXPECT_THROW(look_at(camera({1, 1, 1}, {1, 1, 1})), Error);
}

TEST(FitDepthRange, EnclosesTheSphereTightly) {
  const scene::Camera c = camera({0, 0, 10}, {0, 0, 0});
  const DepthRange range = fit_depth_range(c, {Eigen::Vector3d(0, 0, 0), 1.0});
  EXPECT_LT(range.near_m, 9.0);
  EXPECT_GT(range.near_m, 8.5);
  EXPECT_GT(range.far_m, 11.0);
  EXPECT_LT(range.far_m, 11.5);
}

TEST(FitDepthRange, CameraInsideTheSphereKeepsAPositiveNear) {
  const scene::Camera c = camera({0, 0, 0.1}, {0, 0, 0});
  const DepthRange range = fit_depth_range(c, {Eigen::Vector3d(0, 0, 0), 1.0});
  EXPECT_GT(range.near_m, 0);
  EXPECT_GE(range.near_m, range.far_m * 1e-3);
  EXPECT_GT(range.far_m, 1.1);
}

TEST(Perspective, MapsNearAndFarToTheClipRange) {
  const DepthRange range{0.5, 20};
  const Eigen::Matrix4d p = perspective(0.7, 16.0 / 9.0, range);
  EXPECT_NEAR(transform(p, {0, 0, -0.5}).z(), -1, 1e-12);
  EXPECT_NEAR(transform(p, {0, 0, -20}).z(), 1, 1e-12);
  // The top edge of the field of view lands on y = 1.
  EXPECT_NEAR(transform(p, {0, std::tan(0.35) * 3, -3}).y(), 1, 1e-12);
}

}  // namespace
}  // namespace systole::render

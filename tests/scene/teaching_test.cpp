// Scene keys of the 3D teaching visuals: opacity, clip, color_by, camera orbit and path, views.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/scene_test_util.h"

namespace systole::scene {
namespace {

using testing::kMinimalOrgans;
using testing::load_error;

Scene load_text(const std::string& yaml) { return load_from_string(yaml, "scenes/test.yaml", {}); }

TEST(TeachingVisuals, DefaultsKeepTheOpaqueFixedSingleView) {
  const Scene s = load_text(kMinimalOrgans);
  EXPECT_EQ(s.organs[0].material.opacity, 1.0);
  EXPECT_FALSE(s.organs[0].clip.enabled);
  EXPECT_EQ(s.organs[0].color_by, ColorBy::kMaterial);
  EXPECT_FALSE(s.camera.orbit.enabled);
  EXPECT_TRUE(s.camera.path.empty());
  EXPECT_TRUE(s.views.empty());
}

TEST(TeachingVisuals, ReadsEveryKey) {
  const Scene s = load_text(
      "organs:\n"
      "  - name: heart\n"
      "    mesh: {procedural: heart}\n"
      "    material: {opacity: 0.5}\n"
      "    color_by: strain\n"
      "    clip: {point: [0, 0, 1 cm], normal: [0, 0, -2], cut_color: \"#ffffff\"}\n"
      "    regions:\n"
      "      - {name: aorta, opacity: 0.25}\n"
      "  - name: other\n"
      "    mesh: {procedural: heart}\n"
      "    color_by: activation\n"
      "camera: {orbit: {speed: 30 deg/s}}\n"
      "views:\n"
      "  - {title: \"Normal heart\", organs: [heart]}\n"
      "  - camera: {path: [{time: 0 s, position: [0, 0, 1], target: [0, 0, 0]}, {time: 2 s, position: [1, 0, 0], target: [0, 0, 0]}]}\n"
      "    clip: {normal: [1, 0, 0]}\n");
  const Organ& heart = s.organs[0];
  EXPECT_EQ(heart.material.opacity, 0.5);
  EXPECT_TRUE(heart.regions[0].has_opacity);
  EXPECT_EQ(heart.regions[0].opacity, 0.25);
  EXPECT_EQ(heart.color_by, ColorBy::kStrain);
  EXPECT_EQ(heart.color_range, Eigen::Vector2d(-0.15, 0.15));  // Default by color_by.
  EXPECT_EQ(s.organs[1].color_range, Eigen::Vector2d(0, 1));
  EXPECT_TRUE(heart.clip.enabled);
  EXPECT_NEAR(heart.clip.point_m.z(), 0.01, 1e-15);
  EXPECT_EQ(heart.clip.normal, Eigen::Vector3d(0, 0, -1));  // Normalised.
  EXPECT_TRUE(s.camera.orbit.enabled);
  EXPECT_NEAR(s.camera.orbit.speed_rad_per_s, 30 * std::numbers::pi / 180, 1e-15);
  ASSERT_EQ(s.views.size(), 2u);
  EXPECT_EQ(s.views[0].title, "Normal heart");
  EXPECT_FALSE(s.views[0].has_camera);
  EXPECT_EQ(s.views[0].organs, std::vector<std::string>{"heart"});
  EXPECT_TRUE(s.views[1].has_camera);
  EXPECT_EQ(s.views[1].camera.path.size(), 2u);
  EXPECT_EQ(s.views[1].camera.position_m, Eigen::Vector3d(0, 0, 1));  // The first key.
  EXPECT_TRUE(s.views[1].clip.enabled);
}

TEST(TeachingVisuals, ErrorsNameThePlaceAndTheRule) {
  const std::string organ = "organs:\n  - name: heart\n    mesh: {procedural: heart}\n";
  auto e = load_error(organ + "    material: {opacity: 1.5}\n");
  EXPECT_NE(e.message.find("scenes/test.yaml:4:"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("organs[0].material.opacity"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("[0, 1]"), std::string::npos) << e.message;

  e = load_error(organ + "    clip: {point: [0, 0, 0], normall: [0, 0, 1]}\n");
  EXPECT_NE(e.message.find("unknown key 'normall'"), std::string::npos) << e.message;

  e = load_error(organ + "    color_by: pressure\n");
  EXPECT_NE(e.message.find("material, region, strain, activation"), std::string::npos) << e.message;

  e = load_error(organ + "    color_range: [0.1, -0.1]\n");
  EXPECT_NE(e.message.find("lo < hi"), std::string::npos) << e.message;

  e = load_error(organ + "camera: {orbit: {speed: 20}}\n");
  EXPECT_NE(e.message.find("camera.orbit.speed"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("deg/s"), std::string::npos) << e.message;

  e = load_error(organ + "camera: {orbit: {speed: 20 deg/s}, path: [{time: 0 s, position: [0, 0, 1], target: [0, 0, 0]}]}\n");
  EXPECT_NE(e.message.find("not both"), std::string::npos) << e.message;

  e = load_error(organ + "camera: {path: [{time: 1 s, position: [0, 0, 1], target: [0, 0, 0]}, {time: 1 s, position: [0, 0, 2], target: [0, 0, 0]}]}\n");
  EXPECT_NE(e.message.find("times must increase"), std::string::npos) << e.message;

  e = load_error(organ + "camera: {path: [{time: 1 s, position: [0, 0, 0], target: [0, 0, 0]}]}\n");
  EXPECT_NE(e.message.find("camera.path"), std::string::npos) << e.message;

  e = load_error(organ + "views:\n  - {organs: [hart]}\n");
  EXPECT_NE(e.message.find("views[0].organs[0]"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("no organ is named 'hart'"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find(":5:"), std::string::npos) << e.message;
}

TEST(TeachingVisuals, ViewRectanglesTileTheFrame) {
  const auto two = view_rectangles(1280, 720, 2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].x, 0);
  EXPECT_EQ(two[0].width, 640);
  EXPECT_EQ(two[1].x, 640);
  EXPECT_EQ(two[1].height, 720);
  // One row up to three views, then a grid; no two views share a pixel, and a full grid
  // covers the frame exactly.
  for (const int n : {1, 2, 3, 4, 5, 7, 9, 16}) {
    const auto rects = view_rectangles(322, 242, n);
    ASSERT_EQ(rects.size(), static_cast<std::size_t>(n));
    long area = 0;
    for (std::size_t i = 0; i < rects.size(); ++i) {
      const PixelRect& r = rects[i];
      EXPECT_GE(r.x, 0);
      EXPECT_GE(r.y, 0);
      EXPECT_LE(r.x + r.width, 322);
      EXPECT_LE(r.y + r.height, 242);
      area += static_cast<long>(r.width) * r.height;
      for (std::size_t j = 0; j < i; ++j) {
        const PixelRect& q = rects[j];
        const bool apart = r.x >= q.x + q.width || q.x >= r.x + r.width || r.y >= q.y + q.height || q.y >= r.y + r.height;
        EXPECT_TRUE(apart) << n << " views: " << i << " overlaps " << j;
      }
    }
    if (n == 1 || n == 2 || n == 3 || n == 4 || n == 9 || n == 16) EXPECT_EQ(area, 322L * 242) << n;
  }
  EXPECT_EQ(view_rectangles(1280, 720, 4)[3].y, 360);
}

}  // namespace
}  // namespace systole::scene

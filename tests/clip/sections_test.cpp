// ctest-labels: slow-under-sanitizers
// Named cuts of the anatomical heart: the four-chamber plane holds the long axis and both
// ventricles, the short-axis plane crosses the long axis mid-ventricle, a view cut by one
// with no camera of its own looks square at it from the side cut away; a section of a heart
// without anatomy, or a clip with both or neither of section and normal, is an error.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "clip/camera_framing.h"
#include "common/error.h"
#include "scene/load.h"
#include "world/world.h"

namespace systole::clip {
namespace {

std::string heart_scene(const std::string& procedural, const std::string& clip) {
  return "organs:\n"
         "  - name: heart\n"
         "    mesh: {procedural: " + procedural + ", detail: 1}\n"
         "views:\n"
         "  - title: outside\n"
         "  - title: cut\n"
         "    clip: " + clip + "\n"
         "output: {file: out/x.mp4, width: 640, height: 360, duration: 0.1 s}\n";
}

Eigen::Vector3d centroid_of(const mesh::OrganMesh& m, const std::string& cavity) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (const auto& c : m.anatomy.cavities) {
    if (c.name != cavity) continue;
    for (const auto& t : c.lining) sum += m.surface.positions[t[0]] + m.surface.positions[t[1]] + m.surface.positions[t[2]], n += 3;
  }
  return sum / n;
}

TEST(Sections, FourChamberHoldsTheLongAxisAndBothVentricles) {
  const scene::Scene given = scene::load_from_string(heart_scene("anatomical_heart", "{section: four_chamber}"), "t.yaml");
  const world::World world = world::build_world(given);
  const scene::Scene placed = with_cameras_placed(given, world);
  const scene::ClipPlane& clip = placed.views[1].clip;
  const mesh::OrganMesh& m = world.organs[0].geometry.mesh;
  const auto distance = [&](const Eigen::Vector3d& p) { return std::abs((p - clip.point_m).dot(clip.normal)); };
  EXPECT_LT(distance(m.surface.positions[m.anatomy.left_ventricle.apex]), 1e-9);
  EXPECT_LT(distance(centroid_of(m, "left_ventricle")), 1e-3);
  EXPECT_LT(distance(centroid_of(m, "right_ventricle")), 1e-3);
  EXPECT_LT(clip.normal.z(), 0);  // The front half is cut away.
  // The camera looks along the normal from the side cut away, the long axis upright.
  const scene::Camera& camera = placed.views[1].camera;
  EXPECT_TRUE(placed.views[1].has_camera);
  EXPECT_GT((camera.target_m - camera.position_m).normalized().dot(clip.normal), 1 - 1e-9);
  EXPECT_LT(std::abs(camera.up.dot(clip.normal)), 1e-9);
  EXPECT_FALSE(placed.views[0].has_camera);  // The other view keeps the scene's camera.
}

TEST(Sections, ShortAxisCrossesTheLongAxisMidVentricle) {
  const scene::Scene given = scene::load_from_string(heart_scene("anatomical_heart", "{section: short_axis}"), "t.yaml");
  const world::World world = world::build_world(given);
  const scene::ClipPlane& clip = with_cameras_placed(given, world).views[1].clip;
  const mesh::OrganMesh& m = world.organs[0].geometry.mesh;
  const Eigen::Vector3d apex = m.surface.positions[m.anatomy.left_ventricle.apex];
  const Eigen::Vector3d lv = centroid_of(m, "left_ventricle");
  const Eigen::Vector3d axis = (apex - lv).normalized();
  EXPECT_GT(std::abs(clip.normal.dot(axis)), 0.95);
  Eigen::Vector3d annulus = Eigen::Vector3d::Zero();
  for (int v : m.anatomy.left_ventricle.annulus) annulus += m.surface.positions[v] / m.anatomy.left_ventricle.annulus.size();
  EXPECT_LT((apex - clip.point_m).dot(clip.normal), -0.02);    // The apex is cut away,
  EXPECT_GT((annulus - clip.point_m).dot(clip.normal), 0.02);  // the base kept.
}

TEST(Sections, NeedAnAnatomicalHeart) {
  const scene::Scene given = scene::load_from_string(heart_scene("heart", "{section: four_chamber}"), "t.yaml");
  const world::World world = world::build_world(given);
  try {
    with_cameras_placed(given, world);
    FAIL() << "cut a heart without anatomy";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("views[1].clip: section four_chamber cuts a generated anatomical heart"),
              std::string::npos)
        << e.what();
  }
}

TEST(Sections, ClipTakesASectionOrAPlaneNotBoth) {
  for (const char* clip : {"{section: short_axis, normal: [0, 0, 1]}", "{point: [0, 0, 0]}", "{cut_color: \"#ffffff\"}"}) {
    try {
      scene::load_from_string(heart_scene("anatomical_heart", clip), "t.yaml");
      FAIL() << clip;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("expected `section`, or `normal` (with `point`)"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace systole::clip

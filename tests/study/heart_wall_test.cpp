// ctest-labels: slow-under-sanitizers
// A generated anatomy keeps its linings inside its walls (issue 39): on every shipped scene of
// the anatomical heart no lining vertex leaves the epicardium and an outside view shows no
// lining, over the frames CI can afford (scripts/check-heart-wall runs the whole clips);
// and both checks see a lining that does cross or show.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "mesh/anatomy.h"
#include "mesh/procedural.h"
#include "scene/load.h"
#include "study/lining_view.h"
#include "study/lining_watch.h"
#include "study/motion_check.h"
#include "support/run.h"
#include "world/frame_source.h"

namespace systole::study {
namespace {

/// The shipped scenes whose organs are the generated anatomical heart.
std::vector<std::string> heart_scenes() {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(test::source("scenes"))) {
    if (entry.path().extension() != ".yaml") continue;
    if (test::read_file(entry.path()).find("procedural: anatomical_heart") != std::string::npos) out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A beat and a little of organ time (0.9 s: 27 frames at 30 fps; before issue 39's fix
// lining vertices lay outside from frame 0 and lining pixels showed from frame 2), the
// outside view at the scene's own size.
TEST(HeartWall, EveryShippedHeartKeepsItsLiningsInsideItsWalls) {
  const std::vector<std::string> scenes = heart_scenes();
  ASSERT_GE(scenes.size(), 13u);
  for (const std::string& path : scenes) {
    const scene::Scene scene = scene::load(path);
    MotionOptions options;
    options.duration_s = 0.9;
    options.outside_view = true;
    const MotionReport report = check_motion(scene, options);
    ASSERT_FALSE(report.linings.empty()) << path;
    for (const OrganLinings& l : report.linings) {
      EXPECT_GT(l.frames, 20) << path;
      EXPECT_EQ(l.worst_outside, 0) << path << ": " << l.organ << "'s " << l.worst_cavity << " lining crosses its wall at frame "
                                    << l.worst_frame;
    }
    ASSERT_TRUE(report.view.drawn) << path;
    EXPECT_EQ(report.view.worst_pixels, 0) << path << ": the outside view shows a lining at frame " << report.view.worst_frame;
  }
}

TEST(HeartWall, TheWatchSeesALiningPushedThroughItsWall) {
  const mesh::OrganMesh heart = mesh::generate_organ("anatomical_heart", 1);
  LiningWatch watch(heart);
  ASSERT_FALSE(watch.empty());
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(heart.surface.positions.size()));
  for (std::size_t v = 0; v < heart.surface.positions.size(); ++v) x.col(static_cast<Eigen::Index>(v)) = heart.surface.positions[v];
  EXPECT_EQ(watch.check(x, 0), 0);
  // One lining vertex of the right ventricle pushed 2 cm out from the heart's centre.
  const mesh::Cavity* rv = heart.anatomy.cavity("right_ventricle");
  ASSERT_NE(rv, nullptr);
  const int v = rv->lining[rv->lining.size() / 2][0];
  x.col(v) += 0.02 * x.col(v).normalized();
  EXPECT_EQ(watch.check(x, 1), 1);
  EXPECT_EQ(watch.worst_frame(), 1);
  EXPECT_EQ(watch.worst_vertex(), v);
  EXPECT_EQ(watch.worst_cavity(), "right_ventricle");
  // An organ without an anatomy has nothing to watch.
  EXPECT_TRUE(LiningWatch(mesh::generate_organ("heart", 1)).empty());
}

TEST(HeartWall, TheOutsideViewSeesTheLiningsFromInside) {
  scene::Scene scene = scene::load(test::source("scenes/heart.yaml"));
  scene.output.width = 320;
  scene.output.height = 180;
  world::FrameSource source(scene);
  std::vector<Eigen::Matrix3Xd> positions(1);
  source.advance_to(0);
  source.positions(0, positions[0]);
  // From the scene's camera: the outside only.
  LiningView outside(scene, source.world());
  EXPECT_EQ(outside.lining_pixels(positions, 0), 0);
  // From the middle of the right ventricle's cavity: its lining all round.
  const mesh::Cavity& rv = *source.world().organs[0].geometry.mesh.anatomy.cavity("right_ventricle");
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3i& t : rv.lining) centre += positions[0].col(t[0]) / static_cast<double>(rv.lining.size());
  scene.camera.position_m = centre;
  scene.camera.target_m = centre + Eigen::Vector3d(0, 0, -0.01);
  LiningView inside(scene, source.world());
  EXPECT_GT(inside.lining_pixels(positions, 0), 320 * 180 / 4);
  EXPECT_EQ(inside.worst_frame(), 0);
}

}  // namespace
}  // namespace systole::study

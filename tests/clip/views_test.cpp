// The 3D teaching visuals end to end: cameras that move as pure functions of time, views
// built from the scene, strain and activation following the drive, and the same bits at
// one and two rasterizer threads with transparency, cuts and views.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "clip/camera_motion.h"
#include "clip/render_clip.h"
#include "encode/png.h"
#include "mesh/strain.h"
#include "render/color_map.h"
#include "scene/load.h"
#include "sim/drive.h"
#include "support/run.h"
#include "world/world.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

scene::Camera orbiting(double speed_deg_per_s, const Eigen::Vector3d& axis) {
  scene::Camera c;
  c.position_m = Eigen::Vector3d(0.05, 0.1, 0.4);
  c.target_m = Eigen::Vector3d(0.01, 0.02, 0);
  c.orbit.enabled = true;
  c.orbit.speed_rad_per_s = speed_deg_per_s * std::numbers::pi / 180;
  c.orbit.axis = axis.normalized();
  return c;
}

TEST(CameraMotion, FixedCameraDoesNotMove) {
  scene::Camera c;
  c.position_m = Eigen::Vector3d(1, 2, 3);
  EXPECT_EQ(clip::camera_at(c, 7.5).position_m, c.position_m);
  EXPECT_EQ(clip::camera_at(c, 7.5).target_m, c.target_m);
}

TEST(CameraMotion, OrbitKeepsDistanceAndRepeatsEveryPeriod) {
  const scene::Camera c = orbiting(20, Eigen::Vector3d(0, 1, 0.2));
  const double period_s = 360.0 / 20;
  const double radius = (c.position_m - c.target_m).norm();
  for (const double t : {0.0, 0.7, 4.5, 9.0, 13.3}) {
    const scene::Camera now = clip::camera_at(c, t), later = clip::camera_at(c, t + period_s);
    EXPECT_NEAR((now.position_m - c.target_m).norm(), radius, 1e-12) << t;
    EXPECT_EQ(now.target_m, c.target_m);
    EXPECT_LT((now.position_m - later.position_m).norm(), 1e-12) << t;
    EXPECT_LT((now.up - later.up).norm(), 1e-12) << t;
    EXPECT_FALSE(now.orbit.enabled) << "the result is a fixed camera";
  }
  // Half a period away is the opposite side (for an axis through the target along up).
  const scene::Camera flat = orbiting(20, Eigen::Vector3d::UnitY());
  const Eigen::Vector3d half = clip::camera_at(flat, period_s / 2).position_m - flat.target_m;
  const Eigen::Vector3d start = flat.position_m - flat.target_m;
  EXPECT_NEAR(half.x(), -start.x(), 1e-12);
  EXPECT_NEAR(half.z(), -start.z(), 1e-12);
  EXPECT_NEAR(half.y(), start.y(), 1e-12);
}

TEST(CameraMotion, OrbitImageRepeatsAfterAPeriod) {
  // An off-centre organ, so a turn shows: the frames at t and t + period agree within the
  // golden-image tolerance (the pose differs by rounding only).
  const scene::Scene s = scene::load_from_string(
      "organs:\n  - {name: heart, mesh: {procedural: heart, detail: 1}, transform: {translate: [2 cm, 0, 0]}}\n"
      "camera: {position: [0, 0.01, 0.34], orbit: {speed: 45 deg/s}}\n"
      "output: {width: 96, height: 64}\n",
      "scenes/orbit.yaml", {});
  const world::World world = world::build_world(s);
  render::Renderer renderer(96, 64, 0);
  const auto& surface = world.organs[0].geometry.mesh.surface;
  std::vector<float> x, n(3 * surface.positions.size());
  for (const auto& p : surface.positions) x.insert(x.end(), {float(p.x()), float(p.y()), float(p.z())});
  for (std::size_t v = 0; v < surface.positions.size(); ++v) n[3 * v + 2] = 1;
  const int id = renderer.add_surface(surface.triangles, std::vector<scene::Color>(surface.positions.size(), {0.7, 0.2, 0.2}), {});
  renderer.update_surface(id, x.data(), n.data());
  const auto image_at = [&](double t) {
    renderer.draw(clip::camera_at(s.camera, t), s.lights, s.output.background);
    Image image;
    renderer.read_frame(image);
    return image;
  };
  const Image a = image_at(1.0), b = image_at(1.0 + 8.0), quarter = image_at(3.0);
  int over = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) over += std::abs(int(a.rgb[i]) - int(b.rgb[i])) > 2;
  EXPECT_LE(over, 3) << "t and t + period";
  EXPECT_NE(a.rgb, quarter.rgb) << "a quarter turn later the picture differs";
}

TEST(CameraMotion, PathPassesThroughItsKeysAndIsHeldOutside) {
  scene::Camera c;
  c.path = {{1.0, {0, 0, 1}, {0, 0, 0}}, {2.0, {1, 0, 0}, {0, 0.1, 0}}, {4.0, {0, 0, -1}, {0, 0, 0}},
            {5.0, {-1, 0.5, 0}, {0.2, 0, 0}}};
  for (const scene::CameraKey& k : c.path) {
    const scene::Camera at = clip::camera_at(c, k.time_s);
    EXPECT_LT((at.position_m - k.position_m).norm(), 1e-12) << k.time_s;
    EXPECT_LT((at.target_m - k.target_m).norm(), 1e-12) << k.time_s;
  }
  EXPECT_EQ(clip::camera_at(c, 0.0).position_m, c.path.front().position_m);
  EXPECT_EQ(clip::camera_at(c, 9.0).position_m, c.path.back().position_m);
  // Smooth: small steps move the camera a little, and the same time gives the same bits.
  for (double t = 1.0; t < 5.0; t += 0.01) {
    EXPECT_LT((clip::camera_at(c, t + 0.001).position_m - clip::camera_at(c, t).position_m).norm(), 0.01) << t;
  }
  EXPECT_EQ(clip::camera_at(c, 2.345).position_m, clip::camera_at(c, 2.345).position_m);
}

TEST(Views, FrameViewsFollowTheScene) {
  const scene::Scene s = scene::load_from_string(
      "organs:\n  - {name: a, mesh: {procedural: heart, detail: 1}}\n  - {name: b, mesh: {procedural: heart, detail: 1}}\n"
      "camera: {position: [0, 0, 0.4]}\n"
      "views:\n  - {organs: [b], title: \"B alone\"}\n"
      "  - {organs: [a, b], camera: {position: [0.4, 0, 0]}, clip: {normal: [0, 0, -1]}}\n"
      "output: {width: 320, height: 240}\n",
      "scenes/views.yaml", {});
  auto views = clip::frame_views(s, {10, 11});
  ASSERT_EQ(views.size(), 2u);
  EXPECT_EQ(views[0].surfaces, std::vector<int>{11});
  EXPECT_EQ(views[1].surfaces, (std::vector<int>{10, 11}));
  EXPECT_EQ(views[0].rect.width, 160);
  EXPECT_EQ(views[1].rect.x, 160);
  EXPECT_FALSE(views[0].clip.enabled);
  EXPECT_TRUE(views[1].clip.enabled);
  clip::set_view_cameras(s, 0.0, views);
  EXPECT_EQ(views[0].camera.position_m, s.camera.position_m);
  EXPECT_EQ(views[1].camera.position_m, Eigen::Vector3d(0.4, 0, 0));
  // Without views: one whole-frame view of everything.
  scene::Scene plain = s;
  plain.views.clear();
  views = clip::frame_views(plain, {10, 11});
  ASSERT_EQ(views.size(), 1u);
  EXPECT_TRUE(views[0].surfaces.empty());
  EXPECT_EQ(views[0].rect.width, 0);
}

TEST(ColorMaps, ContractingRegionTurnsTowardsTheShortenedColour) {
  // A heart whose left ventricle alone beats strongly: at the peak of its contraction its
  // vertices' strain is negative and their colour bluer than at rest; its activation is high.
  const scene::Scene s = scene::load_from_string(
      "organs:\n  - name: heart\n    mesh: {procedural: heart, detail: 2}\n    color_by: strain\n"
      "    body: {mass: 300 g, stiffness: 400 N/m, damping: 10 ms, volume_stiffness: 3 kPa, drag: 2 1/s}\n"
      "    regions:\n      - name: left_ventricle\n"
      "        drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.2, systolic_fraction: 0.36}\n"
      "      - {name: aorta, pinned: true}\n"
      "solver: {dt: 1/240 s, substeps: 2}\noutput: {fps: 30}\n",
      "scenes/strain.yaml", {});
  world::World world = world::build_world(s);
  const auto& body = world.organs[0];
  const mesh::VertexStrain strain(body.geometry.mesh.surface.positions, body.geometry.mesh.surface.triangles);
  const render::ColorMap map = render::organ_color_map(s.organs[0]).map;
  const auto ventricle_mean = [&] {
    Eigen::Matrix3Xd x;
    world::render_positions(world.organs[0], x);
    std::vector<double> values;
    strain.compute(x, values);
    double sum = 0;
    int count = 0;
    for (std::size_t v = 0; v < values.size(); ++v) {
      if (body.geometry.vertex_region[v] == 0) sum += values[v], ++count;
    }
    return sum / count;
  };
  const double rest = ventricle_mean();
  EXPECT_NEAR(rest, 0.0, 1e-12);
  world::advance_to_frame(world, 5);  // t = 1/6 s: near the peak (0.36 x 0.83 s / 2 = 0.15 s).
  const double peak = ventricle_mean();
  EXPECT_LT(peak, -0.02) << "the driven wall is shortened";
  const scene::Color at_rest = map.at(rest), contracted = map.at(peak);
  EXPECT_GT(contracted.z() - contracted.x(), at_rest.z() - at_rest.x() + 0.1) << "towards blue";
  EXPECT_GT(sim::activation(body.model.regions[0].drive, 5 / 30.0, body.model.ramp_s), 0.8);
}

}  // namespace
}  // namespace systole::test

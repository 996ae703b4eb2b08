// Valid scenes: every key lands in scene::Scene converted to SI units.

#include <gtest/gtest.h>

#include <numbers>

#include "scene/load.h"
#include "scene_test_util.h"

namespace systole::scene {
namespace {

using testing::kMinimalOrgans;

constexpr double kDeg = std::numbers::pi / 180;

const char* const kFullScene = R"(seed: 7
gravity: [0, -9.81, 0]
organs:
  - name: heart
    mesh:
      procedural: heart
      detail: 4
      center: false
    transform: {translate: [0, 1 cm, 0], rotate: [0, 30 deg, 0.5 rad], scale: 1.5}
    material: {color: "#ff8000", specular: 0.5, shininess: 32}
    body: {mass: 300 g, stiffness: 400 N/m, damping: 10 ms, volume_stiffness: 20 kPa, drag: 2 1/s}
    regions:
      - name: left_ventricle
        drive:
          waveform: cardiac
          rate: 72 bpm
          rate_end: 120 bpm
          amplitude: 0.12
          phase: 90 deg
          delay: 160 ms
          systolic_fraction: 0.3
          irregularity: 0.1
        stiffness: 2
        damping: 0.5
      - name: apex
        select: {sphere: {center: [0, -3 cm, 0], radius: 2 cm}}
        pinned: true
        color: [0.2, 0.4, 0.6]
      - name: rhythm
        select: [all, {box: {min: [-1, -1, -1], max: [1, 1, 1]}}, {half_space: {point: [0, 0, 0], normal: [0, 0, 2]}}, {part: septum}]
        drive:
          waveform: fourier
          rate: 1.2 Hz
          harmonics: [{amplitude: 0.3, phase: 30 deg}, {amplitude: 0.1}]
      - name: lungs
        drive: {waveform: breathing, rate: 15 /min, inhale_fraction: 0.45}
      - name: table
        drive: {waveform: samples, rate: 1 Hz, samples: [0, 0.3, 1, 0.4]}
solver: {method: implicit, dt: 1/240 s, substeps: 8}
camera: {position: [0, 0, 40 cm], target: [0, 0, 0], up: [0, 1, 0], fov: 40 deg}
lights: [{direction: [-0.4, -0.6, -1], color: [1, 1, 1], intensity: 0.8}]
output: {file: out/heart.mp4, width: 1920, height: 1080, fps: 60, duration: 2500 ms, crf: 18, preset: medium, antialias: 2, background: "#000000"}
)";

TEST(SceneLoad, FullSceneArrivesInSiUnits) {
  const Scene s = load_from_string(kFullScene, "scenes/full.yaml");
  EXPECT_EQ(s.path, "scenes/full.yaml");
  EXPECT_EQ(s.name, "full");
  EXPECT_EQ(s.seed, 7u);
  EXPECT_DOUBLE_EQ(s.gravity.y(), -9.81);
  ASSERT_EQ(s.organs.size(), 1u);
  const Organ& o = s.organs[0];
  EXPECT_EQ(o.name, "heart");
  EXPECT_EQ(o.origin.line, 4);
  EXPECT_EQ(o.mesh.procedural, "heart");
  EXPECT_EQ(o.mesh.detail, 4);
  EXPECT_FALSE(o.mesh.center);
  EXPECT_DOUBLE_EQ(o.transform.translate_m.y(), 0.01);
  EXPECT_DOUBLE_EQ(o.transform.rotate_rad.y(), 30 * kDeg);
  EXPECT_DOUBLE_EQ(o.transform.rotate_rad.z(), 0.5);
  EXPECT_DOUBLE_EQ(o.transform.scale, 1.5);
  EXPECT_DOUBLE_EQ(o.material.color.x(), 1.0);
  EXPECT_NEAR(o.material.color.y(), 128 / 255.0, 1e-12);
  EXPECT_DOUBLE_EQ(o.material.shininess, 32);
  EXPECT_DOUBLE_EQ(o.body.mass_kg, 0.3);
  EXPECT_DOUBLE_EQ(o.body.stiffness_N_per_m, 400);
  EXPECT_DOUBLE_EQ(o.body.damping_s, 0.01);
  EXPECT_DOUBLE_EQ(o.body.volume_stiffness_Pa, 20000);
  EXPECT_DOUBLE_EQ(o.body.drag_per_s, 2);

  ASSERT_EQ(o.regions.size(), 5u);
  const Region& lv = o.regions[0];
  EXPECT_EQ(lv.name, "left_ventricle");
  EXPECT_TRUE(lv.select.empty());  // = the part named left_ventricle
  EXPECT_EQ(lv.drive.waveform, Waveform::kCardiac);
  EXPECT_DOUBLE_EQ(lv.drive.rate_hz, 1.2);
  EXPECT_DOUBLE_EQ(lv.drive.rate_end_hz, 2.0);
  EXPECT_DOUBLE_EQ(lv.drive.amplitude, 0.12);
  EXPECT_DOUBLE_EQ(lv.drive.phase_rad, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(lv.drive.delay_s, 0.16);
  EXPECT_DOUBLE_EQ(lv.drive.systolic_fraction, 0.3);
  EXPECT_DOUBLE_EQ(lv.drive.irregularity, 0.1);
  EXPECT_DOUBLE_EQ(lv.stiffness_scale, 2);
  EXPECT_DOUBLE_EQ(lv.damping_scale, 0.5);
  EXPECT_FALSE(lv.has_color);

  const Region& apex = o.regions[1];
  ASSERT_EQ(apex.select.size(), 1u);
  EXPECT_EQ(apex.select[0].kind, SelectorKind::kSphere);
  EXPECT_DOUBLE_EQ(apex.select[0].center.y(), -0.03);
  EXPECT_DOUBLE_EQ(apex.select[0].radius_m, 0.02);
  EXPECT_TRUE(apex.pinned);
  EXPECT_TRUE(apex.has_color);
  EXPECT_DOUBLE_EQ(apex.color.z(), 0.6);

  const Region& rhythm = o.regions[2];
  ASSERT_EQ(rhythm.select.size(), 4u);
  EXPECT_EQ(rhythm.select[0].kind, SelectorKind::kAll);
  EXPECT_EQ(rhythm.select[1].kind, SelectorKind::kBox);
  EXPECT_DOUBLE_EQ(rhythm.select[1].min.x(), -1);
  EXPECT_EQ(rhythm.select[2].kind, SelectorKind::kHalfSpace);
  EXPECT_DOUBLE_EQ(rhythm.select[2].normal.z(), 1.0);  // normalised
  EXPECT_EQ(rhythm.select[3].kind, SelectorKind::kPart);
  EXPECT_EQ(rhythm.select[3].part, "septum");
  EXPECT_EQ(rhythm.drive.waveform, Waveform::kFourier);
  ASSERT_EQ(rhythm.drive.harmonics.size(), 2u);
  EXPECT_DOUBLE_EQ(rhythm.drive.harmonics[0].amplitude, 0.3);
  EXPECT_DOUBLE_EQ(rhythm.drive.harmonics[0].phase_rad, 30 * kDeg);
  EXPECT_DOUBLE_EQ(rhythm.drive.harmonics[1].phase_rad, 0);

  EXPECT_DOUBLE_EQ(o.regions[3].drive.rate_hz, 0.25);  // 15 breaths per minute
  EXPECT_DOUBLE_EQ(o.regions[3].drive.inhale_fraction, 0.45);
  EXPECT_EQ(o.regions[4].drive.samples, (std::vector<double>{0, 0.3, 1, 0.4}));

  EXPECT_EQ(s.solver.method, SolverMethod::kImplicit);
  EXPECT_DOUBLE_EQ(s.solver.dt_s, 1.0 / 240);
  EXPECT_FALSE(s.solver.auto_dt);
  EXPECT_EQ(s.solver.substeps, 8);
  EXPECT_DOUBLE_EQ(s.camera.position_m.z(), 0.4);
  EXPECT_DOUBLE_EQ(s.camera.fov_rad, 40 * kDeg);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_DOUBLE_EQ(s.lights[0].intensity, 0.8);
  EXPECT_EQ(s.output.file, "out/heart.mp4");
  EXPECT_EQ(s.output.width, 1920);
  EXPECT_EQ(s.output.height, 1080);
  EXPECT_DOUBLE_EQ(s.output.fps, 60);
  EXPECT_DOUBLE_EQ(s.output.duration_s, 2.5);
  EXPECT_EQ(s.output.frame_count(), 150);
  EXPECT_EQ(s.output.crf, 18);
  EXPECT_EQ(s.output.preset, "medium");
  EXPECT_EQ(s.output.antialias, Antialias::kMsaa2);
  EXPECT_EQ(s.output.background, Color(0, 0, 0));
}

TEST(SceneLoad, MinimalSceneTakesTheDefaultsOfSceneH) {
  const Scene s = load_from_string(kMinimalOrgans, "minimal.yaml");
  const Scene defaults;
  EXPECT_EQ(s.seed, defaults.seed);
  EXPECT_EQ(s.gravity, defaults.gravity);
  EXPECT_DOUBLE_EQ(s.organs[0].body.mass_kg, Body{}.mass_kg);
  EXPECT_DOUBLE_EQ(s.solver.dt_s, Solver{}.dt_s);
  EXPECT_DOUBLE_EQ(s.camera.fov_rad, Camera{}.fov_rad);
  EXPECT_EQ(s.output.width, Output{}.width);
  EXPECT_TRUE(s.organs[0].regions.empty());
  // No lights written: a key and a fill, the key brighter.
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_GT(s.lights[0].intensity, s.lights[1].intensity);
}

TEST(SceneLoad, UnitsConvertToSi) {
  struct Case {
    const char* override_assignment;
    double (*get)(const Scene&);
    double expected;
  };
  const Case cases[] = {
      {"organs.0.body.mass=250 g", [](const Scene& s) { return s.organs[0].body.mass_kg; }, 0.25},
      {"organs.0.body.mass=2", [](const Scene& s) { return s.organs[0].body.mass_kg; }, 2.0},
      {"organs.0.body.volume_stiffness=3 kPa", [](const Scene& s) { return s.organs[0].body.volume_stiffness_Pa; }, 3000},
      {"organs.0.body.damping=0", [](const Scene& s) { return s.organs[0].body.damping_s; }, 0.0},
      {"organs.0.transform.translate=[1 mm, 2 cm, 3 m]", [](const Scene& s) { return s.organs[0].transform.translate_m.sum(); }, 3.021},
      {"camera.fov=1 rad", [](const Scene& s) { return s.camera.fov_rad; }, 1.0},
      {"output.duration=90 s", [](const Scene& s) { return s.output.duration_s; }, 90},
      {"solver.dt=0.5 ms", [](const Scene& s) { return s.solver.dt_s; }, 0.0005},
      {"solver.dt=1/1000 s", [](const Scene& s) { return s.solver.dt_s; }, 0.001},
      {"gravity=[0, -9.81 m/s^2, +1e-1]", [](const Scene& s) { return s.gravity.z(); }, 0.1},
  };
  for (const Case& c : cases) {
    const Scene s = load_from_string(kMinimalOrgans, "t.yaml", {c.override_assignment});
    EXPECT_NEAR(c.get(s), c.expected, 1e-12) << c.override_assignment;
  }
}

TEST(SceneLoad, AutoStepSize) {
  const Scene s = load_from_string(std::string(kMinimalOrgans) + "solver: {dt: auto}\n", "t.yaml");
  EXPECT_TRUE(s.solver.auto_dt);
}

TEST(SceneLoad, MeshFileResolvesAgainstTheSceneFolder) {
  const auto dir = testing::scratch_dir("mesh_file");
  std::filesystem::create_directories(dir / "assets");
  testing::write_file(dir / "assets" / "organ.obj", "v 0 0 0\n");
  testing::write_file(dir / "scene.yaml",
                      "organs:\n  - name: kidney\n    mesh: {file: assets/organ.obj, units: mm}\n");
  const Scene s = load(dir / "scene.yaml");
  EXPECT_EQ(s.name, "scene");
  EXPECT_EQ(s.path, (dir / "scene.yaml").string());
  EXPECT_EQ(s.organs[0].mesh.file, (dir / "assets" / "organ.obj").string());
  EXPECT_DOUBLE_EQ(s.organs[0].mesh.unit_m, 0.001);
}

}  // namespace
}  // namespace systole::scene

// ctest-labels: slow-under-sanitizers
// The shipped scenes (scenes/*.yaml) as a teacher uses them: each validates and renders;
// the lungs breathe by the right amount, the heart's chambers contract in sequence (the
// infarct's akinesia: tests/study/physiology_test.cpp); any real mesh in ../shared/meshes goes
// through the bring-your-own-mesh path and beats without error; and the example meshes are
// what their scripts write.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "scene/load.h"
#include "sim/model.h"
#include "sim/solvers/step.h"
#include "support/run.h"
#include "world/world.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(source("scenes"))) {
    if (entry.path().extension() == ".yaml") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(Scenes, TheExpectedScenesShip) {
  std::vector<std::string> names;
  for (const fs::path& p : shipped_scenes()) names.push_back(p.stem().string());
  for (const char* name : {"heart", "heart-tachycardia", "heart-afib", "heart-infarct", "heart-compare", "lungs",
                           "kidney", "liver", "own-mesh", "heart-slowmo-loop", "lungs-breath-gif",
                           "heart-labels", "heart-afib-ecg", "atlas-heart"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << "scenes/" << name << ".yaml";
  }
}

TEST(Scenes, EveryShippedSceneValidatesAndRenders) {
  const fs::path out = scratch("scenes_render");
  for (const fs::path& scene : shipped_scenes()) {
    const std::string name = scene.stem().string();
    const RunResult v = run(systole() + " validate " + scene.string());
    EXPECT_EQ(v.exit_code, 0) << name << ":\n" << v.output;
    EXPECT_EQ(v.output.find("warning:"), std::string::npos) << name << ":\n" << v.output;
    // Shipped clips are 8-12 s of video (title cards and slow motion included; a loop, which
    // repeats, at least 4 s), with a header comment saying what they teach.
    const scene::Scene s = scene::load(scene);
    double video_s = s.output.duration_s * s.output.slow_motion;
    for (const auto& card : s.cards) video_s += card.duration_s;
    EXPECT_GE(video_s, s.output.loop ? 4.0 : 8.0) << name;
    EXPECT_LE(video_s, 12.0) << name;
    EXPECT_EQ(read_file(scene).rfind("# ", 0), 0u) << name << ": no header comment";

    const fs::path frames = out / name;
    const RunResult r = run(systole() + " render " + scene.string() + " --frames 0..2 --png " + frames.string() +
                            " --no-video -D output.width=160 -D output.height=90");
    EXPECT_EQ(r.exit_code, 0) << name << ":\n" << r.output;
    for (int f = 0; f < 3; ++f) {
      char file[32];
      std::snprintf(file, sizeof file, "frame_%05d.png", f);
      EXPECT_TRUE(fs::exists(frames / file)) << name << " " << file;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Motion of the scenes, simulated without rendering.

world::World world_of(const std::string& scene_name) {
  return world::build_world(scene::load(source("scenes/" + scene_name + ".yaml")));
}

/// Steps one organ of the world alone by the world's step until time t_s. unit: s
void step_until(world::World& w, world::OrganBody& body, double t_s) {
  while (body.state.time_s < t_s - 1e-9) sim::step(body.model, body.state, w.dt_s);
}

TEST(Scenes, LungsBreatheTenToTwentyPercent) {
  world::World w = world_of("lungs");
  world::OrganBody& lungs = w.organs.at(0);
  ASSERT_TRUE(lungs.model.volume.enabled);
  const double period_s = 60.0 / 14.0;
  // The second breath, after the first has set the body going.
  step_until(w, lungs, period_s);
  double lo = 1e9, hi = 0;
  while (lungs.state.time_s < 2 * period_s) {
    step_until(w, lungs, lungs.state.time_s + 0.05);
    const double v = sim::enclosed_volume(lungs.state.x, lungs.model.volume.triangles);
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  const double change = (hi - lo) / lo;
  std::printf("[ lungs    ] volume %.0f to %.0f ml over a breath: %.1f%%\n", lo * 1e6, hi * 1e6, 100 * change);
  EXPECT_GT(change, 0.10);
  EXPECT_LT(change, 0.20);
}

int region_index(const sim::Model& m, const std::string& name) {
  for (size_t r = 0; r < m.regions.size(); ++r) {
    if (m.regions[r].name == name) return static_cast<int>(r);
  }
  ADD_FAILURE() << "no region " << name;
  return 0;
}

/// Per cavity of the organ's anatomy (by name): the time in [from_s, to_s) when the volume
/// its lining encloses is least (the end of that chamber's emptying), sampled every frame as
/// the valves measure it. unit: s
std::map<std::string, double> emptiest_times(world::World& w, const world::OrganBody& body, double from_s, double to_s) {
  const std::vector<mesh::Cavity>& cavities = body.valves.cavities;
  std::vector<double> least(cavities.size(), HUGE_VAL), when(cavities.size(), 0);
  for (int frame = 1; frame * w.frame_s < to_s; ++frame) {
    world::advance_to_frame(w, frame);
    if (body.state.time_s < from_s - 1e-9) continue;
    for (size_t c = 0; c < cavities.size(); ++c) {
      if (body.valves.volume_m3[c] < least[c]) least[c] = body.valves.volume_m3[c], when[c] = body.state.time_s;
    }
  }
  std::map<std::string, double> out;
  for (size_t c = 0; c < cavities.size(); ++c) out[cavities[c].name] = when[c];
  return out;
}

TEST(Scenes, HeartChambersContractInSequence) {
  // The chambers as a cardiologist times them: each cavity's volume, least at the end of its
  // emptying. (Distances to the centre would blur it: the ventricles pull the base, atria
  // included, towards the apex as they contract.)
  world::World w = world_of("heart");
  const world::OrganBody& heart = w.organs.at(0);
  ASSERT_FALSE(heart.valves.empty()) << "heart.yaml is the anatomical heart";
  const double beat_s = 60.0 / 72.0;
  // The second beat.
  const std::map<std::string, double> t = emptiest_times(w, heart, beat_s, 2 * beat_s);
  auto at = [&](const char* chamber) {
    EXPECT_TRUE(t.count(chamber)) << "no cavity " << chamber;
    return t.count(chamber) ? t.at(chamber) - beat_s : 0.0;
  };
  std::printf("[ heart    ] emptiest at: LA %.0f ms, RA %.0f ms, LV %.0f ms, RV %.0f ms into the beat\n",
              1e3 * at("left_atrium"), 1e3 * at("right_atrium"), 1e3 * at("left_ventricle"), 1e3 * at("right_ventricle"));
  for (const char* atrium : {"left_atrium", "right_atrium"}) {
    // The atria empty in their own systole, the first 15 % of the beat (125 ms) and a frame or two after.
    EXPECT_LT(at(atrium), 0.20) << atrium;
    for (const char* ventricle : {"left_ventricle", "right_ventricle"}) {
      // Then the ventricles, after the AV delay (160 ms) and their ejection (about 0.3 s).
      EXPECT_GT(at(ventricle) - at(atrium), 0.16) << atrium << " then " << ventricle;
      EXPECT_LT(at(ventricle) - at(atrium), 0.50) << atrium << " then " << ventricle;
    }
  }
}

TEST(Scenes, AfibIsIrregularAndRepeats) {
  // The seeded irregular rhythm: two builds give the same beats; the ventricles' beat
  // lengths vary by more than 10%.
  const world::World a = world_of("heart-afib"), b = world_of("heart-afib");
  const sim::Model& m = a.organs.at(0).model;
  const int ventricles = region_index(m, "ventricles");
  const std::vector<double>& beats = m.beat_boundaries[static_cast<size_t>(ventricles)];
  ASSERT_GT(beats.size(), 4u);
  EXPECT_EQ(beats, b.organs.at(0).model.beat_boundaries[static_cast<size_t>(ventricles)]);
  double shortest = 1e9, longest = 0;
  for (size_t k = 1; k < beats.size(); ++k) {
    shortest = std::min(shortest, beats[k] - beats[k - 1]), longest = std::max(longest, beats[k] - beats[k - 1]);
  }
  EXPECT_GT(longest / shortest, 1.1);
}

// ---------------------------------------------------------------------------------------
// Bring your own mesh: every real mesh in ../shared/meshes through the file path.

TEST(Scenes, SharedMeshesBeatThroughTheOwnMeshPath) {
  const fs::path dir = fs::path(SYSTOLE_SOURCE_DIR) / ".." / "shared" / "meshes";
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no shared meshes at " << dir << " (optional test data)";
  int count = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".obj" && ext != ".stl" && ext != ".glb" && ext != ".ply") continue;
    ++count;
    const std::string file = entry.path().string();
    // Units as PROVENANCE.md gives them (a GLB is in metres by the glTF specification); an
    // unknown unit is taken as mm and scaled to an organ's size (the SOFA heart spans about
    // 39 units).
    std::string units = "mm", scale = "1";
    if (file.find("liver") != std::string::npos) units = "cm";
    if (file.find("kidney") != std::string::npos || ext == ".glb") units = "m";
    if (file.find("heart") != std::string::npos && ext != ".glb") scale = "3";
    const std::string yaml = "organs:\n"
                             "  - name: organ\n"
                             "    mesh: {file: \"" + file + "\", units: " + units + "}\n"
                             "    transform: {scale: " + scale + "}\n"
                             "    body: {mass: 300 g, stiffness: 400 N/m, volume_stiffness: 5 kPa, drag: 2 1/s}\n"
                             "    regions:\n"
                             "      - name: all\n"
                             "        select: all\n"
                             "        drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}\n"
                             "output: {fps: 30, duration: 3 s}\n";
    try {
      const scene::Scene s = scene::load_from_string(yaml, (dir / "byo.yaml").string());
      world::World w = world::build_world(s);
      // A single shell (the SOFA and capsule meshes) must weld closed; an atlas file of many
      // overlapping open parts cannot be, and still has to beat.
      const mesh::MeshReport& report = w.organs.at(0).geometry.report;
      if (report.components == 1) {
        EXPECT_TRUE(report.closed()) << file;
      }
      world::advance_to_frame(w, 75);  // 2.5 s: three beats.
      EXPECT_TRUE(w.organs.at(0).state.x.allFinite()) << file;
      std::printf("[ own mesh ] %s: %d triangles, three beats fine\n", entry.path().filename().c_str(),
                  w.organs.at(0).geometry.report.triangles);
    } catch (const std::exception& e) {
      ADD_FAILURE() << file << ": " << e.what();
    }
  }
  if (count == 0) GTEST_SKIP() << "no mesh files in " << dir;
}

TEST(Scenes, TheExampleMeshesAreWhatTheirScriptsWrite) {
  // Our own example files are made by scripts, not downloaded: a fresh copy is the same file.
  if (run("command -v python3").exit_code != 0) GTEST_SKIP() << "python3 is not installed";
  const fs::path out = scratch("example_meshes");
  for (const auto& [script, file] : {std::pair{"scripts/make-atlas-example", "scenes/meshes/heart-parts.glb"},
                                     std::pair{"scripts/make-own-mesh-example", "scenes/meshes/stomach.obj"}}) {
    const fs::path fresh = out / fs::path(file).filename();
    const RunResult r = run("python3 " + source(script) + " " + fresh.string());
    ASSERT_EQ(r.exit_code, 0) << script << ":\n" << r.output;
    EXPECT_EQ(read_file(fresh), read_file(source(file))) << script << " no longer writes " << file;
  }
}

}  // namespace
}  // namespace systole::test

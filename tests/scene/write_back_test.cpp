// Writing a scene back (scene/write.h), as `systole tune` does: the written file loads again
// with the new regions, pinned regions and everything else as written, mesh paths still
// pointing at the same files from another folder, the note after the leading comments, and
// writing the reloaded scene again gives the same text (every value written as it reads).

#include "scene/write.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "scene/load.h"
#include "scene/scene.h"

namespace systole::scene {
namespace {

namespace fs = std::filesystem;

const char* kScene =
    "# A heart and a ball, for writing back.\n"
    "# Second line of the leading comment.\n"
    "seed: 3\n"
    "organs:\n"
    "  - name: heart\n"
    "    mesh: {procedural: heart, detail: 1}\n"
    "    body: {mass: 300 g, stiffness: 400 N/m, damping: 10 ms}\n"
    "    regions:\n"
    "      - name: left_ventricle\n"
    "        drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.14, delay: 160 ms, systolic_fraction: 0.36}\n"
    "      - name: right_ventricle\n"
    "        drive: {waveform: sine, rate: 1.1 Hz, amplitude: 0.1}\n"
    "      - {name: aorta, pinned: true}\n"
    "  - name: ball\n"
    "    mesh: {file: meshes/ball.obj}\n"
    "    body: {mass: 50 g, stiffness: 100 N/m}\n"
    "output: {file: out/x.mp4, width: 320, height: 240, fps: 30, duration: 1 s}\n";

struct Files {
  fs::path scene, output;
};

/// The scene and its mesh in a folder of this test's own (ctest may run the tests of one
/// program at once), and where the tuned scene goes.
Files files() {
  const fs::path dir = fs::path(SYSTOLE_TEST_SCRATCH) / "write_back" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(dir);
  fs::create_directories(dir / "scenes" / "meshes");
  fs::create_directories(dir / "tuned");
  std::ofstream(dir / "scenes" / "meshes" / "ball.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  std::ofstream(dir / "scenes" / "heart.yaml") << kScene;
  return {dir / "scenes" / "heart.yaml", dir / "tuned" / "heart-tuned.yaml"};
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

const Organ& organ(const Scene& s, const std::string& name) {
  for (const Organ& o : s.organs)
    if (o.name == name) return o;
  throw std::runtime_error("no organ " + name);
}

const Region& region(const Organ& o, const std::string& name) {
  for (const Region& r : o.regions)
    if (r.name == name) return r;
  throw std::runtime_error("no region " + name);
}

TEST(WriteBack, TheWrittenSceneLoadsWithTheNewRegionsAndTheRestAsWritten) {
  const Files f = files();
  const Scene original = load(f.scene);
  OrganRegions change{"heart", organ(original, "heart").regions};
  change.regions[0].stiffness_scale = 2.5;  // left_ventricle
  change.regions[2].stiffness_scale = 9.0;  // aorta: pinned, left alone
  const std::string text = scene_yaml_with_regions(original, {change}, f.output, "# tuned by a test\n");
  write(f.output, text);

  const Scene tuned = load(f.output);
  EXPECT_EQ(region(organ(tuned, "heart"), "left_ventricle").stiffness_scale, 2.5);
  EXPECT_EQ(region(organ(tuned, "heart"), "right_ventricle").stiffness_scale, 1.0);
  EXPECT_EQ(region(organ(tuned, "heart"), "aorta").stiffness_scale, 1.0);
  EXPECT_TRUE(region(organ(tuned, "heart"), "aorta").pinned);
  EXPECT_EQ(tuned.seed, original.seed);
  EXPECT_EQ(tuned.organs.size(), original.organs.size());
  // The ball's mesh, written relative to the scene's folder, is the same file from the output's.
  EXPECT_EQ(fs::weakly_canonical(organ(tuned, "ball").mesh.file), fs::weakly_canonical(organ(original, "ball").mesh.file));
  EXPECT_NE(text.find("file: ../scenes/meshes/ball.obj"), std::string::npos) << text;  // Rebased, not copied.
}

TEST(WriteBack, TheNoteFollowsTheLeadingComments) {
  const Files f = files();
  const std::string text = scene_yaml_with_regions(load(f.scene), {}, f.output, "# tuned by a test\n");
  EXPECT_EQ(text.rfind("# A heart and a ball, for writing back.\n# Second line of the leading comment.\n# tuned by a test\n", 0), 0u)
      << text.substr(0, 200);
}

TEST(WriteBack, WritingTheReloadedSceneAgainGivesTheSameText) {
  const Files f = files();
  const Scene original = load(f.scene);
  OrganRegions change{"heart", organ(original, "heart").regions};
  change.regions[1].stiffness_scale = 0.37;
  const std::string first = scene_yaml_with_regions(original, {change}, f.output, "# tuned\n");
  write(f.output, first);
  const Scene reloaded = load(f.output);
  // Its own regions, written where it is: every drive and stiffness reads back as written.
  const std::string second =
      scene_yaml_with_regions(reloaded, {{"heart", organ(reloaded, "heart").regions}}, f.output, "");
  EXPECT_EQ(second, first);
}

// `systole tune -D ...` tunes the scene with the overrides: the written scene must hold them,
// or it would play drives tuned for another body. Inline maps stay inline.
TEST(WriteBack, TheSceneIsWrittenWithTheOverridesItWasLoadedWith) {
  const Files f = files();
  const Scene original = load(f.scene, {"organs.ball.body.mass=70 g", "organs.heart.regions.aorta.pinned=false"});
  const std::string text = scene_yaml_with_regions(original, {}, f.output, "");
  write(f.output, text);
  const Scene tuned = load(f.output);
  EXPECT_DOUBLE_EQ(organ(tuned, "ball").body.mass_kg, 0.07);
  EXPECT_FALSE(region(organ(tuned, "heart"), "aorta").pinned);
  EXPECT_DOUBLE_EQ(organ(tuned, "heart").body.mass_kg, 0.3) << "the rest as written";
  EXPECT_NE(text.find("mesh: {procedural: heart, detail: 1}"), std::string::npos) << text;
  EXPECT_NE(text.find("body: {mass: 70 g, stiffness: 100 N/m}"), std::string::npos) << text;
}

TEST(WriteBack, ASceneFileThatCannotBeReadAgainIsNoInput) {
  const Files f = files();
  const Scene s = load(f.scene);
  fs::remove(f.scene);
  try {
    scene_yaml_with_regions(s, {}, f.output, "");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kNoInput);
  }
}

}  // namespace
}  // namespace systole::scene

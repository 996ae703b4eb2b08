// -D key.path=value: applied before validation, addressed by index or by name.

#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace systole::scene {
namespace {

using testing::load_error;

const char* const kTwoOrgans = R"(organs:
  - name: heart
    mesh: {procedural: heart}
    regions:
      - name: left_ventricle
        drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}
      - name: right_ventricle
  - name: lungs
    mesh: {procedural: lungs}
)";

TEST(SceneOverrides, ByIndex) {
  const Scene s = load_from_string(kTwoOrgans, "t.yaml", {"organs.1.body.mass=2 kg", "organs.0.regions.1.pinned=true"});
  EXPECT_DOUBLE_EQ(s.organs[1].body.mass_kg, 2.0);
  EXPECT_TRUE(s.organs[0].regions[1].pinned);
}

TEST(SceneOverrides, ByName) {
  const Scene s = load_from_string(kTwoOrgans, "t.yaml", {"organs.heart.regions.left_ventricle.drive.rate=90 bpm"});
  EXPECT_DOUBLE_EQ(s.organs[0].regions[0].drive.rate_hz, 1.5);
  EXPECT_DOUBLE_EQ(s.organs[0].regions[0].drive.amplitude, 0.1);  // siblings untouched
}

TEST(SceneOverrides, ValueIsYaml) {
  const Scene s = load_from_string(kTwoOrgans, "t.yaml",
                                   {"camera.position=[0, 10 cm, 1]", "organs.heart.regions.right_ventricle.select={sphere: {radius: 1 cm}}"});
  EXPECT_DOUBLE_EQ(s.camera.position_m.y(), 0.1);
  ASSERT_EQ(s.organs[0].regions[1].select.size(), 1u);
  EXPECT_EQ(s.organs[0].regions[1].select[0].kind, SelectorKind::kSphere);
}

TEST(SceneOverrides, CreatesMissingSchemaMaps) {
  const Scene s = load_from_string(kTwoOrgans, "t.yaml", {"output.width=640", "organs.lungs.material.specular=0.1"});
  EXPECT_EQ(s.output.width, 640);
  EXPECT_DOUBLE_EQ(s.organs[1].material.specular, 0.1);
}

TEST(SceneOverrides, LaterOverrideWins) {
  const Scene s = load_from_string(kTwoOrgans, "t.yaml", {"seed=3", "seed=4"});
  EXPECT_EQ(s.seed, 4u);
}

TEST(SceneOverrides, ValueIsValidatedAndNamedAsTheOrigin) {
  const auto f = load_error(kTwoOrgans, {"organs.heart.body.mass=-1"});
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_EQ(f.message, "-D organs.heart.body.mass=-1: organs[0].body.mass: -1 kg is outside (0, 1000] kg");
}

TEST(SceneOverrides, UnknownKeyGetsTheUnknownKeyMessage) {
  const auto f = load_error(kTwoOrgans, {"organs.heart.body.stifness=1"});
  // The allowed keys are listed (the whole list grows with the schema; the docs test
  // checks it).
  EXPECT_EQ(f.message.rfind("-D organs.heart.body.stifness=1: organs[0].body: unknown key \'stifness\' (did you mean \'stiffness\'?); allowed keys: mass, stiffness, damping, ", 0), 0u) << f.message;
}

TEST(SceneOverrides, MissingItemsAreErrors) {
  auto f = load_error(kTwoOrgans, {"organs.kidney.body.mass=1"});
  EXPECT_EQ(f.message, "-D organs.kidney.body.mass=1: organs: no item named 'kidney'; names: heart, lungs");
  f = load_error(kTwoOrgans, {"organs.5.body.mass=1"});
  EXPECT_EQ(f.message, "-D organs.5.body.mass=1: organs: no item 5; the list has 2 item(s)");
  f = load_error(kTwoOrgans, {"lights.0.intensity=2"});  // lights not written: cannot be created item by item
  EXPECT_NE(f.message.find("lights: is not in the scene"), std::string::npos) << f.message;
  f = load_error(kTwoOrgans, {"seed.value=1"});
  EXPECT_NE(f.message.find("seed: is "), std::string::npos) << f.message;
  f = load_error(kTwoOrgans, {"seed"});
  EXPECT_NE(f.message.find("expected key.path=value"), std::string::npos) << f.message;
}

}  // namespace
}  // namespace systole::scene

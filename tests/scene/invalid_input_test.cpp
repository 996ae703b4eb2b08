// Bad scenes: every error names file:line:column and the key, and says what was expected.

#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace systole::scene {
namespace {

using testing::kMinimalOrgans;
using testing::load_error;

std::string with_organ_keys(const std::string& organ_lines) {
  return "organs:\n  - name: heart\n    mesh: {procedural: heart}\n" + organ_lines;
}

TEST(SceneInvalid, UnknownKeyNamesPlaceAndSuggestsTheClosestKey) {
  const auto f = load_error(with_organ_keys("    body:\n      stifness: 400 N/m\n"));
  EXPECT_EQ(f.code, ExitCode::kDataError);
  // The allowed keys are listed (the whole list grows with the schema; the docs test
  // checks it).
  EXPECT_EQ(f.message.rfind("scenes/test.yaml:5:7: organs[0].body: unknown key \'stifness\' (did you mean \'stiffness\'?); allowed keys: mass, stiffness, damping, ", 0), 0u) << f.message;
}

TEST(SceneInvalid, BytesThatAreNotTextAreShownEscapedInTheMessage) {
  const auto f = load_error(std::string(kMinimalOrgans) + "sound\xfftrack: loud\n");
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_NE(f.message.find("sound\\xfftrack"), std::string::npos) << f.message;
  for (const char c : f.message) EXPECT_NE(static_cast<unsigned char>(c), 0xFF) << "a raw byte in: " << f.message;
  // Text that is UTF-8 stays as it is.
  const auto g = load_error(std::string(kMinimalOrgans) + "caf\xc3\xa9: 1\n");
  EXPECT_NE(g.message.find("unknown key 'caf\xc3\xa9'"), std::string::npos) << g.message;
}

TEST(SceneInvalid, UnknownTopLevelKeyWithoutCloseMatchHasNoSuggestion) {
  const auto f = load_error(std::string(kMinimalOrgans) + "soundtrack: loud\n");
  EXPECT_EQ(f.message.find("did you mean"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("scenes/test.yaml:4:1: unknown key 'soundtrack'; allowed keys: seed, gravity, organs"),
            std::string::npos) << f.message;
}

TEST(SceneInvalid, FrequencyWithoutUnitIsRejectedWithExamples) {
  const auto f = load_error(with_organ_keys("    regions:\n      - name: lv\n        drive: {waveform: sine, rate: 72}\n"));
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_EQ(f.message, "scenes/test.yaml:6:39: organs[0].regions[0].drive.rate: expected a frequency with a unit, "
                       "e.g. \"72 bpm\" or \"1.2 Hz\"; got \"72\"");
}

TEST(SceneInvalid, TimeWithoutUnitIsRejectedButZeroIsFine) {
  auto f = load_error(std::string(kMinimalOrgans) + "output: {duration: 10}\n");
  EXPECT_NE(f.message.find("scenes/test.yaml:4:20: output.duration: expected a time with a unit"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv, drive: {delay: 0}}]\n"));
  EXPECT_TRUE(f.message.empty()) << f.message;
}

TEST(SceneInvalid, UnknownUnitListsTheAcceptedOnes) {
  const auto f = load_error(std::string(kMinimalOrgans) + "output: {duration: 10 min}\n");
  EXPECT_NE(f.message.find("output.duration: unknown unit 'min' in \"10 min\"; a time takes s, ms"), std::string::npos)
      << f.message;
}

TEST(SceneInvalid, OutOfRangeSaysTheRange) {
  auto f = load_error(with_organ_keys("    regions: [{name: lv, drive: {amplitude: 1.5}}]\n"));
  EXPECT_NE(f.message.find("scenes/test.yaml:4:45: organs[0].regions[0].drive.amplitude: 1.5 is outside [0, 0.95]"),
            std::string::npos) << f.message;
  f = load_error(with_organ_keys("    body: {mass: -1}\n"));
  EXPECT_NE(f.message.find("organs[0].body.mass: -1 kg is outside (0, 1000] kg"), std::string::npos) << f.message;
  // In another unit than the range's, the message shows both.
  f = load_error(with_organ_keys("    regions: [{name: lv, drive: {waveform: sine, rate: 1500 bpm}}]\n"));
  EXPECT_NE(f.message.find("rate: 1500 bpm = 25 Hz is outside [0, 20] Hz"), std::string::npos) << f.message;
  f = load_error(std::string(kMinimalOrgans) + "camera: {fov: 170 deg}\n");
  EXPECT_NE(f.message.find("camera.fov: 170 deg is outside (1, 170) deg"), std::string::npos) << f.message;
  f = load_error(std::string(kMinimalOrgans) + "output: {crf: 52}\n");
  EXPECT_NE(f.message.find("output.crf: 52 is outside 0..51"), std::string::npos) << f.message;
}

TEST(SceneInvalid, NanAndInfinityAreRejectedEverywhere) {
  for (const char* bad : {".nan", ".inf", "-.inf", "nan", "inf", "1e999", ".NaN"}) {
    const std::string value(bad);
    auto f = load_error(with_organ_keys("    body: {stiffness: " + value + "}\n"));
    EXPECT_NE(f.message.find("organs[0].body.stiffness: expected a finite number"), std::string::npos) << f.message;
    f = load_error(std::string(kMinimalOrgans) + "camera: {position: [0, " + value + ", 1]}\n");
    EXPECT_NE(f.message.find("camera.position[1]: expected a finite number"), std::string::npos) << f.message;
    f = load_error(with_organ_keys("    regions: [{name: lv, drive: {amplitude: " + value + "}}]\n"));
    EXPECT_NE(f.message.find("drive.amplitude: expected a finite number"), std::string::npos) << f.message;
  }
}

TEST(SceneInvalid, WrongTypesSayWhatWasExpected) {
  auto f = load_error(with_organ_keys("    body: {mass: {kg: 3}}\n"));
  EXPECT_NE(f.message.find("organs[0].body.mass: expected a mass, e.g. \"300 g\" or \"0.3 kg\"; got a map"), std::string::npos)
      << f.message;
  f = load_error(with_organ_keys("    body: [1, 2]\n"));
  EXPECT_NE(f.message.find("organs[0].body: expected a map with keys mass, stiffness"), std::string::npos) << f.message;
  f = load_error(std::string(kMinimalOrgans) + "output: {width: 1280.5}\n");
  EXPECT_NE(f.message.find("output.width: expected a whole number; got \"1280.5\""), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv, pinned: maybe}]\n"));
  EXPECT_NE(f.message.find("pinned: expected true or false; got \"maybe\""), std::string::npos) << f.message;
  f = load_error(std::string(kMinimalOrgans) + "solver: {method: rk4}\n");
  EXPECT_NE(f.message.find("solver.method: expected one of xpbd, explicit, implicit, projective; got \"rk4\""), std::string::npos)
      << f.message;
  f = load_error(std::string(kMinimalOrgans) + "camera: {up: [0, 1]}\n");
  EXPECT_NE(f.message.find("camera.up: expected a list of 3 numbers"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv, drive: {amplitude: 12 %}}]\n"));
  EXPECT_NE(f.message.find("amplitude: expected a plain number without a unit"), std::string::npos) << f.message;
}

TEST(SceneInvalid, ColoursAreHexOrUnitChannels) {
  auto f = load_error(with_organ_keys("    material: {color: [1.2, 0, 0]}\n"));
  EXPECT_NE(f.message.find("organs[0].material.color[0]: 1.2 is outside [0, 1]"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    material: {color: \"#12345\"}\n"));
  EXPECT_NE(f.message.find("expected a colour: \"#rrggbb\""), std::string::npos) << f.message;
  // Unquoted, the # starts a comment: the message says so.
  f = load_error(with_organ_keys("    material:\n      color: #b8322a\n"));
  EXPECT_NE(f.message.find("unquoted # starts a YAML comment"), std::string::npos) << f.message;
}

TEST(SceneInvalid, OddFrameSizeExplainsWhy) {
  const auto f = load_error(std::string(kMinimalOrgans) + "output:\n  width: 1281\n");
  EXPECT_EQ(f.message, "scenes/test.yaml:5:10: output.width: 1281 is odd; H.264 with yuv420p needs even sizes; use 1280 or 1282");
}

TEST(SceneInvalid, CrossFieldRules) {
  auto f = load_error("seed: 1\n");
  EXPECT_NE(f.message.find("missing required key 'organs'"), std::string::npos) << f.message;
  f = load_error("organs: []\n");
  EXPECT_NE(f.message.find("organs: expected 1..64 items; got 0"), std::string::npos) << f.message;
  f = load_error(std::string(kMinimalOrgans) + "  - name: heart\n    mesh: {procedural: heart}\n");
  EXPECT_NE(f.message.find("scenes/test.yaml:4:11: organs[1].name: duplicate organ name 'heart' (also organs[0])"),
            std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv}, {name: lv}]\n"));
  EXPECT_NE(f.message.find("organs[0].regions[1].name: duplicate region name 'lv'"), std::string::npos) << f.message;
  f = load_error("organs:\n  - name: heart\n    mesh: {procedural: heart, file: a.obj}\n");
  EXPECT_NE(f.message.find("organs[0].mesh: expected exactly one of file, procedural; got both"), std::string::npos)
      << f.message;
  f = load_error("organs:\n  - name: heart\n    mesh: {detail: 2}\n");
  EXPECT_NE(f.message.find("got neither"), std::string::npos) << f.message;
  f = load_error("organs:\n  - mesh: {procedural: heart}\n");
  EXPECT_NE(f.message.find("scenes/test.yaml:2:5: organs[0]: missing required key 'name'"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv, drive: {waveform: cardiac}}]\n"));
  EXPECT_NE(f.message.find("drive.rate: a driven region"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv, drive: {waveform: fourier, rate: 1 Hz, harmonics: "
                                 "[{amplitude: 0.4}, {amplitude: 0.3}]}}]\n"));
  EXPECT_NE(f.message.find("harmonic amplitudes sum to 0.7"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv, select: {part: a, sphere: {radius: 1 cm}}}]\n"));
  EXPECT_NE(f.message.find("select: a selector has exactly one of"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv, select: {box: {min: [1, 0, 0], max: [0, 1, 1]}}}]\n"));
  EXPECT_NE(f.message.find("select.box.max: every coordinate of max must be >= that of min"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: '7'}]\n"));
  EXPECT_NE(f.message.find("must not be only digits"), std::string::npos) << f.message;
  f = load_error(std::string(kMinimalOrgans) + "camera: {position: [0, 1, 0], up: [0, 1, 0]}\n");
  EXPECT_NE(f.message.find("camera.up: must not be parallel"), std::string::npos) << f.message;
  f = load_error(std::string(kMinimalOrgans) + "output: {antialias: 3}\n");
  EXPECT_NE(f.message.find("output.antialias: expected one of off, fxaa, msaa2, msaa4"), std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: lv, drive: {samples: [0]}}]\n"));
  EXPECT_NE(f.message.find("drive.samples: expected 2..1024 items; got 1"), std::string::npos) << f.message;
}

// A part is named as validate lists it, whatever its author wrote; a region's own name
// stays a word, since it is a -D path segment (organs.heart.regions.NAME) and a file name.
TEST(SceneInvalid, APartIsAnyTextButARegionNameStaysAWord) {
  for (const std::string& written : {std::string("heart/left_atrium"), std::string("'Heart: left'"),
                                     std::string("Armature|Valve.001")}) {
    SCOPED_TRACE(written);
    const Scene scene = load_from_string(with_organ_keys("    regions: [{name: la, select: {part: " + written + "}}]\n"),
                                         "scenes/test.yaml");
    const std::string unquoted = written.front() == '\'' ? written.substr(1, written.size() - 2) : written;
    EXPECT_EQ(scene.organs[0].regions[0].select[0].part, unquoted);
  }
  const Scene by_define = load_from_string(with_organ_keys("    regions: [{name: la}]\n"), "scenes/test.yaml",
                                           {"organs.heart.regions.la.select={part: heart/left_atrium}"});
  EXPECT_EQ(by_define.organs[0].regions[0].select[0].part, "heart/left_atrium") << "a -D value takes it as the file does";

  auto f = load_error(with_organ_keys("    regions: [{name: la, select: {part: ''}}]\n"));
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_NE(f.message.find("scenes/test.yaml:4:"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("organs[0].regions[0].select.part: expected a part's name as `systole validate` lists it"),
            std::string::npos) << f.message;
  f = load_error(with_organ_keys("    regions: [{name: heart/left_atrium}]\n"));
  EXPECT_NE(f.message.find("organs[0].regions[0].name: a name may use only letters, digits, '_' and '-'"),
            std::string::npos) << f.message;
  EXPECT_NE(f.message.find("name the region left_atrium"), std::string::npos) << "says how to take that part: " << f.message;
  EXPECT_NE(f.message.find("select: {part: heart/left_atrium}"), std::string::npos) << f.message;
}

TEST(SceneInvalid, DuplicateKeyIsAnError) {
  const auto f = load_error(std::string(kMinimalOrgans) + "seed: 1\nseed: 2\n");
  EXPECT_EQ(f.message, "scenes/test.yaml:5:1: duplicate key 'seed' (first written at line 4)");
}

TEST(SceneInvalid, SyntaxErrorGivesLineAndColumn) {
  const auto f = load_error("organs:\n  - name: heart\n    mesh: {procedural: heart\nseed: 1\n");
  EXPECT_EQ(f.code, ExitCode::kDataError);
  EXPECT_EQ(f.message.rfind("scenes/test.yaml:4:", 0), 0u) << f.message;
  EXPECT_NE(f.message.find("invalid YAML"), std::string::npos) << f.message;
}

TEST(SceneInvalid, MissingSceneFileIsNoInput) {
  try {
    load(std::filesystem::path(SYSTOLE_TEST_SCRATCH) / "no_such_scene.yaml");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kNoInput);
    EXPECT_NE(std::string(e.what()).find("no_such_scene.yaml"), std::string::npos);
  }
}

TEST(SceneInvalid, MissingMeshFileIsNoInputWithThePathLookedAt) {
  const auto dir = testing::scratch_dir("missing_mesh");
  testing::write_file(dir / "scene.yaml", "organs:\n  - name: liver\n    mesh:\n      file: meshes/liver.obj\n");
  try {
    load(dir / "scene.yaml");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kNoInput);
    EXPECT_EQ(std::string(e.what()), (dir / "scene.yaml").string() + ":4:13: organs[0].mesh.file: mesh file " +
                                         (dir / "meshes" / "liver.obj").string() + " is not found");
  }
}

TEST(SceneInvalid, SymbolicLinkLoopsAndBrokenLinksAreNamedForWhatTheyAre) {
  const auto dir = testing::scratch_dir("mesh_links");
  std::filesystem::remove(dir / "loop.obj");
  std::filesystem::remove(dir / "broken.obj");
  std::filesystem::create_symlink("loop.obj", dir / "loop.obj");
  std::filesystem::create_symlink("gone.obj", dir / "broken.obj");
  const auto message_for = [&](const std::string& file) -> std::string {
    testing::write_file(dir / "scene.yaml", "organs:\n  - name: liver\n    mesh:\n      file: " + file + "\n");
    try {
      load(dir / "scene.yaml");
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::kNoInput);
      return e.what();
    }
    return "accepted";
  };
  EXPECT_NE(message_for("loop.obj").find(":4:13: organs[0].mesh.file: mesh file " + (dir / "loop.obj").string() +
                                         " is a symbolic link loop"),
            std::string::npos)
      << message_for("loop.obj");
  EXPECT_NE(message_for("broken.obj").find("is a broken symbolic link (to 'gone.obj', which does not exist)"),
            std::string::npos)
      << message_for("broken.obj");
  // The scene file itself.
  std::filesystem::remove(dir / "scene_loop.yaml");
  std::filesystem::create_symlink("scene_loop.yaml", dir / "scene_loop.yaml");
  try {
    load(dir / "scene_loop.yaml");
    FAIL() << "a looping scene link was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kNoInput);
    EXPECT_NE(std::string(e.what()).find("scene_loop.yaml: cannot read the scene file: it is a symbolic link loop"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace systole::scene

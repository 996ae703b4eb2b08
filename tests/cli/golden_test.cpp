// ctest-labels: no-sanitizers
// Golden images: every shipped scene (scenes/*.yaml, found at run time) rendered small at a
// few moments of its cycle and compared with references made by the same renderer, filed
// under tests/golden/<renderer key>/. SYSTOLE_UPDATE_GOLDENS=1 (scripts/update-goldens)
// rewrites only the failing or missing references and says what it changed.
// docs/golden-images.md explains keys, tolerances and the update step.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <set>

#include "common/error.h"
#include "encode/png.h"
#include "scene/load.h"
#include "study/compare.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

/// Small, so the whole suite stays fast; even, as video needs.
const std::vector<std::string> kSize = {"output.width=320", "output.height=240"};
/// Moments of the cycle, unit: s. Rest (the mesh before any step); the atria contracting
/// (in the first 15% of a 72 bpm beat, before the 160 ms AV delay); the ventricles
/// contracting; and diastole. Frame = round(t * fps), so a scene at another frame rate is
/// still caught at the same moments.
constexpr double kMoments_s[] = {0.0, 0.1, 0.3, 0.6};
/// llvmpipe is deterministic on one key, so in practice references match exactly; the
/// tolerance only absorbs a few edge pixels flipping if our own float code changes by an ulp.
const study::CompareTolerance kTolerance{2, 0.05};

std::string line_value(const std::string& text, const std::string& prefix) {
  for (std::size_t at = 0; at < text.size();) {
    const auto end = std::min(text.find('\n', at), text.size());
    if (text.compare(at, prefix.size(), prefix) == 0) return text.substr(at + prefix.size(), end - at - prefix.size());
    at = end + 1;
  }
  return {};
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct RendererId {
  std::string key, renderer, version;
  std::string describe() const { return renderer + ", " + version + " (key " + key + ")"; }
};

/// What this machine renders with, as `systole info` reports it.
RendererId this_renderer() {
  const auto r = run(systole() + " info");
  RendererId id{line_value(r.output, "golden key "), line_value(r.output, "gl renderer "),
                line_value(r.output, "gl version ")};
  if (r.exit_code != 0 || id.key.empty()) throw std::runtime_error("systole info failed:\n" + r.output);
  return id;
}

std::string manifest_text(const RendererId& id) {
  std::string t = "# Golden images for one renderer; written by scripts/update-goldens (docs/golden-images.md).\n";
  t += "key: " + id.key + "\n";
  t += "gl renderer: " + id.renderer + "\n";
  t += "gl version: " + id.version + "\n";
  t += "scenes: every scenes/*.yaml, rendered with -D output.width=320 -D output.height=240\n";
  t += "moments: t = 0, 0.1, 0.3, 0.6 s; frame = round(t * fps); file <scene>_<frame>.png\n";
  t += "command: systole render SCENE -D output.width=320 -D output.height=240 --frames LIST --png DIR --no-video\n";
  t += "tolerance: max delta 2, at most 0.05% of pixels over\n";
  return t;
}

/// "llvmpipe (...), 4.5 ... Mesa 22.3.6 (key ...)" for every key that has references.
std::string known_renderers(const fs::path& golden_root) {
  std::string list;
  if (!fs::is_directory(golden_root)) return list;
  for (const auto& entry : fs::directory_iterator(golden_root)) {
    if (!entry.is_directory()) continue;
    const std::string manifest = read_file(entry.path() / "MANIFEST.txt");
    RendererId id{entry.path().filename().string(), line_value(manifest, "gl renderer: "),
                  line_value(manifest, "gl version: ")};
    list += (list.empty() ? "" : "; ") + id.describe();
  }
  return list;
}

std::string reference_name(const std::string& scene, int frame) {
  std::string number = std::to_string(frame);
  number.insert(0, number.size() < 5 ? 5 - number.size() : 0, '0');
  return scene + "_" + number + ".png";
}

/// The figures without the verdict: "max delta 6 (tolerance 2), pixels over ..., psnr 51.98 dB".
std::string one_line(const study::Comparison& c) {
  std::string text = study::describe(c, kTolerance);
  text.pop_back();
  text.erase(text.rfind('\n'));
  for (auto at = text.find('\n'); at != std::string::npos; at = text.find('\n')) text.replace(at, 1, ", ");
  return text;
}

struct GoldenSettings {
  fs::path scenes_dir;   ///< Every *.yaml here is a shipped scene.
  fs::path golden_root;  ///< tests/golden
  fs::path scratch;      ///< Actual frames and diff images: <scratch>/<scene>/frame_NNNNN[.diff].png
  bool update = false;
  std::vector<std::string> extra_defines;  ///< For the tests of the checker itself.
};

struct GoldenOutcome {
  RendererId renderer;
  std::string made_with;               ///< The references' renderer when it is not exactly ours.
  std::string skip_reason;             ///< Set when no references exist for this renderer.
  std::vector<std::string> failures;   ///< One per failing or missing reference.
  std::vector<std::string> changes;    ///< What an update wrote or removed.
  int checked = 0;                     ///< References compared.
};

void check_scene(const GoldenSettings& s, const fs::path& scene_file, const fs::path& key_dir,
                 std::set<std::string>& expected, GoldenOutcome& out) {
  const std::string name = scene_file.stem().string();
  std::vector<std::string> defines = kSize;
  defines.insert(defines.end(), s.extra_defines.begin(), s.extra_defines.end());
  std::vector<int> frames;
  int frame_count = 0;
  try {
    const auto scene = scene::load(scene_file, defines);
    frame_count = scene.output.frame_count();
    for (double t : kMoments_s) {
      const int f = static_cast<int>(std::lround(t * scene.output.fps));
      if (f < frame_count && (frames.empty() || frames.back() != f)) frames.push_back(f);
    }
  } catch (const Error& e) {
    out.failures.push_back(name + ": the scene does not load: " + e.what());
    return;
  }
  std::string list, command = systole() + " render " + shell_quote(scene_file.string());
  for (int f : frames) list += (list.empty() ? "" : ",") + std::to_string(f);
  for (const auto& d : defines) command += " -D " + shell_quote(d);
  const fs::path actual_dir = s.scratch / name;
  fs::remove_all(actual_dir);
  command += " --frames " + list + " --png " + shell_quote(actual_dir.string()) + " --no-video";
  const auto r = run(command);
  if (r.exit_code != 0) {
    out.failures.push_back(name + ": render failed (exit " + std::to_string(r.exit_code) + "): " + command + "\n" +
                           r.output);
    return;
  }

  for (int f : frames) {
    const auto reference = key_dir / reference_name(name, f);
    const auto actual_file = actual_dir / encode::frame_file_name(f, frame_count);
    expected.insert(reference.filename().string());
    const Image actual = encode::read_png(actual_file);
    std::string problem;
    if (!fs::exists(reference)) {
      problem = "missing";
    } else {
      ++out.checked;
      try {
        const Image expected_image = encode::read_png(reference);
        const auto c = study::compare_images(actual, expected_image, kTolerance);
        if (!c.passed) {
          const auto diff = fs::path(actual_file).replace_extension(".diff.png");
          encode::write_png(diff, study::difference_image(actual, expected_image));
          problem = "differs (" + one_line(c) + ")\n  diff (actual | reference | amplified difference): " +
                    diff.string();
        }
      } catch (const Error& e) {
        problem = std::string("unreadable or another size: ") + e.what();
      }
    }
    if (problem.empty()) continue;
    if (s.update) {
      fs::create_directories(key_dir);
      encode::write_png(reference, actual);
      out.changes.push_back((problem == "missing" ? "created " : "updated ") + reference.string() +
                            (problem == "missing" ? "" : " (was: " + problem.substr(0, problem.find('\n')) + ")"));
    } else {
      out.failures.push_back(name + " frame " + std::to_string(f) + ": " + reference.string() + " " + problem +
                             "\n  actual: " + actual_file.string());
    }
  }
}

/// Renders every scene's moments and compares them with the references of this renderer.
GoldenOutcome check_goldens(const GoldenSettings& s) {
  GoldenOutcome out;
  out.renderer = this_renderer();
  const fs::path key_dir = s.golden_root / out.renderer.key;
  if (!fs::is_directory(key_dir) && !s.update) {
    const std::string known = known_renderers(s.golden_root);
    out.skip_reason = (known.empty() ? "no golden images exist yet" : "goldens were made with " + known) +
                      ", this machine renders with " + out.renderer.describe() +
                      "; run scripts/update-goldens to create references for " + out.renderer.key;
    return out;
  }
  // One key may span renderer strings that give the same pixels (e.g. llvmpipe's vector
  // width); if pixels differ after all, the failure says so plainly.
  const std::string old_manifest = read_file(key_dir / "MANIFEST.txt");
  const std::string made_with =
      line_value(old_manifest, "gl renderer: ") + ", " + line_value(old_manifest, "gl version: ");
  if (!old_manifest.empty() && made_with != out.renderer.renderer + ", " + out.renderer.version) out.made_with = made_with;

  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(s.scenes_dir)) {
    if (entry.path().extension() == ".yaml") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  std::set<std::string> expected;
  for (const auto& scene : scenes) check_scene(s, scene, key_dir, expected, out);
  if (!s.update) return out;

  // References of scenes or moments that no longer exist go, unless a scene failed (then
  // its references are unknown, and nothing is removed).
  if (out.failures.empty() && fs::is_directory(key_dir)) {
    for (const auto& entry : fs::directory_iterator(key_dir)) {
      const auto file = entry.path().filename().string();
      if (entry.path().extension() == ".png" && !expected.count(file)) {
        fs::remove(entry.path());
        out.changes.push_back("removed " + entry.path().string() + " (no such scene or moment)");
      }
    }
  }
  const auto manifest = key_dir / "MANIFEST.txt";
  if (fs::is_directory(key_dir) && read_file(manifest) != manifest_text(out.renderer)) {
    write_file(manifest, manifest_text(out.renderer));
    out.changes.push_back("wrote " + manifest.string());
  }
  return out;
}

/// In CI (CI=true, as CI services set it) a renderer without references fails instead of
/// skipping: a CI moved to another Mesa must not pass with no pixel checked.
bool references_required(const char* ci) { return ci != nullptr && (std::string(ci) == "true" || std::string(ci) == "1"); }

bool updating() {
  const char* v = std::getenv("SYSTOLE_UPDATE_GOLDENS");
  return v && std::string(v) != "" && std::string(v) != "0";
}

TEST(Golden, EveryShippedSceneMatchesItsReferences) {
  GoldenSettings s{source("scenes"), source("tests/golden"), scratch("golden"), updating(), {}};
  const auto out = check_goldens(s);
  for (const auto& change : out.changes) std::cout << "golden: " << change << "\n";
  if (s.update) std::cout << "golden: " << out.changes.size() << " change(s) for " << out.renderer.key << "\n";
  if (!out.skip_reason.empty() && references_required(std::getenv("CI"))) {
    FAIL() << out.skip_reason << ". CI=true: a CI run must check pixels, so missing references fail here.";
  }
  if (!out.skip_reason.empty()) GTEST_SKIP() << out.skip_reason;
  for (const auto& failure : out.failures) ADD_FAILURE() << failure;
  if (!out.failures.empty()) {
    ADD_FAILURE() << out.failures.size() << " golden image(s) failed for " << out.renderer.key
                  << ". If the change is intended, run scripts/update-goldens and commit tests/golden/."
                  << (out.made_with.empty() ? ""
                                            : "\nNote: these references were made with " + out.made_with +
                                                  "; this machine renders with " + out.renderer.renderer + ", " +
                                                  out.renderer.version + ".");
  }
}

// --- the checker itself, on a scratch copy of the references ---------------------------

class GoldenChecker : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch(::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "scenes");
    fs::copy_file(source("scenes/heart.yaml"), dir_ / "scenes" / "heart.yaml");
  }
  GoldenOutcome check(bool update, std::vector<std::string> defines = {}) {
    return check_goldens({dir_ / "scenes", dir_ / "golden", dir_ / "actual", update, std::move(defines)});
  }
  static std::string joined(const std::vector<std::string>& lines) {
    std::string all;
    for (const auto& l : lines) all += l + "\n";
    return all;
  }
  fs::path dir_;
};

TEST_F(GoldenChecker, AnotherRendererIsSkippedWithAPlainMessage) {
  fs::create_directories(dir_ / "golden" / "softpipe-mesa-20.0.0");
  write_file(dir_ / "golden" / "softpipe-mesa-20.0.0" / "MANIFEST.txt",
             "gl renderer: softpipe\ngl version: 3.3 (Core Profile) Mesa 20.0.0\n");
  const auto out = check(false);
  EXPECT_TRUE(out.failures.empty()) << joined(out.failures);
  EXPECT_EQ(out.skip_reason.find("goldens were made with softpipe, 3.3 (Core Profile) Mesa 20.0.0"), 0u)
      << out.skip_reason;
  EXPECT_NE(out.skip_reason.find("this machine renders with " + out.renderer.renderer), std::string::npos)
      << out.skip_reason;
  EXPECT_NE(out.skip_reason.find("run scripts/update-goldens to create references for " + out.renderer.key),
            std::string::npos)
      << out.skip_reason;
}

TEST(GoldenCheckerInCi, ARendererWithoutReferencesFailsWhenCiIsSet) {
  EXPECT_TRUE(references_required("true"));
  EXPECT_TRUE(references_required("1"));
  EXPECT_FALSE(references_required(nullptr));
  EXPECT_FALSE(references_required("false"));
  EXPECT_FALSE(references_required(""));
}

TEST_F(GoldenChecker, UpdateFixesOnlyWhatAChangedDriveBrokeAndSaysSo) {
  // A fresh key: the update creates every reference and the manifest.
  auto out = check(true);
  ASSERT_TRUE(out.failures.empty()) << joined(out.failures);
  EXPECT_EQ(out.changes.size(), std::size(kMoments_s) + 1) << joined(out.changes);
  EXPECT_NE(joined(out.changes).find("created " + (dir_ / "golden" / out.renderer.key / "heart_00009.png").string()),
            std::string::npos)
      << joined(out.changes);
  // A scene without references fails unless updating.
  fs::copy_file(dir_ / "scenes" / "heart.yaml", dir_ / "scenes" / "twin.yaml");
  out = check(false);
  EXPECT_EQ(out.failures.size(), std::size(kMoments_s)) << joined(out.failures);
  EXPECT_NE(joined(out.failures).find("twin_00000.png missing"), std::string::npos) << joined(out.failures);
  fs::remove(dir_ / "scenes" / "twin.yaml");

  // The same build renders the same pixels.
  out = check(false);
  EXPECT_TRUE(out.failures.empty()) << joined(out.failures);
  EXPECT_EQ(out.checked, static_cast<int>(std::size(kMoments_s)));

  // A stronger ventricle: the contracted moments differ, with a diff image beside the frame;
  // the rest shape (frame 0) does not.
  const std::vector<std::string> stronger = {"organs.heart.regions.left_ventricle.drive.amplitude=0.30"};
  out = check(false, stronger);
  const std::string failures = joined(out.failures);
  const std::size_t broken = out.failures.size();
  EXPECT_GE(broken, 2u) << failures;
  EXPECT_NE(failures.find("heart_00018.png differs"), std::string::npos) << failures;
  const auto diff = dir_ / "actual" / "heart" / "frame_00009.diff.png";
  EXPECT_NE(failures.find("heart_00009.png differs (max delta"), std::string::npos) << failures;
  EXPECT_NE(failures.find("diff (actual | reference | amplified difference): " + diff.string()), std::string::npos)
      << failures;
  EXPECT_EQ(encode::read_png(diff).width, 3 * 320);
  EXPECT_EQ(failures.find("heart_00000.png"), std::string::npos) << failures;

  // The update rewrites those only (frame 0 stays), and then they pass.
  out = check(true, stronger);
  EXPECT_TRUE(out.failures.empty()) << joined(out.failures);
  const std::string changes = joined(out.changes);
  EXPECT_EQ(out.changes.size(), broken) << changes;
  EXPECT_EQ(changes.find("heart_00000.png"), std::string::npos) << changes;
  EXPECT_NE(changes.find("updated " + (dir_ / "golden" / out.renderer.key / "heart_00009.png").string() +
                         " (was: differs (max delta"),
            std::string::npos)
      << changes;
  out = check(false, stronger);
  EXPECT_TRUE(out.failures.empty()) << joined(out.failures);
}

}  // namespace
}  // namespace systole::test

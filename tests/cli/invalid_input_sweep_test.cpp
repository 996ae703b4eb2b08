// ctest-labels: slow-under-sanitizers
// Every numeric key of the schema set to NaN, infinities, huge, tiny, negative and zero
// values through -D: refused with the file (or the -D) and the key, stopped by the health
// check with a diagnosis, or simulated to finite positions. Hundreds of scenes built and
// stepped: minutes under the sanitizers.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

#include "clip/limits.h"
#include "common/error.h"
#include "scene/load.h"
#include "scene/schema.h"
#include "world/world.h"

namespace systole::test {
namespace {

// --- Every numeric key ------------------------------------------------------------------------

/// A scene in which every list of the schema has an item, so every key has a -D path.
const char* kEveryList = R"(organs:
  - name: heart
    mesh: {procedural: heart, detail: 1}
    regions:
      - name: left_ventricle
        select: [{part: left_ventricle}]
        drive: {waveform: fourier, rate: 1 Hz, harmonics: [{amplitude: 0.3}]}
    body: {volume_drive: {waveform: fourier, rate: 1 Hz, harmonics: [{amplitude: 0.3}]}}
interactions:
  - poke: {organ: heart, at: [0, 0, 0.03], force: [0, 0, -0.1], drive: {waveform: fourier, rate: 1 Hz, harmonics: [{amplitude: 0.3}]}}
  - grab: {organ: heart, at: [0, 0, -0.03], path: [{time: 0 s, position: [0, 0, -0.03]}]}
lights: [{direction: [0, 0, -1]}]
camera: {orbit: {speed: 10 deg/s}}
views:
  - camera: {path: [{time: 0 s, position: [0, 0, 0.3], target: [0, 0, 0]}]}
    clip: {point: [0, 0, 0], normal: [0, 0, -1]}
output: {width: 64, height: 64, duration: 0.1 s}
)";

/// -D paths of every key whose value is a number or a list of numbers.
void numeric_paths(const scene::KeySpec& spec, const std::string& prefix, const std::string& doc_prefix,
                   std::vector<std::pair<std::string, const scene::KeySpec*>>& out) {
  for (const scene::KeySpec& key : spec.keys) {
    std::string path = prefix.empty() ? key.name : prefix + "." + key.name;
    const std::string doc = doc_prefix.empty() ? key.name : doc_prefix + "." + key.name;
    if (key.type.starts_with("list of") && !key.keys.empty()) {
      // interactions[1] is the grab; every other list's first item has the key.
      numeric_paths(key, path + (doc == "interactions" ? ".%" : ".0"), doc + "[]", out);
    } else if (!key.keys.empty()) {
      numeric_paths(key, path, doc, out);
    } else if (key.type != "name" && key.type != "part name" && key.type != "path" && key.type != "boolean" &&
               key.type != "one of" && key.type != "colour" && key.type != "text") {
      out.emplace_back(path, &key);
    }
  }
}

/// organs.0.body.mass -> organs[0].body.mass, as messages name keys.
std::string doc_path(const std::string& define_path) {
  std::string doc;
  std::size_t at = 0;
  while (at <= define_path.size()) {
    const std::size_t dot = std::min(define_path.find('.', at), define_path.size());
    const std::string piece = define_path.substr(at, dot - at);
    const bool index = !piece.empty() && std::all_of(piece.begin(), piece.end(), ::isdigit);
    doc += index ? "[" + piece + "]" : (doc.empty() ? "" : ".") + piece;
    at = dot + 1;
  }
  return doc;
}

/// A message names the key when it gives its full path (or is about the -D that set it), or
/// its path within the list item whose line it gives ("every.yaml:2:5: organ 'heart': ...
/// body.volume_stiffness"). One check relates two keys and names the other: an organ moved
/// or shrunk away from an interaction names the interaction's `at` and `radius`; and blood
/// in an organ with no ventricles names the `blood` block, whichever of its keys is set.
bool names_the_key(const std::string& message, const std::string& define, const std::string& key) {
  if (message.starts_with("-D " + define + ": ") || message.find(key) != std::string::npos) return true;
  const auto item_end = key.rfind("].");
  if (item_end != std::string::npos && message.find(key.substr(item_end + 2)) != std::string::npos) return true;
  if (key.starts_with("organs[0].blood.") && message.find("organs[0].blood: ") != std::string::npos) return true;
  return key.starts_with("organs[0].transform.") && message.find("interactions[0].poke.at") != std::string::npos;
}

TEST(InvalidInput, EveryNumericKeyRefusesNanInfinityAndNonsenseOrCopesWithIt) {
  std::vector<std::pair<std::string, const scene::KeySpec*>> keys;
  numeric_paths(scene::scene_schema(), "", "", keys);
  ASSERT_GT(keys.size(), 50u);
  for (auto& [path, spec] : keys) {
    if (const auto at = path.find('%'); at != std::string::npos) path.replace(at, 1, path.find(".grab") != std::string::npos ? "1" : "0");
    const bool vector = spec->type.starts_with("3 ") || spec->type.starts_with("list");
    const bool pair = spec->type.starts_with("2 ");
    for (const std::string value : {".nan", ".inf", "-.inf", "1e300", "-1e300", "-1", "0", "1e-300"}) {
      const std::string written = vector ? "[" + value + ", " + value + ", " + value + "]"
                                  : pair ? "[" + value + ", " + value + "]"
                                         : value;
      const std::string define = path + "=" + written;
      SCOPED_TRACE(define);
      try {
        const scene::Scene scene = scene::load_from_string(kEveryList, "every.yaml", {define});
        const bool non_finite = value.find("nan") != std::string::npos || value.find("inf") != std::string::npos;
        EXPECT_FALSE(non_finite) << "a non-finite value was accepted";
        clip::check_scene_limits(scene, {scene.output.frame_count(), true, false}, clip::Limits{});
        world::World world = world::build_world(scene);
        clip::check_world_limits(scene, world, clip::Limits{});
        world::advance_to_frame(world, scene.output.frame_count());
        // Accepted: what would be rendered is finite (the health check stops a run otherwise).
        for (const auto& organ : world.organs) {
          Eigen::Matrix3Xd rendered;
          world::render_positions(organ, rendered);
          EXPECT_TRUE(rendered.allFinite()) << "a non-finite mesh would be rendered";
        }
      } catch (const Error& e) {
        // Refused with the file (or the -D) and the key, or stopped by the health check with
        // the frame, the cause and a remedy.
        const std::string message = e.what();
        if (e.code() == ExitCode::kDiverged) {
          EXPECT_NE(message.find("simulation diverged at frame "), std::string::npos) << message;
          EXPECT_NE(message.find("Remedy: "), std::string::npos) << message;
        } else {
          EXPECT_EQ(e.code(), ExitCode::kDataError) << message;
          EXPECT_TRUE(message.starts_with("-D " + define + ": ") || message.starts_with("every.yaml")) << message;
          EXPECT_TRUE(names_the_key(message, define, doc_path(path))) << "the message names " << doc_path(path) << ": " << message;
        }
      }
    }
  }
}

}  // namespace
}  // namespace systole::test

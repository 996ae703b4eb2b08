// Output formats, slow motion, loops, title cards and captions in the scene
// (docs/teaching-visuals.md): what they resolve to, and errors that say why.

#include <gtest/gtest.h>

#include <cmath>

#include "scene_test_util.h"

namespace systole::scene {
namespace {

using testing::load_error;

/// A heart at 72 bpm (0.8333 s a beat) with one more rhythm; `output` and `extra` are YAML.
std::string heart(const std::string& output, const std::string& extra = "", const std::string& second_rate = "72 bpm") {
  return "organs:\n  - name: heart\n    mesh: {procedural: heart}\n    regions:\n"
         "      - {name: left_ventricle, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}}\n"
         "      - {name: left_atrium, drive: {waveform: cardiac, rate: " + second_rate + ", amplitude: 0.1}}\n"
         "output: " + output + "\n" + extra;
}

Scene load(const std::string& yaml) { return load_from_string(yaml, "scenes/test.yaml", {}); }

TEST(SceneFormat, ComesFromTheFileExtensionOrTheKeyElseMp4) {
  EXPECT_EQ(load(heart("{duration: 1 s}")).output.format, Format::kMp4);
  EXPECT_EQ(load(heart("{file: out/a.gif, fps: 25, duration: 1 s}")).output.format, Format::kGif);
  EXPECT_EQ(load(heart("{file: out/a.WEBM, duration: 1 s}")).output.format, Format::kWebm);
  EXPECT_EQ(load(heart("{format: mkv, duration: 1 s}")).output.format, Format::kMkv);
  EXPECT_EQ(load(heart("{file: out/a.bin, format: mkv, duration: 1 s}")).output.format, Format::kMkv);
}

TEST(SceneFormat, ContradictionsAndFastGifsAreErrors) {
  auto f = load_error(heart("{file: out/a.gif, format: webm, duration: 1 s}"));
  EXPECT_NE(f.message.find("output.format: 'webm' contradicts the file 'out/a.gif' (its extension names gif)"), std::string::npos)
      << f.message;
  f = load_error(heart("{format: gif, fps: 60, duration: 1 s}"));
  EXPECT_NE(f.message.find("output.fps: 60 is outside (0, 50] for a GIF"), std::string::npos) << f.message;
  EXPECT_EQ(f.message.rfind("scenes/test.yaml:7:", 0), 0u) << f.message;
}

TEST(SceneTiming, SlowMotionStretchesTheVideoNotTheSimulation) {
  const Scene s = load(heart("{fps: 30, duration: 2 s, slow_motion: 4}"));
  EXPECT_EQ(s.output.frame_count(), 240);  // 2 s of organ time over 8 s of video.
  EXPECT_DOUBLE_EQ(s.output.frame_period_s(), 1.0 / 120);
  EXPECT_NE(load_error(heart("{slow_motion: 0}")).message.find("output.slow_motion: 0 is outside [0.1, 100]"), std::string::npos);
}

TEST(SceneTiming, LoopSnapsToWholeBeatsAndSettlesInWholeLoops) {
  const Scene s = load(heart("{fps: 30, duration: 2 s, loop: true, settle_cycles: 2}"));
  // 2 s is 2.4 beats of 0.8333 s: two beats, 50 frames of exactly 1/30 s.
  EXPECT_NEAR(s.output.duration_s, 2 / 1.2, 1e-12);
  EXPECT_EQ(s.output.frame_count(), 50);
  EXPECT_NEAR(s.output.frame_period_s(), 1.0 / 30, 1e-12);
  EXPECT_EQ(s.output.start_frame, 50);  // Two beats of settling: one whole loop.
  // A rhythm at 1.5x the slowest needs two slow cycles to close.
  const Scene t = load(heart("{fps: 30, duration: 1 s, loop: true}", "", "108 bpm"));
  EXPECT_NEAR(t.output.duration_s, 2 / 1.2, 1e-12);
  // A rate that is no whole-number ratio has no common cycle.
  EXPECT_NE(load_error(heart("{loop: true}", "", "77.7 bpm")).message.find("output.loop: the drives have no common cycle"),
            std::string::npos);
}

TEST(SceneTiming, LoopNeedsSteadyRhythms) {
  auto f = load_error(heart("{loop: true}", "", "72 bpm, irregularity: 0.2"));
  EXPECT_NE(f.message.find("organs[0].regions[1].drive.irregularity: an irregular rhythm never repeats"), std::string::npos) << f.message;
  f = load_error("organs:\n  - name: liver\n    mesh: {procedural: heart}\noutput: {loop: true}\n");
  EXPECT_NE(f.message.find("output.loop: no region is driven"), std::string::npos) << f.message;
  f = load_error("organs:\n  - name: heart\n    mesh: {procedural: heart}\n    regions:\n"
                 "      - {name: left_ventricle, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}}\n"
                 "      - {name: aorta, pinned: true, motion: [{time: 0 s, position: [0, 0, 0]}, {time: 1 s, position: [0, 0.01, 0]}]}\n"
                 "output: {loop: true}\n");
  EXPECT_NE(f.message.find("organs[0].regions[1].motion: a prescribed motion is held after its last key"), std::string::npos) << f.message;
  f = load_error(heart("{loop: true}", "interactions:\n  - poke: {organ: heart, at: [0, 0, 0.03], force: [0, 0, -1]}\n"));
  EXPECT_NE(f.message.find("interactions[0]: happens once"), std::string::npos) << f.message;
}

TEST(SceneCards, CardsAndCaptionsAreRead) {
  const Scene s = load(heart("{duration: 2 s}",
                             "cards:\n  - {text: \"The heart\\nsinus rhythm\", duration: 2 s, fade: 0.4 s}\n"
                             "captions:\n  - {text: Systole, from: 0.5 s, to: 1.5 s}\n"));
  ASSERT_EQ(s.cards.size(), 1u);
  EXPECT_EQ(s.cards[0].text, "The heart\nsinus rhythm");
  EXPECT_DOUBLE_EQ(s.cards[0].fade_s, 0.4);
  ASSERT_EQ(s.captions.size(), 1u);
  EXPECT_DOUBLE_EQ(s.captions[0].from_s, 0.5);
  EXPECT_DOUBLE_EQ(s.captions[0].to_s, 1.5);
  EXPECT_DOUBLE_EQ(s.captions[0].fade_s, 0.3);
}

TEST(SceneCards, BadTimesSayWhy) {
  auto f = load_error(heart("{duration: 2 s}", "captions:\n  - {text: Systole, from: 1.5 s, to: 0.5 s}\n"));
  EXPECT_NE(f.message.find("scenes/test.yaml:9:"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("captions[0].to: 0.5 s must be after from (1.5 s)"), std::string::npos) << f.message;
  f = load_error(heart("{duration: 2 s}", "captions:\n  - {text: Systole, from: 0 s, to: 0.5 s, fade: 0.3 s}\n"));
  EXPECT_NE(f.message.find("captions[0].fade: twice the fade (0.3 s) must fit"), std::string::npos) << f.message;
  f = load_error(heart("{duration: 2 s}", "cards:\n  - {text: Title, duration: 1 s, fade: 0.6 s}\n"));
  EXPECT_NE(f.message.find("cards[0].fade: twice the fade"), std::string::npos) << f.message;
  f = load_error(heart("{duration: 2 s}", "captions:\n  - {from: 0 s, to: 1 s}\n"));
  EXPECT_NE(f.message.find("missing required key 'text'"), std::string::npos) << f.message;
}

}  // namespace
}  // namespace systole::scene

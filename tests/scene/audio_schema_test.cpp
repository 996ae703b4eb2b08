// The audio, chapters and burn_captions keys: defaults, the ventricles found by name, and
// every mistake named with file:line:key.

#include <gtest/gtest.h>

#include "scene/load.h"
#include "scene_test_util.h"

namespace systole::scene {
namespace {

using testing::load_error;

const std::string kOrgans =
    "organs:\n"
    "  - name: heart\n"
    "    mesh: {procedural: heart}\n"
    "    regions:\n"
    "      - {name: left_ventricle, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}}\n"
    "      - {name: right_ventricle, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}}\n"
    "      - {name: aorta, pinned: true}\n";

TEST(AudioSchema, OffByDefaultAndReadWithItsDefaults) {
  const Scene plain = load_from_string(kOrgans, "scenes/test.yaml");
  EXPECT_FALSE(plain.audio.enabled);
  EXPECT_TRUE(plain.output.burn_captions);
  const Scene s = load_from_string(kOrgans +
                                       "audio:\n"
                                       "  level: -6 dB\n"
                                       "  heart: {stethoscope: base, s3: {}, murmur: {shape: plateau, from: 0.05, to: 0.95}}\n"
                                       "  click: {rate: 60 bpm}\n"
                                       "output: {burn_captions: false}\n"
                                       "chapters:\n  - {title: Start, at: 0 s}\n  - {title: Later, at: 2 s}\n",
                                   "scenes/test.yaml");
  ASSERT_TRUE(s.audio.enabled);
  EXPECT_DOUBLE_EQ(s.audio.level_db, -6);
  EXPECT_EQ(s.audio.heart.organ, "heart");
  EXPECT_EQ(s.audio.heart.regions, (std::vector<std::string>{"left_ventricle", "right_ventricle"}));
  EXPECT_EQ(s.audio.heart.stethoscope, Stethoscope::kBase);
  EXPECT_TRUE(s.audio.heart.s1.enabled);
  EXPECT_TRUE(s.audio.heart.s3.enabled);
  EXPECT_DOUBLE_EQ(s.audio.heart.s3.level_db, -6);
  EXPECT_TRUE(s.audio.heart.murmur.enabled);
  EXPECT_EQ(s.audio.heart.murmur.shape, MurmurShape::kPlateau);
  EXPECT_TRUE(s.audio.click.enabled);
  EXPECT_DOUBLE_EQ(s.audio.click.rate_hz, 1.0);
  EXPECT_FALSE(s.audio.breath.enabled);
  EXPECT_FALSE(s.output.burn_captions);
  ASSERT_EQ(s.chapters.size(), 2u);
  EXPECT_DOUBLE_EQ(s.chapters[1].at_s, 2.0);
}

TEST(AudioSchema, MistakesNameTheirPlaceAndKey) {
  const struct {
    std::string yaml, expected;
  } cases[] = {
      {"audio: {}\n", "scenes/test.yaml:8:8: audio: says nothing to play: give heart, breath or click"},
      {"audio: {heart: {stethoscop: apex}}\n", "scenes/test.yaml:8:17: audio.heart: unknown key 'stethoscop' (did you mean 'stethoscope'?)"},
      {"audio: {heart: {stethoscope: back}}\n", "audio.heart.stethoscope: expected one of apex, base"},
      {"audio: {heart: {s1: {level: 3}}}\n", "audio.heart.s1.level: expected a level with a unit, e.g. \"-6 dB\""},
      {"audio: {heart: {s1: {level: 30 dB}}}\n", "audio.heart.s1.level: 30 dB is outside [-60, 12]"},
      {"audio: {heart: {regions: [left_ventricel]}}\n",
       "scenes/test.yaml:8:27: audio.heart.regions[0]: organ 'heart' has no region named 'left_ventricel'"},
      {"audio: {heart: {regions: [aorta]}}\n", "audio.heart.regions[0]: region 'aorta' is pinned"},
      {"audio: {heart: {organ: lungs}}\n", "audio.heart.organ: no organ is named 'lungs'"},
      {"audio: {heart: {murmur: {from: 0.8, to: 0.2}}}\n", "audio.heart.murmur.to: 0.2 must be after from (0.8)"},
      {"audio: {heart: {murmur: {shape: triangle}}}\n", "audio.heart.murmur.shape: expected one of diamond, plateau"},
      {"audio: {breath: {}}\n", "audio.breath: no organ's body has a volume_drive"},
      {"audio: {click: {level: -3 dB}}\n", "audio.click: missing required key 'rate'"},
      {"audio: {click: {rate: 60}}\n", "audio.click.rate: expected a frequency with a unit"},
      {"chapters:\n  - {title: B, at: 2 s}\n  - {title: A, at: 1 s}\n", "scenes/test.yaml:10:"},
      {"chapters:\n  - {title: B, at: 2 s}\n  - {title: A, at: 1 s}\n", "chapters[1].at: 1 s must be after the chapter before (2 s)"},
      {"chapters:\n  - {titel: B, at: 2 s}\n", "unknown key 'titel' (did you mean 'title'?)"},
      {"output: {burn_captions: maybe}\n", "output.burn_captions: expected"},
  };
  for (const auto& c : cases) {
    const auto f = load_error(kOrgans + c.yaml);
    EXPECT_NE(f.message.find(c.expected), std::string::npos) << c.yaml << "\n -> " << f.message;
  }
  // Without a region named like a ventricle, the organ's regions must be named.
  const auto f = load_error("organs:\n  - name: blob\n    mesh: {procedural: heart}\n"
                            "    regions: [{name: wall, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}}]\n"
                            "audio: {heart: {}}\n");
  EXPECT_NE(f.message.find("audio.heart: no organ has a region named like a ventricle"), std::string::npos) << f.message;
}

}  // namespace
}  // namespace systole::scene

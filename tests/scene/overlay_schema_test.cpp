// The overlay keys: defaults, sizes and windows read in their units, and every mistake
// (unknown key, unknown organ or region, an undriven region traced, a region on a volume
// trace, a bad corner) named with file:line:key.

#include <gtest/gtest.h>

#include "scene/load.h"
#include "scene_test_util.h"

namespace systole::scene {
namespace {

using testing::load_error;

const std::string kOrgan =
    "organs:\n"
    "  - name: heart\n"
    "    mesh: {procedural: heart}\n"
    "    regions:\n"
    "      - {name: left_ventricle, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}}\n"
    "      - {name: aorta, pinned: true}\n";

TEST(OverlaySchema, ReadsEveryPartWithItsDefaults) {
  const Scene s = load_from_string(kOrgan +
                                       "overlay:\n"
                                       "  title: \"Sinus rhythm\"\n"
                                       "  labels: {regions: all}\n"
                                       "  legend: {}\n"
                                       "  traces:\n"
                                       "    - {signal: ecg, region: left_ventricle, window: 2500 ms}\n"
                                       "    - {signal: volume, position: top-right, window: clip}\n",
                                   "scenes/test.yaml");
  EXPECT_EQ(s.overlay.title, "Sinus rhythm");
  EXPECT_TRUE(s.overlay.labels.enabled);
  EXPECT_TRUE(s.overlay.labels.regions.empty());
  EXPECT_EQ(s.overlay.labels.size_px, 16);
  EXPECT_TRUE(s.overlay.legend.enabled);
  EXPECT_EQ(s.overlay.legend.position, Corner::kTopLeft);
  ASSERT_EQ(s.overlay.traces.size(), 2u);
  EXPECT_DOUBLE_EQ(s.overlay.traces[0].window_s, 2.5);
  EXPECT_EQ(s.overlay.traces[0].position, Corner::kBottomRight);
  EXPECT_EQ(s.overlay.traces[1].window_s, 0);
  EXPECT_EQ(s.overlay.traces[1].position, Corner::kTopRight);
  EXPECT_TRUE(load_from_string(kOrgan, "scenes/test.yaml").overlay.empty());
}

TEST(OverlaySchema, MistakesNameTheirPlaceAndKey) {
  const struct {
    std::string yaml, expected;
  } cases[] = {
      {"overlay: {labels: {regions: [left_ventricel]}}\n",
       "scenes/test.yaml:7:30: overlay.labels.regions[0]: no region is named 'left_ventricel'"},
      {"overlay: {labels: {view: Inside}}\n",
       "scenes/test.yaml:7:26: overlay.labels.view: no view is titled 'Inside' (the scene has no views)"},
      {"overlay: {labels: {regions: []}}\n",
       "overlay.labels.regions: expected 1..256 region names, got 0 (to show no labels, leave out overlay.labels)"},
      {"overlay: {labels: {regions: left_ventricle}}\n", "overlay.labels.regions: expected all or a list of region names"},
      {"views: [{title: Outside}, {title: Cut}]\noverlay: {labels: {view: Inside}}\n",
       "overlay.labels.view: no view is titled 'Inside' (views: 'Outside', 'Cut')"},
      {"overlay: {labels: {siz: 12}}\n", "scenes/test.yaml:7:20: overlay.labels: unknown key 'siz' (did you mean 'size'?)"},
      {"overlay: {labels: {size: 200}}\n", "scenes/test.yaml:7:26: overlay.labels.size: 200 is outside 6..96"},
      {"overlay: {legend: {organ: lungs}}\n", "scenes/test.yaml:7:27: overlay.legend.organ: no organ is named 'lungs'"},
      {"overlay: {legend: {position: middle}}\n", "overlay.legend.position: expected one of top-left, top-right"},
      {"overlay: {traces: [{signal: ecg}]}\n", "overlay.traces[0]: signal activation and ecg need a region"},
      {"overlay: {traces: [{signal: ecg, region: aorta}]}\n",
       "overlay.traces[0].region: region 'aorta' has no drive: nothing beats to trace"},
      {"overlay: {traces: [{signal: activation, region: apex}]}\n", "organ 'heart' has no region named 'apex'"},
      {"overlay: {traces: [{signal: volume, region: aorta}]}\n", "overlay.traces[0].region: signal volume is the whole organ's"},
      {"overlay: {traces: [{signal: volume, window: 3}]}\n", "overlay.traces[0].window"},
      {"overlay: {traces: [{signal: volume, window: 700 s}]}\n", "overlay.traces[0].window: 700 s is outside (0, 600] s"},
      {"overlay: {title: \"\"}\n", "overlay.title: expected text"},
      {"overlay: {traces: [{signal: ecg, region: left_ventricle, atria: aorta}]}\n",
       "overlay.traces[0].atria: region 'aorta' has no drive: it gives no P waves"},
      {"overlay: {traces: [{signal: activation, region: left_ventricle, atria: left_ventricle}]}\n",
       "overlay.traces[0].atria: atria applies to signal ecg only"},
  };
  for (const auto& c : cases) {
    const auto f = load_error(kOrgan + c.yaml);
    EXPECT_EQ(f.code, ExitCode::kDataError) << c.yaml;
    EXPECT_NE(f.message.find(c.expected), std::string::npos) << c.yaml << " gave: " << f.message;
  }
}

}  // namespace
}  // namespace systole::scene

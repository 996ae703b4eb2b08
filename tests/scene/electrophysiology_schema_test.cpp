// The `electrophysiology:` block: read with its block, and every contradiction of a
// conduction system named with file:line:key (a region's own delay, two rates, a mesh
// without a myocardium, a trace asking a synthetic ECG of it).

#include <gtest/gtest.h>

#include "scene/load.h"
#include "scene_test_util.h"

namespace systole::scene {
namespace {

using testing::load_error;

std::string heart(const std::string& electrophysiology, const std::string& ventricle_drive,
                  const std::string& procedural = "anatomical_heart") {
  return "organs:\n"
         "  - name: heart\n"
         "    mesh: {procedural: " + procedural + ", detail: 1}\n"
         "    electrophysiology: " + electrophysiology + "\n"
         "    regions:\n"
         "      - {name: left_atrium, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1}}\n"
         "      - {name: left_ventricle, drive: " + ventricle_drive + "}\n";
}

const std::string kDrive = "{waveform: cardiac, rate: 72 bpm, amplitude: 0.2}";

TEST(ElectrophysiologySchema, ReadsTheBlockAndItsBranchBlock) {
  const Scene normal = load_from_string(heart("{}", kDrive), "scenes/test.yaml");
  EXPECT_TRUE(normal.organs[0].electrophysiology.enabled);
  EXPECT_EQ(normal.organs[0].electrophysiology.block, BundleBranchBlock::kNone);
  const Scene left = load_from_string(heart("{block: left_bundle_branch}", kDrive), "scenes/test.yaml");
  EXPECT_EQ(left.organs[0].electrophysiology.block, BundleBranchBlock::kLeft);
  const Scene none = load_from_string(testing::kMinimalOrgans, "scenes/test.yaml");
  EXPECT_FALSE(none.organs[0].electrophysiology.enabled);
}

TEST(ElectrophysiologySchema, ContradictionsNameTheirPlaceAndKey) {
  const auto delay = load_error(heart("{}", "{waveform: cardiac, rate: 72 bpm, amplitude: 0.2, delay: 160 ms}"));
  EXPECT_EQ(delay.code, ExitCode::kDataError);
  EXPECT_NE(delay.message.find("scenes/test.yaml:7:"), std::string::npos) << delay.message;
  EXPECT_NE(delay.message.find("organs[0].regions[1].drive.delay"), std::string::npos) << delay.message;
  EXPECT_NE(delay.message.find("remove the region's delay"), std::string::npos) << delay.message;

  const auto rate = load_error(heart("{}", "{waveform: cardiac, rate: 80 bpm, amplitude: 0.2}"));
  EXPECT_NE(rate.message.find("organs[0].regions[1].drive.rate"), std::string::npos) << rate.message;
  EXPECT_NE(rate.message.find("sinus rate"), std::string::npos) << rate.message;

  const auto mesh = load_error(heart("{}", kDrive, "heart"));
  EXPECT_NE(mesh.message.find("organs[0].electrophysiology"), std::string::npos) << mesh.message;
  EXPECT_NE(mesh.message.find("anatomical_heart"), std::string::npos) << mesh.message;

  const auto typo = load_error(heart("{blok: left_bundle_branch}", kDrive));
  EXPECT_NE(typo.message.find("blok"), std::string::npos) << typo.message;
  const auto value = load_error(heart("{block: left}", kDrive));
  EXPECT_NE(value.message.find("left_bundle_branch"), std::string::npos) << value.message;
}

TEST(ElectrophysiologySchema, AnEcgTraceShowsALeadOfTheComputedEcg) {
  const std::string base = heart("{}", kDrive) + "overlay:\n  traces:\n";
  const Scene s = load_from_string(base + "    - {signal: ecg, lead: V5}\n", "scenes/test.yaml");
  EXPECT_EQ(s.overlay.traces[0].lead, "V5");
  EXPECT_EQ(load_from_string(base + "    - {signal: ecg}\n", "scenes/test.yaml").overlay.traces[0].lead, "II");
  const auto region = load_error(base + "    - {signal: ecg, region: left_ventricle}\n");
  EXPECT_NE(region.message.find("give a `lead`"), std::string::npos) << region.message;
  const auto lead = load_error(base + "    - {signal: ecg, lead: V7}\n");
  EXPECT_NE(lead.message.find("V6"), std::string::npos) << lead.message;
  const auto synthetic = load_error(std::string(testing::kMinimalOrgans) +
                                    "    regions:\n      - {name: left_ventricle, drive: " + kDrive +
                                    "}\noverlay:\n  traces:\n    - {signal: ecg, region: left_ventricle, lead: II}\n");
  EXPECT_NE(synthetic.message.find("no electrophysiology"), std::string::npos) << synthetic.message;
  const auto volume = load_error(base + "    - {signal: volume, lead: II}\n");
  EXPECT_NE(volume.message.find("lead applies to signal ecg only"), std::string::npos) << volume.message;
}

}  // namespace
}  // namespace systole::scene

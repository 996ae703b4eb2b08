// The computed ECG beside the video: a clip of a heart with a conduction system leaves its
// twelve leads as CSV and EDF+ and a 12-lead sheet as a PNG, each read back; a heart
// without one leaves none.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "clip/ecg_outputs.h"
#include "clip/render_clip.h"
#include "electro/ecg_files.h"
#include "encode/png.h"
#include "scene/load.h"
#include "support/run.h"

namespace systole::test {
namespace {

namespace fs = std::filesystem;

std::string heart_scene(bool electrophysiology) {
  return std::string(
             "organs:\n"
             "  - name: heart\n"
             "    mesh: {procedural: anatomical_heart, detail: 1}\n") +
         (electrophysiology ? "    electrophysiology: {}\n" : "") +
         "    regions:\n"
         "      - {name: left_atrium, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.1, systolic_fraction: 0.15}}\n"
         "      - {name: left_ventricle, drive: {waveform: cardiac, rate: 72 bpm, amplitude: 0.2}}\n"
         "      - {name: aorta, pinned: true}\n"
         "solver: {method: projective, dt: 1/120 s, iterations: 1}\n"
         "camera: {position: [0, 0, 0.34], target: [0, 0, 0], fov: 40 deg}\n"
         "output: {width: 160, height: 90, fps: 10, duration: 1.2 s}\n";
}

TEST(EcgOutputs, AnExcitedHeartsClipLeavesItsEcgBesideTheVideo) {
  const fs::path dir = scratch("ecg_outputs");
  clip::RenderRequest request;
  request.video = dir / "heart.mp4";
  clip::render_clip(scene::load_from_string(heart_scene(true), "heart.yaml"), request);
  const clip::EcgFiles files = clip::ecg_files_beside(request.video, "heart", false);
  EXPECT_EQ(files.csv, dir / "heart.ecg.csv");
  const electro::Ecg edf = electro::read_ecg_edf(files.edf);
  ASSERT_EQ(edf.leads.size(), 12u);
  EXPECT_EQ(edf.samples(), 600u);  // 1.2 s at 500 Hz.
  double peak = 0;
  for (double v : *edf.lead("II")) peak = std::max(peak, std::abs(v));
  EXPECT_GT(peak, 0.05);
  // The CSV holds the same leads: its header and one row per sample.
  std::ifstream csv(files.csv);
  std::string header, row;
  std::getline(csv, header);
  EXPECT_EQ(header, "time_s,I,II,III,aVR,aVL,aVF,V1,V2,V3,V4,V5,V6");
  int rows = 0;
  while (std::getline(csv, row)) ++rows;
  EXPECT_EQ(rows, 600);
  const Image sheet = encode::read_png(files.sheet);
  EXPECT_EQ(sheet.width, 1340);
  EXPECT_GT(sheet.height, 600);
}

TEST(EcgOutputs, AHeartWithoutAConductionSystemLeavesNone) {
  const fs::path dir = scratch("ecg_outputs_none");
  clip::RenderRequest request;
  request.video = dir / "heart.mp4";
  clip::render_clip(scene::load_from_string(heart_scene(false), "heart.yaml"), request);
  EXPECT_TRUE(fs::exists(request.video));
  EXPECT_FALSE(fs::exists(dir / "heart.edf"));
  EXPECT_FALSE(fs::exists(dir / "heart.ecg.csv"));
}

}  // namespace
}  // namespace systole::test

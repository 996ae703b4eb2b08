// Every field of the physics value types (physics/drive.h, physics/world.h) a scene writes
// arrives in the built model: YAML -> scene::load -> sim/from_scene -> sim::build_model.
// Each field is set to its own non-default value, and each check names every field with a
// structured binding, so a field added to one of these types stops this test compiling
// until it is walked here too.

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>

#include "mesh/organ.h"
#include "scene/load.h"
#include "sim/from_scene.h"
#include "sim/model.h"

namespace systole::sim {
namespace {

const std::map<physics::Waveform, std::string> kWaveformNames = {
    {physics::Waveform::kNone, "none"},       {physics::Waveform::kSine, "sine"},
    {physics::Waveform::kFourier, "fourier"}, {physics::Waveform::kCardiac, "cardiac"},
    {physics::Waveform::kBreathing, "breathing"}, {physics::Waveform::kSamples, "samples"},
};

/// A drive with every field away from its default; `k` makes the drives of one scene differ
/// from each other, so a drive arriving in another's place fails too. Every value is a
/// dyadic fraction, exact in binary, so the YAML round trip is exact.
physics::Drive distinctive_drive(physics::Waveform waveform, int k) {
  physics::Drive d;
  d.waveform = waveform;
  d.rate_hz = 1.25 + 0.25 * k;
  d.rate_end_hz = 1.5 + 0.25 * k;
  d.amplitude = 0.125 + 0.0625 * k;
  d.phase_rad = 0.375 + 0.125 * k;
  d.delay_s = 0.0625 + 0.03125 * k;
  d.harmonics = {{0.25, 0.5 + k}, {0.125 + 0.0625 * k, -0.75}};
  d.systolic_fraction = 0.3125 + 0.0625 * k;
  d.peak_fraction = 0.625 + 0.0625 * k;
  d.inhale_fraction = 0.4375 + 0.0625 * k;
  d.samples = {0, 0.5 + 0.125 * k, 1, 0.25};
  d.irregularity = 0.0625 + 0.03125 * k;
  return d;
}

/// The drive as a YAML flow map, in SI units spelt out (the loader converts them).
std::string yaml(const physics::Drive& d) {
  std::ostringstream y;
  y.precision(17);
  y << "{waveform: " << kWaveformNames.at(d.waveform) << ", rate: " << d.rate_hz << " Hz, rate_end: " << d.rate_end_hz
    << " Hz, amplitude: " << d.amplitude << ", phase: " << d.phase_rad << " rad, delay: " << d.delay_s
    << " s, systolic_fraction: " << d.systolic_fraction << ", peak_fraction: " << d.peak_fraction
    << ", inhale_fraction: " << d.inhale_fraction << ", irregularity: " << d.irregularity << ", harmonics: [";
  for (std::size_t i = 0; i < d.harmonics.size(); ++i)
    y << (i ? ", " : "") << "{amplitude: " << d.harmonics[i].amplitude << ", phase: " << d.harmonics[i].phase_rad
      << " rad}";
  y << "], samples: [";
  for (std::size_t i = 0; i < d.samples.size(); ++i) y << (i ? ", " : "") << d.samples[i];
  y << "]}";
  return y.str();
}

void expect_harmonics(const std::vector<physics::Harmonic>& got, const std::vector<physics::Harmonic>& want,
                      const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const auto& [amplitude, phase_rad] = got[i];
    EXPECT_EQ(amplitude, want[i].amplitude) << what << ".harmonics[" << i << "]";
    EXPECT_EQ(phase_rad, want[i].phase_rad) << what << ".harmonics[" << i << "]";
  }
}

void expect_drive(const physics::Drive& got, const physics::Drive& want, const std::string& what) {
  const auto& [waveform, rate_hz, rate_end_hz, amplitude, phase_rad, delay_s, harmonics, systolic_fraction,
               peak_fraction, inhale_fraction, samples, irregularity] = got;
  EXPECT_EQ(waveform, want.waveform) << what;
  EXPECT_EQ(rate_hz, want.rate_hz) << what;
  EXPECT_EQ(rate_end_hz, want.rate_end_hz) << what;
  EXPECT_EQ(amplitude, want.amplitude) << what;
  EXPECT_EQ(phase_rad, want.phase_rad) << what;
  EXPECT_EQ(delay_s, want.delay_s) << what;
  expect_harmonics(harmonics, want.harmonics, what);
  EXPECT_EQ(systolic_fraction, want.systolic_fraction) << what;
  EXPECT_EQ(peak_fraction, want.peak_fraction) << what;
  EXPECT_EQ(inhale_fraction, want.inhale_fraction) << what;
  EXPECT_EQ(samples, want.samples) << what;
  EXPECT_EQ(irregularity, want.irregularity) << what;
}

/// The test's own values differ from the defaults in every field, or a dropped field
/// (left at its default) could still pass.
void expect_not_default(const physics::Drive& d, const std::string& what) {
  const physics::Drive none;
  const auto& [waveform, rate_hz, rate_end_hz, amplitude, phase_rad, delay_s, harmonics, systolic_fraction,
               peak_fraction, inhale_fraction, samples, irregularity] = d;
  EXPECT_NE(waveform, none.waveform) << what;
  EXPECT_NE(rate_hz, none.rate_hz) << what;
  EXPECT_NE(rate_end_hz, none.rate_end_hz) << what;
  EXPECT_NE(amplitude, none.amplitude) << what;
  EXPECT_NE(phase_rad, none.phase_rad) << what;
  EXPECT_NE(delay_s, none.delay_s) << what;
  EXPECT_FALSE(harmonics.empty()) << what;
  for (const auto& [h_amplitude, h_phase_rad] : harmonics) {
    EXPECT_NE(h_amplitude, physics::Harmonic{}.amplitude) << what;
    EXPECT_NE(h_phase_rad, physics::Harmonic{}.phase_rad) << what;
  }
  EXPECT_NE(systolic_fraction, none.systolic_fraction) << what;
  EXPECT_NE(peak_fraction, none.peak_fraction) << what;
  EXPECT_NE(inhale_fraction, none.inhale_fraction) << what;
  EXPECT_FALSE(samples.empty()) << what;
  EXPECT_NE(irregularity, none.irregularity) << what;
}

void expect_path(const std::vector<physics::PathKey>& got, const std::vector<physics::PathKey>& want,
                 const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const auto& [time_s, position_m] = got[i];
    EXPECT_EQ(time_s, want[i].time_s) << what << "[" << i << "]";
    EXPECT_EQ(position_m, want[i].position_m) << what << "[" << i << "]";
  }
}

TEST(FromScene, EveryFieldOfTheSharedPhysicsTypesReachesTheModel) {
  const physics::Drive region_drive = distinctive_drive(physics::Waveform::kFourier, 0);
  const physics::Drive volume_drive = distinctive_drive(physics::Waveform::kBreathing, 1);
  const physics::Drive poke_drive = distinctive_drive(physics::Waveform::kSamples, 2);
  expect_not_default(region_drive, "region drive");
  expect_not_default(volume_drive, "volume drive");
  expect_not_default(poke_drive, "poke drive");
  const std::vector<physics::PathKey> motion = {{0.25, {0.0, 0.0, 0.0}}, {0.75, {0.001953125, -0.00390625, 0.0078125}}};
  const std::vector<physics::PathKey> grab_path = {{0.5, {0.0, 0.0, 0.03125}}, {1.5, {0.015625, 0.0, 0.046875}}};

  const std::string yaml_text =
      "organs:\n"
      "  - name: ball\n"
      "    mesh: {procedural: heart, detail: 1}\n"
      "    body: {volume_drive: " + yaml(volume_drive) + "}\n"
      "    regions:\n"
      "      - {name: left_ventricle, drive: " + yaml(region_drive) + "}\n"
      "      - name: aorta\n"
      "        pinned: true\n"
      "        motion: [{time: 0.25 s, position: [0, 0, 0]},"
      " {time: 0.75 s, position: [0.001953125, -0.00390625, 0.0078125]}]\n"
      "interactions:\n"
      "  - {poke: {organ: ball, at: [0, 0, 0.03], radius: 20 cm, force: [0, 0, -1], drive: " + yaml(poke_drive) + "}}\n"
      "  - grab:\n"
      "      organ: ball\n"
      "      at: [0, 0, 0.03]\n"
      "      radius: 20 cm\n"
      "      path: [{time: 0.5 s, position: [0, 0, 0.03125]}, {time: 1.5 s, position: [0.015625, 0, 0.046875]}]\n"
      "floor: {point: [0.125, -0.25, -0.5], normal: [0, 0, 1]}\n"
      "solver: {method: xpbd, dt: 1/120 s}\n"
      "output: {fps: 30, duration: 2 s}\n";
  const scene::Scene s = scene::load_from_string(yaml_text, "every_field.yaml");

  const OrganParams organ = organ_params(s.organs[0]);
  const ModelOptions options = model_options(s, "ball", 1.0 / 120);
  const Model model = build_model(organ, mesh::build_organ_geometry(s.organs[0]), options);

  ASSERT_EQ(model.regions.size(), 2u);
  expect_drive(model.regions[0].drive, region_drive, "regions[0].drive");
  expect_path(model.regions[1].motion, motion, "regions[1].motion");
  ASSERT_EQ(model.kinematic.size(), 1u);
  expect_path(model.kinematic[0].motion, motion, "kinematic[0].motion");
  ASSERT_TRUE(model.volume.enabled);
  expect_drive(model.volume.drive, volume_drive, "volume.drive");

  ASSERT_EQ(options.interactions.size(), 2u);
  EXPECT_EQ(options.interactions[0].kind, physics::InteractionKind::kPoke);
  EXPECT_EQ(options.interactions[1].kind, physics::InteractionKind::kGrab);
  ASSERT_EQ(model.pokes.size(), 1u) << "the poke is built as a poke";
  expect_drive(model.pokes[0].drive, poke_drive, "pokes[0].drive");
  ASSERT_EQ(model.grabs.size(), 1u) << "the grab is built as a grab";
  expect_path(model.grabs[0].path, grab_path, "grabs[0].path");

  const auto& [enabled, point_m, normal] = model.floor;
  EXPECT_TRUE(enabled);
  EXPECT_EQ(point_m, Eigen::Vector3d(0.125, -0.25, -0.5));
  EXPECT_EQ(normal, Eigen::Vector3d(0, 0, 1));
}

}  // namespace
}  // namespace systole::sim

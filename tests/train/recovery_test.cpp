// ctest-labels: slow-under-sanitizers
// Acceptance 1: a target made by Systole itself from known drive parameters is recovered
// by fitting and tuning from perturbed parameters, down to the error floor that the key
// frames' interpolation leaves.

#include <gtest/gtest.h>

#include <cmath>

#include "scene/load.h"
#include "sim/solvers/step.h"
#include "train/fourier.h"
#include "train/train_test_util.h"
#include "train/tune.h"
#include "world/world.h"

namespace systole::train {
namespace {

using namespace testing;

constexpr int kFrames = 40;

/// Key frames of the known drives: the ball run free for 2 cycles, then one cycle sampled.
std::string write_truth_frames(const std::filesystem::path& dir, const std::string& truth_yaml) {
  write_text(dir / "truth.yaml", truth_yaml);
  world::World world = world::build_world(scene::load(dir / "truth.yaml"));
  world::OrganBody& body = world.organs.front();
  const int steps_per_frame = static_cast<int>(std::lround(1.0 / (kFrames * world.dt_s)));
  const int settle = 2 * kFrames * steps_per_frame;
  for (int k = 0; k < settle; ++k) sim::step(body.model, body.state, world.dt_s);
  std::string frames = "      frames:\n";
  for (int f = 0; f < kFrames; ++f) {
    std::vector<Eigen::Vector3d> v;
    for (Eigen::Index i = 0; i < body.state.x.cols(); ++i) v.push_back(body.state.x.col(i));
    const std::string name = "truth_" + std::to_string(f) + ".obj";
    write_obj(dir / name, v, body.geometry.mesh.surface.triangles);
    frames += "        - {file: " + name + ", time: " + std::to_string(double(f) / kFrames) + " s}\n";
    for (int k = 0; k < steps_per_frame; ++k) sim::step(body.model, body.state, world.dt_s);
  }
  return frames;
}

double max_signal_difference(const scene::Drive& a, const scene::Drive& b) {
  const FourierSeries sa = series_from_drive(a), sb = series_from_drive(b);
  double worst = 0;
  for (int k = 0; k < 100; ++k) worst = std::max(worst, std::abs(sa(k / 100.0) - sb(k / 100.0)));
  return worst;
}

TEST(Recovery, TunedDrivesComeBackToTheKnownOnesAndTheErrorToTheFloor) {
  const auto dir = scratch("recovery");
  const mesh::TriangleMesh ball = icosphere(2);
  write_obj(dir / "ball.obj", ball.positions, ball.triangles);
  const std::string top = "{waveform: fourier, rate: 1 Hz, amplitude: 0.12, delay: 0.2 s, harmonics: [{amplitude: 0.5}]}";
  const std::string bottom = "{waveform: fourier, rate: 1 Hz, amplitude: 0.08, delay: 0.55 s, harmonics: [{amplitude: 0.5}]}";
  const std::string frames = write_truth_frames(dir, ball_scene(top, bottom, ""));

  const std::string target = "    target:\n      rate: 1 Hz\n      harmonics: 1\n      lock: [stiffness]\n      budget: 600\n" + frames;
  write_text(dir / "tune.yaml",
             ball_scene("{waveform: sine, rate: 1 Hz, amplitude: 0.07, delay: 0.35 s}",
                        "{waveform: sine, rate: 1 Hz, amplitude: 0.12, delay: 0.3 s}", target));
  const scene::Scene scene = scene::load(dir / "tune.yaml");
  TuneSettings settings;
  settings.threads = 2;
  const OrganTuning t = tune_organ(scene, 0, settings);

  // The floor: the known drives played against their own interpolated key frames.
  const scene::Scene truth = scene::load(dir / "truth.yaml");
  const Problem problem = make_problem(scene, 0);
  const PlaybackError floor = play(problem, with_regions(problem.model, truth.organs[0].regions));
  // Errors are shares of the target's motion: a body that never moves cannot score under
  // 100 % (no still shape is closer to a moving target than its mean shape).
  std::vector<scene::Region> still = truth.organs[0].regions;
  for (auto& r : still) r.drive.amplitude = 0;
  const PlaybackError still_error = play(problem, with_regions(problem.model, still));
  EXPECT_GE(still_error.rms_pct_of_motion, 100.0 - 1e-9);
  // A still body's error is its offset from the target's mean shape and the whole motion,
  // at right angles: RMS^2 = offset^2 + 100^2 (the split the report's offset column makes).
  EXPECT_NEAR(std::pow(still_error.rms_pct_of_motion, 2), std::pow(still_error.mean_offset_pct_of_motion, 2) + 1e4,
              1e-6 * std::pow(still_error.rms_pct_of_motion, 2));
  std::printf("written %.4f%%, fitted %.4f%%, tuned %.4f%%, floor %.4f%%, %d generations\n", t.written.rms_pct_of_motion,
              t.before.rms_pct_of_motion, t.after.rms_pct_of_motion, floor.rms_pct_of_motion, t.generations);
  for (int r = 0; r < 2; ++r) {
    const scene::Drive& d = t.regions[r].drive;
    std::printf("%s: A %.4f a1 %.4f delay %.4f; off by %.5f\n", t.regions[r].name.c_str(), d.amplitude, d.harmonics[0].amplitude,
                d.delay_s, max_signal_difference(d, truth.organs[0].regions[r].drive));
  }
  EXPECT_GT(t.written.rms_pct_of_motion, 5 * t.after.rms_pct_of_motion);
  // Near the floor: the target's key frames cannot follow the body's fast ripples between them.
  EXPECT_LT(t.after.rms_pct_of_motion, 2 * floor.rms_pct_of_motion + 0.5);
  for (int r = 0; r < 2; ++r) {
    // The contraction signal, not the raw numbers (amplitude and timing together): within
    // 0.01 of the known one over the whole cycle, where the known ones swing by 0.08 and 0.12.
    EXPECT_LT(max_signal_difference(t.regions[r].drive, truth.organs[0].regions[r].drive), 0.01) << t.regions[r].name;
  }
}

}  // namespace
}  // namespace systole::train

// ctest-labels: slow-under-sanitizers
// A reduced body (a lattice of other particles than the surface's vertices) is trained
// through its render surface: tied to the target by the surface's embedding, measured on
// the surface. Before, training tied particle i to target vertex i, read a lattice out of
// bounds (`systole tune` died of SIGSEGV) and then refused it.

#include <gtest/gtest.h>

#include <cmath>

#include "scene/load.h"
#include "sim/solvers/step.h"
#include "train/playback.h"
#include "train/train_test_util.h"
#include "train/tune.h"
#include "world/world.h"

namespace systole::train {
namespace {

using namespace testing;

constexpr int kFrames = 24;

/// Key frames of the lattice body's render surface under known drives, one cycle after two.
std::string write_truth_frames(const std::filesystem::path& dir, const std::string& truth_yaml) {
  write_text(dir / "truth.yaml", truth_yaml);
  world::World world = world::build_world(scene::load(dir / "truth.yaml"));
  world::OrganBody& body = world.organs.front();
  EXPECT_GT(body.lattice, 0) << "the truth's body is a lattice";
  const int steps_per_frame = static_cast<int>(std::lround(1.0 / (kFrames * world.dt_s)));
  for (int k = 0; k < 2 * kFrames * steps_per_frame; ++k) sim::step(body.model, body.state, world.dt_s);
  std::string frames = "      frames:\n";
  Eigen::Matrix3Xd surface;
  for (int f = 0; f < kFrames; ++f) {
    world::render_positions(body, surface);
    std::vector<Eigen::Vector3d> v;
    for (Eigen::Index i = 0; i < surface.cols(); ++i) v.push_back(surface.col(i));
    const std::string name = "truth_" + std::to_string(f) + ".obj";
    write_obj(dir / name, v, body.geometry.mesh.surface.triangles);
    frames += "        - {file: " + name + ", time: " + std::to_string(double(f) / kFrames) + " s}\n";
    for (int k = 0; k < steps_per_frame; ++k) sim::step(body.model, body.state, world.dt_s);
  }
  return frames;
}

std::string lattice(std::string yaml) { return yaml.replace(yaml.find("drag: 4 1/s}"), 12, "drag: 4 1/s, lattice: 5}"); }

TEST(ReducedBody, ALatticeBodyIsTiedAndMeasuredThroughItsSurfaceAndTunedBackToKnownDrives) {
  const auto dir = scratch("reduced_body");
  const mesh::TriangleMesh ball = icosphere(3);
  write_obj(dir / "ball.obj", ball.positions, ball.triangles);
  const std::string frames = write_truth_frames(
      dir, lattice(ball_scene("{waveform: sine, rate: 1 Hz, amplitude: 0.12, delay: 0.2 s}",
                              "{waveform: sine, rate: 1 Hz, amplitude: 0.08, delay: 0.55 s}", "")));
  // Perturbed by 30 % and more in amplitude and 40 ms and more in delay; the waveform kept.
  const std::string target = "    target:\n      rate: 1 Hz\n      lock: [stiffness, shape]\n      budget: 320\n" + frames;
  write_text(dir / "tune.yaml", lattice(ball_scene("{waveform: sine, rate: 1 Hz, amplitude: 0.16, delay: 0.25 s}",
                                                   "{waveform: sine, rate: 1 Hz, amplitude: 0.05, delay: 0.5 s}", target)));
  const scene::Scene scene = scene::load(dir / "tune.yaml");
  const Problem problem = make_problem(scene, 0);
  EXPECT_LT(problem.model.particle_count(), static_cast<int>(ball.positions.size())) << "a lattice, fewer particles";
  EXPECT_EQ(problem.target.particle_count(), static_cast<int>(ball.positions.size())) << "the target moves the surface";

  // The known drives, played free, score what the key frames' interpolation leaves.
  const scene::Scene truth = scene::load(dir / "truth.yaml");
  const double known = play(problem, with_regions(problem.model, truth.organs[0].regions)).rms_pct_of_motion;
  EXPECT_LT(known, 2.0);
  TuneSettings settings;
  settings.threads = 2;
  const OrganTuning t = tune_organ(scene, 0, settings);
  std::printf("floor %.3f%%, written %.3f%%, from forces %.3f%%, from lengths %.3f%%, tuned %.3f%%\n", t.floor.rms_pct_of_motion,
              t.written.rms_pct_of_motion, t.fitted_from_forces.rms_pct_of_motion, t.fitted_from_lengths.rms_pct_of_motion,
              t.after.rms_pct_of_motion);
  // Tied to its own motion, the body follows it closely; run free with the tuned drives too.
  EXPECT_LT(t.floor.rms_pct_of_motion, 25.0);
  EXPECT_GT(t.written.rms_pct_of_motion, 2 * t.after.rms_pct_of_motion);
  EXPECT_LT(t.after.rms_pct_of_motion, 2 * known + 1.0);
  EXPECT_NEAR(t.regions[0].drive.amplitude, 0.12, 0.012);
  EXPECT_NEAR(t.regions[1].drive.amplitude, 0.08, 0.008);
  EXPECT_NEAR(std::remainder(t.regions[0].drive.delay_s - 0.2, 1.0), 0.0, 0.010);
  EXPECT_NEAR(std::remainder(t.regions[1].drive.delay_s - 0.55, 1.0), 0.0, 0.010);
}

}  // namespace
}  // namespace systole::train

// body.volume_drive: the rest volume follows V0(t) = V0 (1 + a phi(t)), so a closed body
// inflates and deflates by itself (the lungs' "volume-driven inflation").

#include <gtest/gtest.h>

#include "common/error.h"
#include "sim/forces.h"
#include "sim/model.h"
#include "sim/solvers/step.h"
#include "sim/state.h"
#include "support/shapes.h"

namespace systole::sim {
namespace {

sim::OrganParams breathing_ball(sim::Method) {
  sim::OrganParams organ;
  organ.name = "ball";
  organ.body.mass_kg = 0.2;
  organ.body.stiffness_N_per_m = 40;
  organ.body.damping_s = 0.005;
  organ.body.volume_stiffness_Pa = 50000;
  organ.body.drag_per_s = 5;
  organ.body.volume_drive.waveform = sim::Waveform::kSine;
  organ.body.volume_drive.rate_hz = 0.5;
  organ.body.volume_drive.amplitude = 0.15;
  return organ;
}

Model build(const sim::OrganParams& organ, sim::Method method) {
  const mesh::TriangleMesh sphere = test::icosphere(0.05, 2);
  ModelOptions options;
  options.solver.method = method;
  options.solver.substeps = 8;
  options.dt_s = 1.0 / 240.0;
  options.clip_s = 10;
  return build_model(organ, test::geometry_of(sphere, std::vector<int>(sphere.positions.size(), -1)), options);
}

TEST(VolumeDrive, RestVolumeFollowsTheDrive) {
  const Model m = build(breathing_ball(sim::Method::kXpbd), sim::Method::kXpbd);
  ASSERT_TRUE(m.volume.enabled);
  EXPECT_DOUBLE_EQ(driven_rest_volume(m, 0.0), m.volume.rest_m3);
  EXPECT_NEAR(driven_rest_volume(m, 1.0), 1.15 * m.volume.rest_m3, 1e-12 * m.volume.rest_m3);  // Peak: half a period.
  EXPECT_NEAR(driven_rest_volume(m, 2.0), m.volume.rest_m3, 1e-12 * m.volume.rest_m3);
}

TEST(VolumeDrive, UndrivenRestVolumeIsConstant) {
  sim::OrganParams organ = breathing_ball(sim::Method::kXpbd);
  organ.body.volume_drive = sim::Drive{};
  const Model m = build(organ, sim::Method::kXpbd);
  EXPECT_EQ(driven_rest_volume(m, 0.7), m.volume.rest_m3);
}

// The body follows: near the drive's peak its volume is well above V0, and a period later
// back near V0. Both solvers that read the helper.
class VolumeDriveSolver : public ::testing::TestWithParam<sim::Method> {};

TEST_P(VolumeDriveSolver, BodyInflatesAndDeflates) {
  const sim::OrganParams organ = breathing_ball(GetParam());
  const Model m = build(organ, GetParam());
  State s = initial_state(m);
  const double dt = 1.0 / 240.0;
  const double v0 = m.volume.rest_m3;
  double peak = 0;
  for (int i = 0; i < 480; ++i) {  // Two seconds: one breath, peak at 1 s.
    step(m, s, dt);
    peak = std::max(peak, enclosed_volume(s.x, m.volume.triangles));
  }
  const double end = enclosed_volume(s.x, m.volume.triangles);
  EXPECT_GT(peak, 1.08 * v0) << "the ball should inflate towards +15%";
  EXPECT_LT(peak, 1.16 * v0);
  EXPECT_LT(end, 1.03 * v0) << "and deflate when the drive returns to 0";
}

INSTANTIATE_TEST_SUITE_P(Solvers, VolumeDriveSolver,
                         ::testing::Values(sim::Method::kXpbd, sim::Method::kExplicit));

TEST(VolumeDrive, NeedsTheVolumeConstraint) {
  sim::OrganParams organ = breathing_ball(sim::Method::kXpbd);
  organ.body.volume_stiffness_Pa = 0;
  try {
    build(organ, sim::Method::kXpbd);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    EXPECT_NE(std::string(e.what()).find("volume_stiffness"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace systole::sim

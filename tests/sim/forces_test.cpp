// The forces the explicit and implicit solvers integrate: springs with damping along them,
// driven rest lengths, the volume pressure; equal and opposite, so they sum to zero.

#include <gtest/gtest.h>

#include "sim/drive.h"
#include "sim/forces.h"
#include "sim/state.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

TEST(Forces, AtRestThereIsNoForceAndInternalForcesAlwaysSumToZero) {
  test::BeatingBall ball(2);
  ball.organ.body.volume_stiffness_Pa = 5000;
  const Model m = ball.model();
  State s = initial_state(m);
  region_contractions(m.regions, m.beat_boundaries, 0.0, m.ramp_s, s.region_contraction);
  Eigen::Matrix3Xd f;
  f.resize(3, m.particle_count());
  internal_and_scripted_forces(m, s.x, s.v, 0.0, s, f);
  EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-12);
  // Squeezed and moving: springs, dampers and pressure all act, and cancel in the sum.
  s.x *= 0.95;
  s.v.setRandom();
  s.v *= 0.01;
  internal_and_scripted_forces(m, s.x, s.v, 0.0, s, f);
  EXPECT_GT(f.cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_LT(f.rowwise().sum().norm(), 1e-9 * f.cwiseAbs().sum());
}

TEST(Forces, TheDriveShortensTheRestLengthOfSpringsInsideItsRegion) {
  test::BeatingBall ball(2);
  const Model m = ball.model();
  const Springs& sp = m.springs;
  Eigen::VectorXd contraction = Eigen::VectorXd::Zero(1);
  for (int j = 0; j < sp.size(); ++j) {
    if (sp.region_a[j] != 0 || sp.region_b[j] != 0) continue;
    EXPECT_DOUBLE_EQ(driven_rest_length(sp, j, contraction), sp.rest_m[j]);
    contraction[0] = 0.1;
    EXPECT_DOUBLE_EQ(driven_rest_length(sp, j, contraction), sp.rest_m[j] * 0.9) << "both ends driven: full";
    return;
  }
  FAIL() << "no spring inside the driven region";
}

}  // namespace
}  // namespace systole::sim

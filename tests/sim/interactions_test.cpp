// The interaction timeline every solver shares: pokes act in their window, grabs hold from
// their first key to their last, kinematic regions are placed on their path, the floor
// pushes particles back onto its free side.

#include <gtest/gtest.h>

#include "sim/interactions.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

TEST(Interactions, OneOffPokeActsOnlyInItsWindowAndAPeriodicOneFollowsItsDrive) {
  Poke once;
  once.start_s = 1.0;
  once.end_s = 1.5;
  EXPECT_EQ(poke_factor(once, 0.99, 10), 0.0);
  EXPECT_EQ(poke_factor(once, 1.0, 10), 1.0);
  EXPECT_EQ(poke_factor(once, 1.5, 10), 0.0) << "the window is half open";
  Poke periodic;
  periodic.drive.waveform = Waveform::kSine;
  periodic.drive.rate_hz = 1.0;
  EXPECT_NEAR(poke_factor(periodic, 0.0, 10), 0.0, 1e-12);
  EXPECT_NEAR(poke_factor(periodic, 0.5, 10), 1.0, 1e-12) << "phi = (1 - cos 2 pi f t) / 2";
}

TEST(Interactions, GrabHoldsFromItsFirstKeyToItsLastAlongItsPath) {
  Grab g;
  g.path = {{0.5, Eigen::Vector3d(0, 0, 0)}, {1.5, Eigen::Vector3d(0.02, 0, 0)}};
  EXPECT_FALSE(grab_active(g, 0.4));
  EXPECT_TRUE(grab_active(g, 0.5));
  EXPECT_TRUE(grab_active(g, 1.5));
  EXPECT_FALSE(grab_active(g, 1.6));
  EXPECT_EQ(handle_position(g, 1.5), Eigen::Vector3d(0.02, 0, 0));
  EXPECT_NEAR(handle_position(g, 1.0).x(), 0.01, 1e-12) << "two keys: a straight line";
}

TEST(Interactions, KinematicRegionIsPlacedOnItsPathAndTheFloorPushesBack) {
  test::BeatingBall ball(2);
  ball.top().drive = Drive{};
  ball.top().pinned = true;
  ball.top().motion = {{0.0, Eigen::Vector3d::Zero()}, {1.0, Eigen::Vector3d(0, 0.01, 0)}};
  ball.options.floor = {true, Eigen::Vector3d(0, -0.04, 0), Eigen::Vector3d::UnitY()};
  const Model m = ball.model();
  ASSERT_EQ(m.kinematic.size(), 1u);
  Eigen::Matrix3Xd x = m.rest_positions;
  move_kinematic_regions(m, 1.0, x);
  for (int i : m.kinematic[0].particles) EXPECT_NEAR(x(1, i) - m.rest_positions(1, i), 0.01, 1e-12);
  resolve_floor_contact(m, x);
  EXPECT_GE(x.row(1).minCoeff(), -0.04 - 1e-15) << "nothing stays below the floor";
  EXPECT_LT(m.rest_positions.row(1).minCoeff(), -0.045) << "the ball did reach below it";
}

}  // namespace
}  // namespace systole::sim

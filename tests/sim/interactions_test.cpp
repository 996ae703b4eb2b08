// The interaction timeline every solver shares: pokes act in their window, grabs hold from
// their first key to their last, kinematic regions are placed on their path, the floor
// pushes particles back onto its free side; for_each_grab hands every solver the same
// held particles, targets and compliances.

#include <gtest/gtest.h>

#include "sim/interactions.h"
#include "sim/solvers/substep.h"
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

TEST(Interactions, ForEachGrabVisitsTheHeldParticlesInOrderWithTheirTargetsAndCompliances) {
  Model model;
  Grab first;  // Holds over [0, 2] s, its handle moving 0.2 m along x.
  first.path = {{0.0, Eigen::Vector3d(0, 0, 0)}, {2.0, Eigen::Vector3d(0.2, 0, 0)}};
  first.particles = {4, 1};
  first.offsets_m = {Eigen::Vector3d(0, 0.01, 0), Eigen::Vector3d(0, 0, -0.02)};
  first.compliance_m_per_N = 1e-3;
  Grab later = first;  // Not yet holding at 1 s.
  later.path = {{5.0, Eigen::Vector3d(1, 1, 1)}, {6.0, Eigen::Vector3d(1, 1, 1)}};
  later.particles = {7};
  later.offsets_m = {Eigen::Vector3d(0, 0, 0)};
  Grab second;  // Holds still at (0, 0.3, 0) over [0.5, 1.5] s.
  second.path = {{0.5, Eigen::Vector3d(0, 0.3, 0)}, {1.5, Eigen::Vector3d(0, 0.3, 0)}};
  second.particles = {9};
  second.offsets_m = {Eigen::Vector3d(0.05, 0, 0)};
  second.compliance_m_per_N = 5e-4;
  model.grabs = {first, later, second};

  struct Visit {
    int particle;
    Eigen::Vector3d target_m;
    double compliance_m_per_N;
  };
  std::vector<Visit> visits;
  const auto record = [&](int i, const Eigen::Vector3d& target_m, double compliance) {
    visits.push_back({i, target_m, compliance});
  };
  for_each_grab(model, 1.0, record);
  ASSERT_EQ(visits.size(), 3u) << "the grab that does not hold yet adds nothing";
  EXPECT_EQ(visits[0].particle, 4);
  EXPECT_EQ(visits[1].particle, 1);
  EXPECT_EQ(visits[2].particle, 9);
  EXPECT_NEAR((visits[0].target_m - Eigen::Vector3d(0.1, 0.01, 0)).norm(), 0, 1e-12) << "handle + its own offset";
  EXPECT_NEAR((visits[1].target_m - Eigen::Vector3d(0.1, 0, -0.02)).norm(), 0, 1e-12);
  EXPECT_NEAR((visits[2].target_m - Eigen::Vector3d(0.05, 0.3, 0)).norm(), 0, 1e-12);
  EXPECT_EQ(visits[0].target_m, handle_position(first, 1.0) + first.offsets_m[0]) << "the same bits as written out";
  EXPECT_EQ(visits[0].compliance_m_per_N, 1e-3);
  EXPECT_EQ(visits[1].compliance_m_per_N, 1e-3);
  EXPECT_EQ(visits[2].compliance_m_per_N, 5e-4);

  visits.clear();
  for_each_grab(model, 5.5, record);
  ASSERT_EQ(visits.size(), 1u) << "the first two have let go, the later one holds";
  EXPECT_EQ(visits[0].particle, 7);
  EXPECT_NEAR((visits[0].target_m - Eigen::Vector3d(1, 1, 1)).norm(), 0, 1e-12);
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

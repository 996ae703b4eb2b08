// The parts every solver shares inside a substep (sim/solvers/substep.h): the drift by the
// velocities, the floor that stops what falls through it, and the pokes that act only
// within their interval.

#include "sim/solvers/substep.h"

#include <gtest/gtest.h>

#include <vector>

#include "sim/state.h"
#include "support/spring_body.h"

namespace systole::sim {
namespace {

Model three_particles() {
  Eigen::Matrix3Xd x(3, 3);
  x << 0, 0.01, 0.02, 0.05, 0.05, 0.05, 0, 0, 0;
  return test::spring_body(x, {0.1, 0.1, 0.1}, {{0, 1}, {1, 2}}, 10, 1);
}

TEST(Substep, DriftMovesByTheVelocityAndRemembersWhereItStarted) {
  const Model m = three_particles();
  State s = initial_state(m);
  s.v.col(0) = Eigen::Vector3d(1, 0, 0);
  s.v.col(2) = Eigen::Vector3d(0, -2, 0.5);
  const Eigen::Matrix3Xd before = s.x;
  drift(m, s, 0.01, 0.01);
  EXPECT_EQ(s.x_prev, before);
  EXPECT_TRUE(s.x.isApprox(before + 0.01 * s.v));
}

TEST(Substep, TheFloorStopsWhatFallsThroughAndKeepsTheSlide) {
  Model m = three_particles();
  m.floor.enabled = true;
  m.floor.point_m = Eigen::Vector3d(0, 0.04, 0);
  m.floor.normal = Eigen::Vector3d::UnitY();
  State s = initial_state(m);
  // Particle 0 falls 2 cm in the step while sliding sideways; particle 1 stays above.
  s.v.col(0) = Eigen::Vector3d(0.3, -2.0, 0.1);
  s.v.col(1) = Eigen::Vector3d(0, -0.5, 0);
  const double h = 0.01;
  drift(m, s, h, h);
  settle_on_floor(m, s, h);
  EXPECT_DOUBLE_EQ(s.x(1, 0), 0.04);                      // On the floor, not below it.
  EXPECT_NEAR(s.v(1, 0), (0.04 - 0.05) / h, 1e-9);        // Only the motion down to the floor.
  EXPECT_NEAR(s.v(0, 0), 0.3, 1e-9);                      // The slide is kept.
  EXPECT_NEAR(s.v(2, 0), 0.1, 1e-9);
  EXPECT_NEAR(s.x(1, 1), 0.05 - 0.5 * h, 1e-12);           // Above the floor: untouched.
  EXPECT_NEAR(s.v(1, 1), -0.5, 1e-9);
}

TEST(Substep, WithoutAFloorNothingIsSettled) {
  const Model m = three_particles();
  State s = initial_state(m);
  s.v.col(0) = Eigen::Vector3d(0, -100, 0);
  drift(m, s, 0.01, 0.01);
  const Eigen::Matrix3Xd x = s.x, v = s.v;
  settle_on_floor(m, s, 0.01);
  EXPECT_EQ(s.x, x);
  EXPECT_EQ(s.v, v);
}

TEST(Substep, APokeActsOnItsParticlesOnlyWithinItsInterval) {
  Model m = three_particles();
  Poke p;
  p.particles = {0, 2};
  p.force_per_particle_N = Eigen::Vector3d(0, 0, 0.5);
  p.start_s = 0.2;
  p.end_s = 0.3;
  m.pokes.push_back(p);
  const auto touched = [&](double t) {
    std::vector<int> particles;
    for_each_poke(m, t, [&](int i, double factor, const Eigen::Vector3d& f) {
      EXPECT_NE(factor, 0.0);
      EXPECT_EQ(f, p.force_per_particle_N);
      particles.push_back(i);
    });
    return particles;
  };
  EXPECT_TRUE(touched(0.1).empty());
  EXPECT_EQ(touched(0.2), (std::vector<int>{0, 2}));  // From its start ...
  EXPECT_EQ(touched(0.29), (std::vector<int>{0, 2}));
  EXPECT_TRUE(touched(0.3).empty());                  // ... to just before its end.
}

}  // namespace
}  // namespace systole::sim

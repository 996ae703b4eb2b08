// The blood in the ventricles (sim/circulation.h): a chamber's volume and its gradient, the
// pressure's load on its walls, and Wiggers' four phases, on a box whose answers are known.

#include "sim/circulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/box.h"

namespace systole::sim {
namespace {

/// A chamber whose surface points are the particles themselves (weight 1, no offset).
Chamber chamber_on(const test::Box& box) {
  Chamber c;
  c.name = "left_ventricle";
  c.triangles = box.triangles;
  const int n = static_cast<int>(box.corners.cols());
  for (int p = 0; p < n; ++p) {
    c.point_begin.push_back(p);
    c.term_particle.push_back(p);
    c.term_weight.push_back(1.0);
  }
  c.point_begin.push_back(n);
  c.point_offset = Eigen::Matrix3Xd::Zero(3, n);
  return c;
}

Eigen::Vector3d net(const Eigen::Matrix3Xd& force) { return force.rowwise().sum(); }

TEST(Circulation, BoxVolumeIsTheProductOfItsSides) {
  const test::Box box = test::box(0.02, 0.03, 0.05, Eigen::Vector3d(0.1, -0.2, 0.3));
  EXPECT_NEAR(chamber_volume(chamber_on(box), box.corners), 0.02 * 0.03 * 0.05, 1e-15);
}

TEST(Circulation, VolumeScalesAsTheCubeAndIgnoresTranslation) {
  const test::Box box = test::box(0.04, 0.04, 0.04);
  const Chamber c = chamber_on(box);
  const double v = chamber_volume(c, box.corners);
  EXPECT_NEAR(chamber_volume(c, 1.5 * box.corners), std::pow(1.5, 3) * v, 1e-15);
  const Eigen::Matrix3Xd moved = box.corners.colwise() + Eigen::Vector3d(0.3, -0.7, 1.1);
  EXPECT_NEAR(chamber_volume(c, moved), v, 1e-15);
}

TEST(Circulation, EmbeddedPointsFollowTheirParticlesWeightsAndOffset) {
  // Each surface point the midpoint of two particles, plus an offset: the particles are
  // placed so the points land exactly on a 1 x 2 x 3 cm box.
  const test::Box box = test::box(0.01, 0.02, 0.03);
  Chamber c = chamber_on(box);
  const int n = static_cast<int>(box.corners.cols());
  c.point_begin.clear();
  c.term_particle.clear();
  c.term_weight.clear();
  Eigen::Matrix3Xd particles(3, 2 * n);
  const Eigen::Vector3d offset(0.001, 0.002, -0.003);
  for (int p = 0; p < n; ++p) {
    c.point_begin.push_back(2 * p);
    c.term_particle.insert(c.term_particle.end(), {2 * p, 2 * p + 1});
    c.term_weight.insert(c.term_weight.end(), {0.5, 0.5});
    const Eigen::Vector3d spread(0.004 * p, -0.001, 0.002);
    particles.col(2 * p) = box.corners.col(p) - offset + spread;
    particles.col(2 * p + 1) = box.corners.col(p) - offset - spread;
  }
  c.point_begin.push_back(2 * n);
  c.point_offset = offset.replicate(1, n);
  EXPECT_NEAR(chamber_volume(c, particles), 0.01 * 0.02 * 0.03, 1e-15);
}

TEST(Circulation, GradientMatchesCentralDifferences) {
  test::Box box = test::box(0.03, 0.02, 0.04);
  // Skew it so no component of the gradient is trivially zero.
  for (int p = 0; p < 8; ++p) box.corners.col(p) += 0.003 * Eigen::Vector3d(std::sin(p), std::cos(3 * p), std::sin(5 * p + 1));
  const Chamber c = chamber_on(box);
  Eigen::Matrix3Xd gradient;
  const double v = chamber_volume(c, box.corners, gradient);
  EXPECT_DOUBLE_EQ(v, chamber_volume(c, box.corners));
  ASSERT_EQ(gradient.cols(), 8);
  const double h = 1e-7;
  for (int p = 0; p < 8; ++p) {
    for (int k = 0; k < 3; ++k) {
      Eigen::Matrix3Xd plus = box.corners, minus = box.corners;
      plus(k, p) += h;
      minus(k, p) -= h;
      const double numeric = (chamber_volume(c, plus) - chamber_volume(c, minus)) / (2 * h);
      EXPECT_NEAR(gradient(k, p), numeric, 1e-9) << "particle " << p << " axis " << k;
    }
  }
  // Moving the whole chamber rigidly does not change its volume.
  EXPECT_NEAR(gradient.rowwise().sum().norm(), 0.0, 1e-15);
}

TEST(Circulation, GradientIsZeroForParticlesTheChamberDoesNotUse) {
  const test::Box box = test::box(0.02, 0.02, 0.02);
  const Chamber c = chamber_on(box);
  Eigen::Matrix3Xd x(3, 10);
  x.leftCols(8) = box.corners;
  x.rightCols(2).setConstant(5.0);
  Eigen::Matrix3Xd gradient;
  chamber_volume(c, x, gradient);
  ASSERT_EQ(gradient.cols(), 10);
  EXPECT_EQ(gradient.rightCols(2).norm(), 0.0);
}

TEST(Circulation, PressureOnAShutChamberIsPressureTimesTheVolumeGradient) {
  // The work of a pressure p moving the walls is p dV: with both valves shut the load on each
  // particle is p times the volume's gradient, and a closed surface feels no net force.
  test::Box box = test::box(0.03, 0.02, 0.04);
  box.corners.col(7) += Eigen::Vector3d(0.004, 0.002, -0.001);
  Chamber c = chamber_on(box);
  c.inflow_cap = {2 * test::kTop, 2 * test::kTop + 2};
  c.outflow_cap = {2 * test::kRight, 2 * test::kRight + 2};
  const double p = 1500;
  Eigen::Matrix3Xd gradient;
  chamber_volume(c, box.corners, gradient);
  for (ChamberPhase phase : {ChamberPhase::kIsovolumicContraction, ChamberPhase::kIsovolumicRelaxation}) {
    Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, 8);
    add_pressure_load(c, phase, box.corners, p, force);
    EXPECT_LT((force - p * gradient).norm(), 1e-12 * p * gradient.norm());
    EXPECT_LT(net(force).norm(), 1e-12 * p);
  }
}

TEST(Circulation, LoadIsAddedToTheForceAlreadyThere) {
  const test::Box box = test::box(0.02, 0.02, 0.02);
  const Chamber c = chamber_on(box);
  Eigen::Matrix3Xd once = Eigen::Matrix3Xd::Zero(3, 8);
  add_pressure_load(c, ChamberPhase::kIsovolumicContraction, box.corners, 100, once);
  Eigen::Matrix3Xd twice = once;
  add_pressure_load(c, ChamberPhase::kIsovolumicContraction, box.corners, 100, twice);
  EXPECT_LT((twice - 2 * once).norm(), 1e-15);
}

TEST(Circulation, AnOpenValvesCapCarriesNoLoad) {
  // Leaving one face out of a closed surface's load leaves a net force of minus that face's
  // load: p times its area, pointing into the box. Filling opens the inflow cap, ejection
  // the outflow cap.
  const double a = 0.03, b = 0.02, cc = 0.04, p = 2000;
  const test::Box box = test::box(a, b, cc);
  Chamber c = chamber_on(box);
  c.inflow_cap = {2 * test::kTop, 2 * test::kTop + 2};
  c.outflow_cap = {2 * test::kRight, 2 * test::kRight + 2};

  Eigen::Matrix3Xd filling = Eigen::Matrix3Xd::Zero(3, 8);
  add_pressure_load(c, ChamberPhase::kFilling, box.corners, p, filling);
  EXPECT_LT((net(filling) - Eigen::Vector3d(0, 0, -p * a * b)).norm(), 1e-12 * p * a * b);
  for (int corner : {4, 5, 6, 7}) {
    // The top corners carry only their side faces' load: nothing pushes them up.
    EXPECT_NEAR(filling(2, corner), 0.0, 1e-12 * p * a * b) << corner;
  }

  Eigen::Matrix3Xd ejecting = Eigen::Matrix3Xd::Zero(3, 8);
  add_pressure_load(c, ChamberPhase::kEjection, box.corners, p, ejecting);
  EXPECT_LT((net(ejecting) - Eigen::Vector3d(-p * b * cc, 0, 0)).norm(), 1e-12 * p * b * cc);
}

TEST(Circulation, ChordaeMoveTheShutInflowCapsLoadWithoutChangingTheTotal) {
  const double a = 0.03, b = 0.02, cc = 0.04, p = 1000;
  const test::Box box = test::box(a, b, cc);
  Chamber plain = chamber_on(box);
  plain.inflow_cap = {2 * test::kTop, 2 * test::kTop + 2};
  plain.outflow_cap = {2 * test::kRight, 2 * test::kRight + 2};
  Chamber tethered = plain;
  tethered.chordae_points = {0, 1};  // Two bottom corners: the papillary muscles.
  tethered.chordae_share = 0.75;

  // Ejecting: the inflow valve is shut and hangs on the chordae.
  Eigen::Matrix3Xd f_plain = Eigen::Matrix3Xd::Zero(3, 8), f_tethered = Eigen::Matrix3Xd::Zero(3, 8);
  add_pressure_load(plain, ChamberPhase::kEjection, box.corners, p, f_plain);
  add_pressure_load(tethered, ChamberPhase::kEjection, box.corners, p, f_tethered);
  EXPECT_LT((net(f_plain) - net(f_tethered)).norm(), 1e-12 * p * a * b);
  // The top face's load p*a*b (up) is 3/4 on the chordae: they pull the bottom corners up
  // by 3/8 of it each, and the top corners keep a quarter of it.
  const double top_load = p * a * b;
  EXPECT_NEAR(f_tethered(2, 0) - f_plain(2, 0), 0.375 * top_load, 1e-12 * top_load);
  EXPECT_NEAR(f_tethered(2, 1) - f_plain(2, 1), 0.375 * top_load, 1e-12 * top_load);
  double top_plain = 0, top_tethered = 0;
  for (int corner : {4, 5, 6, 7}) {
    top_plain += f_plain(2, corner);
    top_tethered += f_tethered(2, corner);
  }
  EXPECT_NEAR(top_plain - top_tethered, 0.75 * top_load, 1e-12 * top_load);

  // Filling: the inflow valve is open; its cap carries nothing, the chordae nothing either.
  Eigen::Matrix3Xd g_plain = Eigen::Matrix3Xd::Zero(3, 8), g_tethered = Eigen::Matrix3Xd::Zero(3, 8);
  add_pressure_load(plain, ChamberPhase::kFilling, box.corners, p, g_plain);
  add_pressure_load(tethered, ChamberPhase::kFilling, box.corners, p, g_tethered);
  EXPECT_LT((g_plain - g_tethered).norm(), 1e-15);
}

class Phases : public ::testing::Test {
 protected:
  Phases() : box_(test::box(0.03, 0.03, 0.03)) {
    Chamber c = chamber_on(box_);
    c.rest_m3 = chamber_volume(c, box_.corners);
    c.afterload_Pa = 10000;
    circulation_.chambers.push_back(c);
    circulation_.filling_Pa = 800;
    state_.resize(1);
    state_[0].volume_m3 = c.rest_m3;
  }
  /// The box scaled uniformly to `volume` (its lowest corner fixed).
  Eigen::Matrix3Xd at_volume(double volume) const {
    return box_.corners * std::cbrt(volume / circulation_.chambers[0].rest_m3);
  }
  void step(double volume, double h = 1e-3) { advance_phases(circulation_, at_volume(volume), h, state_); }
  double rest() const { return circulation_.chambers[0].rest_m3; }

  test::Box box_;
  Circulation circulation_;
  std::vector<ChamberState> state_;
};

TEST_F(Phases, AVentricleGoesRoundWiggersFourPhases) {
  ASSERT_TRUE(circulation_.enabled());
  const double h = 1e-3;
  // Filling: the volume grows; the inflow valve stays open.
  double v = rest();
  for (int i = 0; i < 20; ++i) step(v += rest() * h, h);  // One rest volume a second.
  EXPECT_EQ(state_[0].phase, ChamberPhase::kFilling);
  EXPECT_NEAR(state_[0].volume_m3, v, 1e-12 * rest());
  EXPECT_GT(state_[0].flow_m3_per_s, 0.0);

  // The wall contracts fast (5 rest volumes a second): the inflow valve shuts, the blood's
  // volume at that moment is kept.
  int steps = 0;
  while (state_[0].phase == ChamberPhase::kFilling && steps < 100) {
    step(v -= 5 * rest() * h, h);
    ++steps;
  }
  ASSERT_EQ(state_[0].phase, ChamberPhase::kIsovolumicContraction);
  EXPECT_TRUE(isovolumic(state_[0].phase));
  EXPECT_NEAR(state_[0].shut_m3, v, 1e-12 * rest());

  // Pressure below the afterload keeps the outflow valve shut; reaching it opens the valve.
  state_[0].pressure_Pa = 9999;
  step(v, h);
  EXPECT_EQ(state_[0].phase, ChamberPhase::kIsovolumicContraction);
  state_[0].pressure_Pa = 10000;
  step(v, h);
  ASSERT_EQ(state_[0].phase, ChamberPhase::kEjection);
  EXPECT_FALSE(isovolumic(state_[0].phase));

  // Ejecting: the volume falls; a rise smaller than the backflow threshold is vibration.
  for (int i = 0; i < 10; ++i) step(v -= 0.02 * rest(), h);
  const double least = v;
  EXPECT_NEAR(state_[0].smallest_m3, least, 1e-12 * rest());
  step(v = least + 0.5 * kBackflow * rest(), h);
  EXPECT_EQ(state_[0].phase, ChamberPhase::kEjection);
  // The flow turns back: the outflow valve shuts.
  step(v = least + 2 * kBackflow * rest(), h);
  ASSERT_EQ(state_[0].phase, ChamberPhase::kIsovolumicRelaxation);
  EXPECT_NEAR(state_[0].shut_m3, v, 1e-12 * rest());

  // The pressure falls to the filling pressure: the inflow valve opens again.
  state_[0].pressure_Pa = 801;
  step(v, h);
  EXPECT_EQ(state_[0].phase, ChamberPhase::kIsovolumicRelaxation);
  state_[0].pressure_Pa = 800;
  step(v, h);
  EXPECT_EQ(state_[0].phase, ChamberPhase::kFilling);
}

TEST_F(Phases, ASlowSqueezeDoesNotShutTheInflowValve) {
  // The atria squeeze the ventricle at well under kShuttingRate_per_s rest volumes a second.
  const double h = 1e-3;
  double v = rest();
  for (int i = 0; i < 200; ++i) step(v -= 0.5 * kShuttingRate_per_s * rest() * h, h);
  EXPECT_EQ(state_[0].phase, ChamberPhase::kFilling);
  EXPECT_NEAR(state_[0].flow_m3_per_s, -0.5 * kShuttingRate_per_s * rest(), 1e-6 * rest());
}

TEST_F(Phases, TheSmoothedFlowDoesNotDependOnTheStep) {
  // A steady contraction reaches the same smoothed flow, and shuts the valve at the same
  // time, whether stepped at 0.1 ms or 1 ms.
  const double rate = -3 * rest();  // m^3/s
  std::vector<double> shut_at;
  for (double h : {1e-4, 1e-3}) {
    state_.assign(1, ChamberState{});
    state_[0].volume_m3 = rest();
    double v = rest(), t = 0;
    while (state_[0].phase == ChamberPhase::kFilling && t < 0.2) {
      step(v += rate * h, h);
      t += h;
    }
    ASSERT_EQ(state_[0].phase, ChamberPhase::kIsovolumicContraction) << h;
    shut_at.push_back(t);
  }
  // Exponential smoothing over kFlowSmoothing_s reaches kShuttingRate / 3 of the final rate
  // after -ln(2/3) time constants.
  const double expected = -kFlowSmoothing_s * std::log(1 - kShuttingRate_per_s / 3.0);
  for (double t : shut_at) EXPECT_NEAR(t, expected, 1.2e-3);
}

}  // namespace
}  // namespace systole::sim

#include "sim/motion_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace systole::sim {
namespace {

/// One vertex on the x axis following a sine of amplitude `a` about x0 (and a still one at
/// the origin), 60 samples over one 1-Hz period.
Trajectory oscillation(double a, double delay_s = 0, double x0 = 1) {
  Trajectory frames;
  for (int i = 1; i <= 60; ++i) {
    Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, 2);
    x(0, 0) = x0 + a * std::sin(2 * M_PI * (i / 60.0 - delay_s));
    frames.push_back(x);
  }
  return frames;
}

TEST(MotionError, MotionIsTheRmsDistanceFromTheMeanShape) {
  // A sine of amplitude a has RMS a / sqrt(2); the still vertex halves the mean square.
  EXPECT_NEAR(rms_motion_m(oscillation(0.2)), 0.2 / 2.0, 1e-12);
  EXPECT_EQ(rms_motion_m(oscillation(0)), 0.0);
}

TEST(MotionError, AFrozenMeanShapeScoresOneHundredPercent) {
  const Trajectory reference = oscillation(0.2);
  EXPECT_NEAR(error_pct_of_motion(oscillation(0.0), reference), 100.0, 1e-9);
  EXPECT_NEAR(error_pct_of_motion(reference, reference), 0.0, 1e-12);
  // Half the motion, in phase: off by half of it.
  EXPECT_NEAR(error_pct_of_motion(oscillation(0.1), reference), 50.0, 1e-9);
}

TEST(MotionError, ErrorIsRelativeToMotionNotToSize) {
  // The same lag on a body ten times farther from the origin is the same share of the motion.
  const double near = error_pct_of_motion(oscillation(0.2, 0.05, 1), oscillation(0.2, 0, 1));
  const double far = error_pct_of_motion(oscillation(0.2, 0.05, 10), oscillation(0.2, 0, 10));
  EXPECT_NEAR(near, far, 1e-9);
  EXPECT_GT(near, 10.0);
}

TEST(MotionError, AStillReferenceIsMatchedOnlyByStillness) {
  EXPECT_EQ(error_pct_of_motion(oscillation(0), oscillation(0)), 0.0);
  EXPECT_TRUE(std::isinf(error_pct_of_motion(oscillation(0.1), oscillation(0))));
}

TEST(MotionError, SignalsCompareByAmplitudePhaseAndSpan) {
  std::vector<double> reference, run;
  for (int i = 1; i <= 120; ++i) {
    const double t = i / 60.0;
    reference.push_back(std::sin(2 * M_PI * t));
    run.push_back(1.1 * std::sin(2 * M_PI * (t - 0.02)));  // 10 % larger, 20 ms late.
  }
  const SignalAgreement a = compare_signals(run, reference, 1.0, 60.0);
  EXPECT_NEAR(a.amplitude_error_pct, 10.0, 1e-6);
  EXPECT_NEAR(a.phase_lag_ms, 20.0, 1e-6);
  EXPECT_NEAR(a.peak_to_peak_error_pct, 10.0, 0.5);
}

TEST(MotionError, RadialDistanceAveragesTheChosenVertices) {
  Eigen::Matrix3Xd x(3, 3);
  x << 1, 0, 5, 0, 2, 0, 0, 0, 0;
  EXPECT_NEAR(mean_radial_distance_m(x, {0, 1}, Eigen::Vector3d::Zero()), 1.5, 1e-12);
  EXPECT_EQ(mean_radial_distance_m(x, {}, Eigen::Vector3d::Zero()), 0.0);
}

}  // namespace
}  // namespace systole::sim

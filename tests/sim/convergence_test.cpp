// The solvers integrate one model: as the step shrinks, each converges, and they converge
// to the same motion.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/model.h"
#include "sim/solvers/step.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

using sim::Method;

/// A heavy, soft, beating ball: slow enough that even the explicit solver runs at every
/// step tried here, so all three can be compared on the same model.
Model soft_ball(Method method, int substeps) {
  test::BeatingBall ball(2, 1.0, 0.2);
  ball.organ.body.mass_kg = 1.0;
  ball.organ.body.stiffness_N_per_m = 50;
  ball.organ.body.damping_s = 0.002;
  ball.organ.body.volume_stiffness_Pa = 2000;
  ball.options.solver.method = method;
  ball.options.solver.substeps = substeps;
  return ball.model();
}

/// Positions at every 1/30 s over 1.5 s, stepping with substeps of `h`.
std::vector<Eigen::Matrix3Xd> trajectory(Method method, double h) {
  const double frame = 1.0 / 30;
  const int substeps = static_cast<int>(std::lround(frame / h));
  const Model m = soft_ball(method, substeps);
  State s = initial_state(m);
  std::vector<Eigen::Matrix3Xd> out;
  for (int f = 0; f < 45; ++f) {
    step(m, s, frame);
    EXPECT_FALSE(diagnose(m, s).has_value());
    out.push_back(s.x);
  }
  return out;
}

/// RMS distance between two trajectories. unit: m
double rms_error(const std::vector<Eigen::Matrix3Xd>& a, const std::vector<Eigen::Matrix3Xd>& b) {
  double sum = 0;
  long n = 0;
  for (std::size_t f = 0; f < a.size(); ++f) {
    sum += (a[f] - b[f]).colwise().squaredNorm().sum();
    n += a[f].cols();
  }
  return std::sqrt(sum / double(n));
}

/// RMS displacement from rest: the size of the motion the errors are measured against. unit: m
double rms_motion(const std::vector<Eigen::Matrix3Xd>& a, const Eigen::Matrix3Xd& rest) {
  double sum = 0;
  long n = 0;
  for (const auto& x : a) {
    sum += (x - rest).colwise().squaredNorm().sum();
    n += x.cols();
  }
  return std::sqrt(sum / double(n));
}

class Convergence : public ::testing::TestWithParam<Method> {};

TEST_P(Convergence, ErrorShrinksWithTheStep) {
  const Method method = GetParam();
  const double h0 = 1.0 / 600;
  const auto reference = trajectory(method, h0 / 16);
  double previous = 1e9;
  for (double h : {h0, h0 / 2, h0 / 4}) {
    const double e = rms_error(trajectory(method, h), reference);
    EXPECT_LT(e, 0.8 * previous) << method_name(method) << ": error at h = " << h << " s did not shrink";
    previous = e;
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, Convergence,
                         ::testing::Values(Method::kXpbd, Method::kExplicit, Method::kImplicit),
                         [](const auto& info) { return std::string(method_name(info.param)); });

TEST(Convergence, AllSolversApproachTheSameMotion) {
  const double h = 1.0 / 9600;
  const auto xpbd = trajectory(Method::kXpbd, h);
  const auto explicit_euler = trajectory(Method::kExplicit, h);
  const auto implicit = trajectory(Method::kImplicit, h);
  const double motion = rms_motion(explicit_euler, soft_ball(Method::kExplicit, 1).rest_positions);
  ASSERT_GT(motion, 1e-3) << "the ball moves";
  EXPECT_LT(rms_error(xpbd, explicit_euler), 0.05 * motion);
  EXPECT_LT(rms_error(implicit, explicit_euler), 0.05 * motion);
}

}  // namespace
}  // namespace systole::sim

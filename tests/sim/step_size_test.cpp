// Choosing the step (sim/solvers/step_size.h): the Gershgorin bound on the springs' squared
// frequency, explicit Euler's stability limit (stable at the chosen substep, unstable past
// h w = 2), XPBD's damping-time limit, and the cost estimate's proportionality.

#include "sim/solvers/step_size.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/solvers/explicit_euler.h"
#include "sim/state.h"
#include "support/spring_body.h"

namespace systole::sim {
namespace {

Eigen::Matrix3Xd line(int n, double spacing_m) {
  Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, n);
  for (int i = 0; i < n; ++i) x(0, i) = spacing_m * i;
  return x;
}

TEST(StepSize, OmegaSquaredIsTheGershgorinBound) {
  // Two masses on one spring: w_i * 2k, largest at the lighter, which for equal masses is the
  // oscillator's own w^2 = k (1/m + 1/m).
  EXPECT_DOUBLE_EQ(max_omega_squared(test::spring_body(line(2, 0.01), {0.02, 0.06}, {{0, 1}}, 20, 1)), 2 * 20 / 0.02);
  EXPECT_DOUBLE_EQ(max_omega_squared(test::spring_body(line(2, 0.01), {0.05, 0.05}, {{0, 1}}, 20, 1)), 20 * (2 / 0.05));
  // A chain of three: the middle particle has two springs.
  EXPECT_DOUBLE_EQ(max_omega_squared(test::spring_body(line(3, 0.01), {0.1, 0.1, 0.1}, {{0, 1}, {1, 2}}, 30, 1)),
                   4 * 30 / 0.1);
  // A pinned particle (inverse mass 0) sets no limit.
  Model pinned = test::spring_body(line(2, 0.01), {0.01, 1.0}, {{0, 1}}, 10, 1);
  pinned.inverse_mass[0] = 0;
  EXPECT_DOUBLE_EQ(max_omega_squared(pinned), 2 * 10 / 1.0);
}

/// The largest stretch over `steps` explicit steps of h from a 1 mm stretch.
double largest_stretch(Model m, double h, int steps) {
  m.substeps = 1;
  State s = initial_state(m);
  s.x(0, 1) += 0.001;
  double largest = 0;
  for (int i = 0; i < steps && largest < 1; ++i) {
    explicit_step(m, s, h);
    largest = std::max(largest, std::abs((s.x.col(1) - s.x.col(0)).norm() - 0.01));
  }
  return largest;
}

TEST(StepSize, ExplicitEulerIsStableAtItsLimitAndNotBeyondHOmegaTwo) {
  Model m = test::spring_body(line(2, 0.01), {0.05, 0.05}, {{0, 1}}, 20, 1);
  m.method = Method::kExplicit;
  const StepLimits limits = step_limits(m);
  const double omega = std::sqrt(max_omega_squared(m));
  EXPECT_NEAR(limits.max_substep_s, 0.8 * 2 / omega, 1e-12);  // Undamped: h w = 2, with the margin.
  EXPECT_LE(limits.max_substep_s, limits.max_step_s);
  EXPECT_FALSE(limits.reason.empty());
  // Symplectic Euler on an oscillator: bounded for h w < 2, growing without bound above.
  EXPECT_LT(largest_stretch(m, limits.max_substep_s, 2000), 0.002);
  EXPECT_GT(largest_stretch(m, 1.1 * 2 / omega, 2000), 1.0);
}

TEST(StepSize, DampingTightensTheExplicitLimit) {
  Model m = test::spring_body(line(2, 0.01), {0.05, 0.05}, {{0, 1}}, 20, 1);
  m.method = Method::kExplicit;
  const double undamped = step_limits(m).max_substep_s;
  m.springs.damping_s[0] = 0.01;
  const double h = step_limits(m).max_substep_s / 0.8;
  const double w2 = max_omega_squared(m);
  EXPECT_LT(h * 0.8, undamped);
  EXPECT_NEAR(h * h * w2 + 2 * h * 0.01 * w2, 4.0, 1e-9);  // On the stability boundary, before the margin.
}

TEST(StepSize, XpbdIsLimitedOnlyByTheDrivesAndTheDampingTime) {
  Model m = test::spring_body(line(2, 0.01), {0.02, 0.06}, {{0, 1}}, 20, 1);
  m.method = Method::kXpbd;
  // Nothing driven, no dampers: 1 s, the step without a drive.
  EXPECT_DOUBLE_EQ(step_limits(m).max_step_s, 1.0);
  EXPECT_DOUBLE_EQ(step_limits(m).max_substep_s, 1.0);
  // A damper of c = tau k: the lighter particle's damping time m / c.
  m.springs.damping_s[0] = 0.002;
  EXPECT_NEAR(step_limits(m).max_substep_s, 0.02 / (0.002 * 20), 1e-15);
}

TEST(StepSize, ImplicitSolversNeedOneSubstepPerStep) {
  Model m = test::spring_body(line(2, 0.01), {0.02, 0.06}, {{0, 1}}, 1e6, 1);
  for (Method method : {Method::kImplicit, Method::kProjective}) {
    m.method = method;
    const StepLimits limits = step_limits(m);
    EXPECT_EQ(limits.max_substep_s, limits.max_step_s);  // However stiff.
  }
}

TEST(StepSize, NothingDrivenMeansNoDriveLimit) {
  EXPECT_EQ(highest_drive_frequency_hz({}), 0.0);
  EXPECT_EQ(max_step_s({}), 1.0);
}

TEST(StepSize, CostGrowsWithTheStepsTakenAndTheSprings) {
  Model m = test::spring_body(line(3, 0.01), {0.1, 0.1, 0.1}, {{0, 1}, {1, 2}}, 30, 4);
  for (Method method : {Method::kXpbd, Method::kExplicit}) {
    m.method = method;
    m.substeps = 4;
    const double base = estimated_cost_s_per_s(m, 1e-3);
    EXPECT_GT(base, 0.0);
    EXPECT_NEAR(estimated_cost_s_per_s(m, 0.5e-3), 2 * base, 1e-12 * base);  // Twice the steps.
    m.substeps = 8;
    EXPECT_NEAR(estimated_cost_s_per_s(m, 1e-3), 2 * base, 1e-12 * base);  // Twice the substeps.
  }
  const Model longer = test::spring_body(line(5, 0.01), std::vector<double>(5, 0.1), {{0, 1}, {1, 2}, {2, 3}, {3, 4}}, 30, 4);
  EXPECT_NEAR(estimated_cost_s_per_s(longer, 1e-3), 2 * estimated_cost_s_per_s(test::spring_body(line(3, 0.01), {0.1, 0.1, 0.1}, {{0, 1}, {1, 2}}, 30, 4), 1e-3),
              1e-9);  // Twice the springs.
}

}  // namespace
}  // namespace systole::sim

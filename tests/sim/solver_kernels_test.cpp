// The three time-stepping kernels called directly (sim/solvers/explicit_euler.h, xpbd.h,
// projective.h), on bodies small enough that their motion is known in closed form: a free
// fall, and two masses on one spring (a harmonic oscillator of angular frequency
// sqrt(k (1/m1 + 1/m2))). Internal forces keep the momentum; the spring sets the period.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <vector>

#include "sim/solvers/explicit_euler.h"
#include "sim/solvers/projective.h"
#include "sim/solvers/xpbd.h"
#include "support/spring_body.h"

namespace systole::sim {
namespace {

using Kernel = void (*)(const Model&, State&, double);

void xpbd(const Model& m, State& s, double h) { xpbd_step(m, s, h); }

struct Solver {
  const char* name;
  Kernel step;
  int substeps;
};

// Named by its name in test names (not as the bytes of its pointers).
void PrintTo(const Solver& s, std::ostream* os) { *os << s.name; }

const Solver kSolvers[] = {{"explicit", explicit_step, 40}, {"xpbd", xpbd, 20}, {"projective", projective_step, 1}};

Model body(const Eigen::Matrix3Xd& x, const std::vector<double>& mass_kg, const std::vector<std::pair<int, int>>& springs,
           double k_N_per_m, int substeps) {
  return test::spring_body(x, mass_kg, springs, k_N_per_m, substeps);
}

Eigen::Vector3d momentum(const Model& m, const State& s) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < s.v.cols(); ++i) p += s.v.col(i) / m.inverse_mass[i];
  return p;
}

class Kernels : public ::testing::TestWithParam<Solver> {};

TEST_P(Kernels, AFreeBodyFallsAsGravityAccelerates) {
  const Solver& solver = GetParam();
  Eigen::Matrix3Xd x(3, 2);
  x << 0, 0.02, 0, 0, 0, 0;
  Model m = body(x, {0.1, 0.1}, {{0, 1}}, 50, solver.substeps);
  m.gravity = Eigen::Vector3d(0, -9.81, 0);
  State s = initial_state(m);
  const double h = 1.0 / 240;
  const int steps = 120;  // Half a second.
  for (int i = 0; i < steps; ++i) solver.step(m, s, h);
  const double t = steps * h;
  for (int p = 0; p < 2; ++p) {
    // The spring at rest length moves with the body: every particle falls alike.
    EXPECT_NEAR(s.v(1, p), -9.81 * t, 1e-6) << solver.name;
    EXPECT_NEAR(s.v(0, p), 0.0, 1e-9) << solver.name;
    const double fall = x(1, p) - s.x(1, p);
    EXPECT_NEAR(fall, 0.5 * 9.81 * t * t, 0.01 * 0.5 * 9.81 * t * t) << solver.name;  // First order: 1 %.
  }
  EXPECT_NEAR((s.x.col(1) - s.x.col(0)).norm(), 0.02, 1e-9) << solver.name;
}

TEST_P(Kernels, TwoMassesOnASpringKeepTheirMomentumAndCentre) {
  const Solver& solver = GetParam();
  Eigen::Matrix3Xd x(3, 2);
  x << 0, 0.03, 0, 0.01, 0, -0.005;
  const std::vector<double> mass{0.05, 0.15};
  const Model m = body(x, mass, {{0, 1}}, 40, solver.substeps);
  State s = initial_state(m);
  // Stretch the spring and set the pair moving: momentum P = m0 v0 + m1 v1.
  s.x.col(1) += 0.3 * (x.col(1) - x.col(0));
  s.v.col(0) = Eigen::Vector3d(0.1, 0.0, 0.02);
  s.v.col(1) = Eigen::Vector3d(-0.02, 0.05, 0.0);
  const Eigen::Vector3d p0 = momentum(m, s);
  const Eigen::Vector3d c0 = (mass[0] * s.x.col(0) + mass[1] * s.x.col(1)) / (mass[0] + mass[1]);
  const double h = 1.0 / 240;
  for (int i = 0; i < 240; ++i) solver.step(m, s, h);
  EXPECT_LT((momentum(m, s) - p0).norm(), 1e-12) << solver.name;
  const Eigen::Vector3d c = (mass[0] * s.x.col(0) + mass[1] * s.x.col(1)) / (mass[0] + mass[1]);
  // The centre moves uniformly: c0 + P / M t.
  EXPECT_LT((c - (c0 + p0 / (mass[0] + mass[1]) * 1.0)).norm(), 1e-9) << solver.name;
}

TEST_P(Kernels, TheSpringOscillatesAtItsNaturalFrequency) {
  const Solver& solver = GetParam();
  Eigen::Matrix3Xd x(3, 2);
  x << 0, 0.04, 0, 0, 0, 0;
  const double k = 20, m0 = 0.02, m1 = 0.06;
  const Model m = body(x, {m0, m1}, {{0, 1}}, k, solver.substeps);
  State s = initial_state(m);
  s.x(0, 1) += 0.004;  // 10 % stretch, released at rest.
  const double omega = std::sqrt(k * (1 / m0 + 1 / m1));
  const double period = 2 * std::numbers::pi / omega;  // About 0.17 s.
  const double h = period / 200;
  // Times the stretch crosses zero going down, interpolated within the step.
  std::vector<double> crossings;
  double t = 0, last = 0.004;
  while (crossings.size() < 6 && t < 20 * period) {
    solver.step(m, s, h);
    t += h;
    const double stretch = (s.x.col(1) - s.x.col(0)).norm() - 0.04;
    if (last > 0 && stretch <= 0) crossings.push_back(t - h * stretch / (stretch - last));
    last = stretch;
  }
  ASSERT_EQ(crossings.size(), 6u) << solver.name;
  const double measured = (crossings.back() - crossings.front()) / 5;
  EXPECT_NEAR(measured, period, 0.02 * period) << solver.name;
  // Undamped: it still swings after five periods (a tenth of the amplitude at least).
  double largest = 0;
  for (int i = 0; i < 200; ++i) {
    solver.step(m, s, h);
    largest = std::max(largest, std::abs((s.x.col(1) - s.x.col(0)).norm() - 0.04));
  }
  EXPECT_GT(largest, 0.1 * 0.004) << solver.name;
  EXPECT_LT(largest, 1.05 * 0.004) << solver.name;  // ... and never gains energy.
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, Kernels, ::testing::ValuesIn(kSolvers),
                         [](const ::testing::TestParamInfo<Solver>& info) { return std::string(info.param.name); });

TEST(ExplicitKernel, SymplecticEulerKeepsTheOscillatorsAmplitude) {
  // Symplectic Euler has no numerical damping: after 20 periods the amplitude is the same.
  Eigen::Matrix3Xd x(3, 2);
  x << 0, 0.04, 0, 0, 0, 0;
  const Model m = body(x, {0.05, 0.05}, {{0, 1}}, 20, 10);
  State s = initial_state(m);
  s.x(0, 1) += 0.004;
  const double period = 2 * std::numbers::pi / std::sqrt(20 * (2 / 0.05));
  const double h = period / 100;
  for (int i = 0; i < 2000; ++i) explicit_step(m, s, h);
  double largest = 0;
  for (int i = 0; i < 100; ++i) {
    explicit_step(m, s, h);
    largest = std::max(largest, std::abs((s.x.col(1) - s.x.col(0)).norm() - 0.04));
  }
  EXPECT_NEAR(largest, 0.004, 0.01 * 0.004);
}

TEST(ProjectiveKernel, ARestartStepsAsBackwardEulerFromScratch) {
  Eigen::Matrix3Xd x(3, 3);
  x << 0, 0.03, 0.01, 0, 0, 0.025, 0, 0, 0;
  const Model m = body(x, {0.03, 0.04, 0.05}, {{0, 1}, {1, 2}, {2, 0}}, 30, 1);
  State s = initial_state(m);
  s.x(0, 1) += 0.005;
  const double h = 1.0 / 120;
  for (int i = 0; i < 7; ++i) projective_step(m, s, h);

  State restarted = s;
  projective_restart(restarted);
  projective_step(m, restarted, h);
  State fresh = s;
  fresh.solver_cache = SolverScratch{};  // No history: the first step is backward Euler.
  projective_step(m, fresh, h);
  State continued = s;  // BDF2 from its history.
  projective_step(m, continued, h);

  EXPECT_LT((restarted.x - fresh.x).norm(), 1e-12);
  EXPECT_LT((restarted.v - fresh.v).norm(), 1e-10);
  EXPECT_GT((continued.x - fresh.x).norm(), 1e-7);  // The history matters: the restart did something.

  // A state no projective step has touched has nothing to restart.
  State untouched = initial_state(m);
  projective_restart(untouched);
  EXPECT_EQ(untouched.x, m.rest_positions);
}

}  // namespace
}  // namespace systole::sim

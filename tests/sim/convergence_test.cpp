// ctest-labels: no-sanitizers
// The solvers integrate one model: as the step shrinks, each converges, and they converge
// to the same motion - on a gentle ball and on a body as stiff, damped and pinned as the
// shipped heart.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/model.h"
#include "sim/solvers/step.h"
#include "sim/motion_error.h"
#include "support/beating_ball.h"
#include "support/small_heart.h"

namespace systole::sim {
namespace {

using sim::Method;

/// A heavy, soft, beating ball: slow enough that even the explicit solver runs at every
/// step tried here, so all of them can be compared on the same model.
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

class Convergence : public ::testing::TestWithParam<Method> {};

TEST_P(Convergence, ErrorShrinksWithTheStep) {
  const Method method = GetParam();
  const double h0 = 1.0 / 600;
  const auto reference = trajectory(method, h0 / 16);
  double previous = 1e9;
  for (double h : {h0, h0 / 2, h0 / 4}) {
    const double e = rms_distance_m(trajectory(method, h), reference);
    EXPECT_LT(e, 0.8 * previous) << method_name(method) << ": error at h = " << h << " s did not shrink";
    previous = e;
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, Convergence,
                         ::testing::Values(Method::kXpbd, Method::kExplicit, Method::kImplicit, Method::kProjective),
                         [](const auto& info) { return std::string(method_name(info.param)); });

// --- The heart's kind of body -----------------------------------------------------------
// Stiff, strongly damped, partly pinned (support/small_heart.h). The reference is projective
// dynamics at 1/960 s, the same as `systole bench`'s: halving its step must not move it,
// and the explicit solver at its stability limit - another integrator, another damping
// discretization - must reach the same motion. Then every solver at its documented setting
// stays within its documented error budget (docs/accuracy.md, "Budgets"), as a share of the
// reference's motion, with each band's beat amplitude and phase.

constexpr double kReferenceDt = 1.0 / 960;

struct Reference {
  test::SmallHeart heart;
  test::SmallHeart::Run run = heart.run(heart.model(Method::kProjective, kReferenceDt, 1), kReferenceDt);
};

const Reference& reference() {
  static const Reference r;
  return r;
}

TEST(HeartLikeBody, ReferenceIsConverged) {
  const auto& ref = reference();
  ASSERT_GT(rms_motion_m(ref.run.x), 2e-4) << "the body beats";
  const auto halved = ref.heart.run(ref.heart.model(Method::kProjective, kReferenceDt / 2, 1), kReferenceDt / 2);
  EXPECT_LT(error_pct_of_motion(halved.x, ref.run.x), 2.0) << "halving the step moves the reference";
}

TEST(HeartLikeBody, SecondSolverAgrees) {
  const auto& ref = reference();
  const auto explicit_euler = ref.heart.run(ref.heart.explicit_reference(), 1.0 / 60);
  EXPECT_LT(error_pct_of_motion(explicit_euler.x, ref.run.x), 2.0);
  for (int band = 0; band < 2; ++band) {
    const SignalAgreement a = compare_signals(explicit_euler.band[band], ref.run.band[band], test::SmallHeart::kBeatHz, 60);
    EXPECT_LT(std::abs(a.amplitude_error_pct), 1.0) << "band " << band;
    EXPECT_LT(std::abs(a.phase_lag_ms), 1.0) << "band " << band;
  }
}

struct Budget {
  Method method;
  double dt_s;
  int substeps;
  double rms_pct;        ///< Largest RMS error, % of the reference's motion.
  double amplitude_pct;  ///< Largest |amplitude error| of either band's beat.
  double phase_ms;       ///< Largest |phase lag| of either band's beat.
};

// The budgets docs/accuracy.md documents, each a little above what this body measures, so
// a regression of the solver fails and a rounding change does not. XPBD's (10 % at
// 1/240 s x 2048) is XpbdConvergesOnlyAsItsSubstepShrinks's last step.
const Budget kBudgets[] = {
    {Method::kProjective, 1.0 / 60, 1, 5.0, 5.0, 5.0},
    {Method::kProjective, 1.0 / 240, 1, 1.0, 1.0, 1.0},
    {Method::kImplicit, 1.0 / 240, 1, 10.0, 5.0, 5.0},
};

class SolverBudget : public ::testing::TestWithParam<Budget> {};

TEST_P(SolverBudget, ErrorRelativeToTheMotionStaysWithinBudget) {
  const Budget b = GetParam();
  const auto& ref = reference();
  const auto run = ref.heart.run(ref.heart.model(b.method, b.dt_s, b.substeps), b.dt_s);
  const double rms = error_pct_of_motion(run.x, ref.run.x);
  EXPECT_LT(rms, b.rms_pct);
  for (int band = 0; band < 2; ++band) {
    const SignalAgreement a = compare_signals(run.band[band], ref.run.band[band], test::SmallHeart::kBeatHz, 60);
    EXPECT_LT(std::abs(a.amplitude_error_pct), b.amplitude_pct) << "band " << band;
    EXPECT_LT(std::abs(a.phase_lag_ms), b.phase_ms) << "band " << band;
  }
  std::printf("%s %.5g s x%d: %.2f %% of the motion\n", method_name(b.method), b.dt_s, b.substeps, rms);
}

INSTANTIATE_TEST_SUITE_P(Documented, SolverBudget, ::testing::ValuesIn(kBudgets), [](const auto& info) {
  const Budget& b = info.param;
  return std::string(method_name(b.method)) + "_" + std::to_string(std::lround(1 / b.dt_s)) + "_x" +
         std::to_string(b.substeps);
});

TEST(HeartLikeBody, XpbdConvergesOnlyAsItsSubstepShrinks) {
  // One Gauss-Seidel pass per substep, positions then dampers: the error falls with the
  // substep towards the same motion, but only below m / (k tau) (docs/accuracy.md).
  const auto& ref = reference();
  double previous = 1e9;
  for (int substeps : {128, 512, 2048}) {
    const auto run = ref.heart.run(ref.heart.model(Method::kXpbd, 1.0 / 240, substeps), 1.0 / 240);
    const double e = error_pct_of_motion(run.x, ref.run.x);
    EXPECT_LT(e, 0.6 * previous) << substeps << " substeps";
    previous = e;
  }
  EXPECT_LT(previous, 10.0);
}

}  // namespace
}  // namespace systole::sim

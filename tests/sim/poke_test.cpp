// ctest-labels: slow-under-sanitizers
// A self-driven body still reacts: a poke dents it where it lands, the dent spreads, and
// the body settles back into its own rhythm.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/model.h"
#include "sim/solvers/step.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

using sim::Method;

constexpr double kRadius = 0.05;
constexpr double kPokeStart = 2.0;

Model beating_ball(Method method, bool poked) {
  test::BeatingBall ball(2, 1.2, 0.12, kRadius);
  ball.top().drive.waveform = sim::Waveform::kCardiac;
  ball.pin_base(0.8);
  sim::BodyParams& body = ball.organ.body;
  body.mass_kg = 0.5;
  body.stiffness_N_per_m = 100;
  body.damping_s = 0.002;
  body.volume_stiffness_Pa = 3000;
  body.drag_per_s = 3;
  // Bending makes the shape unique: without it a thin membrane can settle into another
  // wrinkle pattern after a hard push and never quite return (measured: 2 mm for ever,
  // against 0.02 mm eight beats on with bending).
  body.bending_N_per_m = 20;
  ModelOptions& options = ball.options;
  options.solver.method = method;
  options.solver.substeps = method == Method::kExplicit ? 20 : method == Method::kXpbd ? 4 : 1;
  if (poked) {
    sim::InteractionParams poke;  // A 0.1 s push into the side of the ball.
    poke.at_m = Eigen::Vector3d(kRadius, 0, 0);
    poke.radius_m = 0.012;
    poke.force_N = Eigen::Vector3d(-3, 0, 0);
    poke.start_s = kPokeStart;
    poke.duration_s = 0.1;
    options.interactions.push_back(poke);
  }
  return ball.model();
}

class Poke : public ::testing::TestWithParam<Method> {};

TEST_P(Poke, DentsSpreadsAndSettlesBackIntoTheRhythm) {
  const Method method = GetParam();
  const Model calm = beating_ball(method, false);
  const Model poked = beating_ball(method, true);
  ASSERT_EQ(poked.pokes.size(), 1u);
  const auto& patch = poked.pokes[0].particles;
  State a = initial_state(calm), b = initial_state(poked);
  const double dt = 1.0 / 240;
  auto advance_to = [&](double t) {
    while (a.time_s < t - 1e-9) {
      step(calm, a, dt);
      step(poked, b, dt);
      ASSERT_FALSE(diagnose(poked, b).has_value());
    }
  };
  /// How concentrated the disturbance is: mean displacement (against the undisturbed run)
  /// on the poked patch over the mean on the whole body.
  auto concentration = [&] {
    const Eigen::VectorXd d = (b.x - a.x).colwise().norm().transpose();
    double on_patch = 0;
    for (int i : patch) on_patch += d[i] / patch.size();
    return on_patch / d.mean();
  };

  advance_to(kPokeStart);
  EXPECT_EQ((b.x - a.x).cwiseAbs().maxCoeff(), 0.0) << "identical until the poke";

  advance_to(kPokeStart + 0.05);
  double dent = 0;
  for (int i : patch) dent += (b.x.col(i) - a.x.col(i)).x() / patch.size();
  EXPECT_LT(dent, -2e-3) << method_name(method) << ": the patch is pushed in by over 2 mm";
  const double early = concentration();
  EXPECT_GT(early, 3.0) << "at first the dent is where the poke landed";

  advance_to(kPokeStart + 0.3);
  EXPECT_LT(concentration(), 0.7 * early) << "then it spreads over the body";

  // Five beats later the body is back in its own rhythm: over the whole sixth beat no
  // particle is further than 1% of the body's size from the undisturbed motion.
  advance_to(kPokeStart + 5 / 1.2);
  double residual = 0;
  while (a.time_s < kPokeStart + 6 / 1.2) {
    advance_to(a.time_s + 1.0 / 60);
    residual = std::max(residual, (b.x - a.x).colwise().norm().maxCoeff());
  }
  EXPECT_LT(residual, 0.01 * 2 * kRadius) << method_name(method);
}

INSTANTIATE_TEST_SUITE_P(Solvers, Poke,
                         ::testing::Values(Method::kXpbd, Method::kExplicit, Method::kImplicit, Method::kProjective),
                         [](const auto& info) { return std::string(method_name(info.param)); });

}  // namespace
}  // namespace systole::sim

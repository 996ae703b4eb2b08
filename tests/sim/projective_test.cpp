// Projective dynamics keeps state between steps (its factorized matrix, BDF2's history, the
// volume's Sherman-Morrison vector): a copied State must continue bit for bit, and a State
// stepped by a model of another material must not reuse the old factors.

#include <gtest/gtest.h>

#include "sim/model.h"
#include "sim/solvers/step.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

Model ball_model(double stiffness_scale = 1) {
  test::BeatingBall ball(2);
  ball.options.solver.method = Method::kProjective;
  ball.options.solver.substeps = 1;
  ball.top().stiffness_scale = stiffness_scale;
  return ball.model();
}

TEST(Projective, ACopiedStateContinuesBitForBit) {
  const Model m = ball_model();
  State s = initial_state(m);
  for (int k = 0; k < 7; ++k) step(m, s, 1.0 / 60);  // Mid-way between two refreshes of the volume's vector.
  State copy = s;
  for (int k = 0; k < 9; ++k) {
    step(m, s, 1.0 / 60);
    step(m, copy, 1.0 / 60);
  }
  EXPECT_EQ((s.x - copy.x).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((s.v - copy.v).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT((s.x - m.rest_positions).cwiseAbs().maxCoeff(), 1e-4) << "the ball moved";
}

TEST(Projective, AnotherMaterialIsNotSolvedWithTheOldFactors) {
  const Model soft = ball_model(1), stiff = ball_model(5);
  State s = initial_state(soft);
  for (int k = 0; k < 5; ++k) step(soft, s, 1.0 / 60);
  State fresh = s;
  fresh.solver_cache.reset(nullptr);  // Nothing kept: the stiff model's own factors.
  step(stiff, s, 1.0 / 60);
  step(stiff, fresh, 1.0 / 60);
  EXPECT_EQ((s.x - fresh.x).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace systole::sim

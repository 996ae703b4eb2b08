// ctest-labels: no-sanitizers
// The same model and inputs give a bit-identical State at 1 and 2 threads, for every solver.

#include <gtest/gtest.h>

#include <cstring>

#include "sim/model.h"
#include "sim/solvers/step.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

using sim::Method;

Model ball(Method method, int threads) {
  test::BeatingBall ball(4, 1.2, 0.12);  // 2,562 particles: colours big enough to split.
  ball.top().drive.waveform = sim::Waveform::kCardiac;
  ball.organ.body.bending_N_per_m = 50;
  ball.organ.body.stiffness_N_per_m = 100;  // Soft and lightly damped, so 100 us explicit substeps are stable.
  ball.organ.body.damping_s = 0.0005;
  ball.options.solver.method = method;
  ball.options.solver.substeps = method == Method::kExplicit ? 40 : method == Method::kXpbd ? 4 : 1;
  ball.options.solver.threads = threads;
  return ball.model();
}

State run(const Model& m, int steps) {
  State s = initial_state(m);
  for (int i = 0; i < steps; ++i) step(m, s, 1.0 / 240);
  return s;
}

bool same_bits(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

class ThreadDeterminism : public ::testing::TestWithParam<Method> {};

TEST_P(ThreadDeterminism, OneAndTwoThreadsGiveTheSameBits) {
  const Model one = ball(GetParam(), 1), two = ball(GetParam(), 2);
  int largest_colour = 0;
  for (int c = 0; c < one.springs.colors(); ++c)
    largest_colour = std::max(largest_colour, one.springs.color_begin[c + 1] - one.springs.color_begin[c]);
  ASSERT_GT(largest_colour, 512) << "colours must be large enough to be split between threads";

  const int steps = 12;  // 50 ms: into the first contraction.
  const State a = run(one, steps), b = run(two, steps), c = run(two, steps);
  EXPECT_GT((a.x - one.rest_positions).cwiseAbs().maxCoeff(), 1e-6) << "the body moved";
  EXPECT_TRUE(same_bits(a.x, b.x)) << "positions at 1 and 2 threads";
  EXPECT_TRUE(same_bits(a.v, b.v)) << "velocities at 1 and 2 threads";
  EXPECT_TRUE(same_bits(b.x, c.x)) << "two runs at 2 threads";
}

INSTANTIATE_TEST_SUITE_P(Solvers, ThreadDeterminism,
                         ::testing::Values(Method::kXpbd, Method::kExplicit, Method::kImplicit, Method::kProjective),
                         [](const auto& info) { return std::string(method_name(info.param)); });

}  // namespace
}  // namespace systole::sim

// ctest-labels: slow-under-sanitizers
// The implicit (backward Euler) solver on the beating ball: rest, pins, drive, stability,
// convergence, determinism, grabs. Its kernels: implicit_kernels_test.cpp.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <numbers>

#include "sim/forces.h"
#include "sim/model.h"
#include "sim/solvers/implicit_euler.h"
#include "sim/solvers/step.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

/// A 5 cm sphere whose upper half is one driven region (support/beating_ball.h), stepped
/// by the implicit solver.
struct Ball : test::BeatingBall {
  explicit Ball(double rate_hz = 1.5, double amplitude = 0.15, int levels = 3) : BeatingBall(levels, rate_hz, amplitude) {
    options.solver.method = sim::Method::kImplicit;
  }
};

State run(const Model& m, double dt, double seconds) {
  State s = initial_state(m);
  const int steps = static_cast<int>(std::lround(seconds / dt));
  for (int i = 0; i < steps; ++i) step(m, s, dt);
  return s;
}

/// Largest particle distance between two states. unit: m
double max_distance(const State& a, const State& b) { return (a.x - b.x).colwise().norm().maxCoeff(); }

TEST(Implicit, AtRestWithoutDriveNothingMoves) {
  Ball ball;
  ball.organ.regions[0].drive.waveform = sim::Waveform::kNone;
  const Model m = ball.model();
  const State s = run(m, 1.0 / 240, 1.0);
  EXPECT_LT((s.x - m.rest_positions).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Implicit, PinnedParticlesStayPut) {
  Ball ball(1.5, 0.3);
  sim::RegionParams pin;
  pin.name = "pin";
  pin.pinned = true;
  ball.organ.regions.push_back(pin);
  for (std::size_t i = 0; i < ball.geometry.vertex_region.size(); ++i) {
    if (ball.geometry.mesh.surface.positions[i].y() < -0.04) ball.geometry.vertex_region[i] = 1;
  }
  ball.organ.body.volume_stiffness_Pa = 1e6;  // Exercise Sherman-Morrison with pinned rows.
  const Model m = ball.model();
  ASSERT_TRUE(m.volume.enabled);
  const State s = run(m, 1.0 / 60, 1.0);
  int pinned = 0;
  for (int i = 0; i < m.particle_count(); ++i) {
    if (m.vertex_region[i] != 1) continue;
    ++pinned;
    EXPECT_EQ(s.x.col(i), m.rest_positions.col(i));
  }
  EXPECT_GT(pinned, 0);
  EXPECT_GT((s.x - m.rest_positions).cwiseAbs().maxCoeff(), 1e-3) << "the rest moves";
}

TEST(Implicit, DrivePeriodShowsInTheVolume) {
  Ball ball(1.5, 0.15, 2);
  ball.organ.body.volume_stiffness_Pa = 2000;
  ball.options.solver.substeps = 1;
  const Model m = ball.model();
  const double dt = 1.0 / 60;
  const int settle = 60, n = 60 * 4;  // 4 s = 6 periods after 1 s of settling.
  State s = initial_state(m);
  std::vector<double> v;
  for (int i = 0; i < settle + n; ++i) {
    step(m, s, dt);
    v.push_back(enclosed_volume(s.x, m.volume.triangles));
  }
  double mean = 0;
  for (int i = settle; i < settle + n; ++i) mean += v[i] / n;
  double best_f = 0, best_power = 0;
  for (double f = 0.25; f <= 6.0; f += 0.25) {
    std::complex<double> sum = 0;
    for (int i = 0; i < n; ++i) sum += (v[settle + i] - mean) * std::polar(1.0, -2 * std::numbers::pi * f * i * dt);
    if (std::norm(sum) > best_power) best_power = std::norm(sum), best_f = f;
  }
  EXPECT_DOUBLE_EQ(best_f, 1.5);
}

/// A stiff body (stiff springs, a nearly incompressible volume) at one frame per step: far
/// beyond the explicit solver's limit dt < 2 / omega_max, well within the implicit one's.
Ball stiff_ball() {
  Ball ball(1.2, 0.2);
  ball.organ.body.stiffness_N_per_m = 5000;
  ball.organ.body.volume_stiffness_Pa = 1e7;
  ball.options.solver.substeps = 1;
  return ball;
}

TEST(Implicit, StableAtAFrameStepWhereExplicitBlowsUp) {
  const double dt = 1.0 / 30;
  Ball ball = stiff_ball();
  ball.options.solver.method = sim::Method::kExplicit;
  const Model explicit_model = ball.model();
  ball.options.solver.method = sim::Method::kImplicit;
  const Model implicit_model = ball.model();

  State e = initial_state(explicit_model);
  bool explicit_diagnosed = false;
  for (int i = 0; i < 30 && !explicit_diagnosed; ++i) {
    step(explicit_model, e, dt);
    explicit_diagnosed = diagnose(explicit_model, e).has_value();
  }
  EXPECT_TRUE(explicit_diagnosed) << "the explicit solver should blow up at dt = 1/30 s";

  State s = initial_state(implicit_model);
  const double v0 = implicit_model.volume.rest_m3;
  double worst_volume = 0, moved = 0;
  for (int i = 0; i < 90; ++i) {
    step(implicit_model, s, dt);
    const auto d = diagnose(implicit_model, s);
    ASSERT_FALSE(d.has_value()) << "step " << i << ": " << *d;
    worst_volume = std::max(worst_volume, std::abs(enclosed_volume(s.x, implicit_model.volume.triangles) / v0 - 1));
    moved = std::max(moved, (s.x - implicit_model.rest_positions).colwise().norm().maxCoeff());
  }
  EXPECT_LT(worst_volume, 0.01) << "the stiff volume holds (Sherman-Morrison keeps it implicit)";
  EXPECT_GT(moved, 1e-3) << "the drive still moves the body";
  EXPECT_LT(moved, 0.05) << "and the motion stays organ-sized";
  EXPECT_EQ(s.solver_cache.get<ImplicitCache>()->unconverged_solves, 0);
}

TEST(Implicit, ErrorShrinksWithTheStep) {
  // Positions after 0.25 s at dt, 2 dt, 4 dt against a 1/7680 s reference of the same solver:
  // backward Euler is first order, so halving the step about halves the error.
  Ball ball(2.0, 0.2, 2);
  ball.options.solver.substeps = 1;
  const Model m = ball.model();
  const double t = 0.25;
  const State reference = run(m, 1.0 / 7680, t);
  const double e1 = max_distance(run(m, 1.0 / 960, t), reference);
  const double e2 = max_distance(run(m, 1.0 / 480, t), reference);
  const double e4 = max_distance(run(m, 1.0 / 240, t), reference);
  EXPECT_LT(e1, e2);
  EXPECT_LT(e2, e4);
  EXPECT_GT(e2 / e1, 1.6) << e1 << " " << e2 << " " << e4;
  EXPECT_GT(e4 / e2, 1.6) << e1 << " " << e2 << " " << e4;

  // And the limit is the explicit solver's: the same forces, integrated another way.
  Ball explicit_ball = ball;
  explicit_ball.options.solver.method = sim::Method::kExplicit;
  explicit_ball.options.solver.auto_substeps = true;  // Its stability limit, not the implicit's step.
  explicit_ball.options.dt_s = 1.0 / 7680;
  const State explicit_reference = run(explicit_ball.model(), 1.0 / 7680, t);
  const double motion = (reference.x - m.rest_positions).colwise().norm().maxCoeff();
  // The 1/7680 s reference is itself first order: about e1 / 8 from the limit.
  EXPECT_LT(max_distance(explicit_reference, reference), 0.2 * e1) << "motion " << motion;
}

TEST(Implicit, AgreesWithXpbdAsTheStepShrinks) {
  // XPBD solves the same springs and volume as constraints; both tend to the same motion.
  Ball ball(2.0, 0.2, 2);
  const double t = 0.25;
  ball.options.solver.substeps = 1;
  const Model implicit_model = ball.model();
  ball.options.solver.method = sim::Method::kXpbd;
  const Model xpbd_model = ball.model();
  std::vector<double> gap;
  double motion = 0;
  for (double dt : {1.0 / 960, 1.0 / 3840, 1.0 / 15360}) {
    const State a = run(implicit_model, dt, t), b = run(xpbd_model, dt, t);
    gap.push_back(max_distance(a, b));
    motion = (a.x - implicit_model.rest_positions).colwise().norm().maxCoeff();
  }
  ASSERT_GT(motion, 1e-3);
  EXPECT_LT(gap[1], gap[0]);
  EXPECT_LT(gap[2], gap[1]);
  EXPECT_LT(gap[2], 0.1 * motion) << gap[0] << " " << gap[1] << " " << gap[2];
}

TEST(Implicit, StepSolvesBackwardEulerToSecondOrder) {
  // One step from a perturbed rest state: the linearized step leaves a backward-Euler
  // residual M (v1 - v0) - h f(x1, v1) of second order in the perturbation. A wrong or
  // missing Jacobian (the volume's rank-one term, a spring block) would leave first order.
  Ball ball(1.5, 0.0, 2);
  ball.organ.regions[0].drive.waveform = sim::Waveform::kNone;
  ball.organ.body.drag_per_s = 0;
  ball.organ.body.volume_stiffness_Pa = 1e6;
  ball.options.solver.substeps = 1;
  const Model m = ball.model();
  const double h = 1.0 / 60;
  auto residual = [&](double eps) {
    State s = initial_state(m);
    for (int i = 0; i < m.particle_count(); ++i) {
      const double a = 0.7 * i, b = 1.3 * i;
      s.x.col(i) += eps * Eigen::Vector3d(std::sin(a), std::cos(b), std::sin(a + b));
      s.v.col(i) = eps / h * Eigen::Vector3d(std::cos(a), std::sin(b), std::cos(a - b));
    }
    const Eigen::Matrix3Xd v0 = s.v;
    Eigen::Matrix3Xd f(3, m.particle_count());
    internal_and_scripted_forces(m, s.x, s.v, s.time_s, s, f);
    const double scale = h * f.colwise().norm().maxCoeff();  // The first-order terms' size. unit: N s
    step(m, s, h);
    internal_and_scripted_forces(m, s.x, s.v, s.time_s, s, f);
    double worst = 0;
    for (int i = 0; i < m.particle_count(); ++i) {
      worst = std::max(worst, (1.0 / m.inverse_mass[i] * (s.v.col(i) - v0.col(i)) - h * f.col(i)).norm());
    }
    return std::pair{worst, scale};
  };
  const auto [r1, s1] = residual(1e-4);
  const auto [r2, s2] = residual(2e-4);
  EXPECT_LT(r1, 1e-2 * s1);
  EXPECT_LT(r2, 2e-2 * s2);
  EXPECT_GT(r2 / r1, 3.5) << "second order: doubling the perturbation quadruples the residual";
}

TEST(Implicit, SameInputsGiveBitIdenticalStates) {
  const Model m = Ball(1.5, 0.15, 2).model();
  State a = initial_state(m), b = initial_state(m);
  for (int i = 0; i < 50; ++i) step(m, a, 1.0 / 240);
  for (int i = 0; i < 50; ++i) step(m, b, 1.0 / 240);
  EXPECT_EQ(std::memcmp(a.x.data(), b.x.data(), sizeof(double) * a.x.size()), 0);
  // A copied state (with its solver cache) steps on its own to the same result.
  State c = a;
  for (int i = 0; i < 50; ++i) step(m, a, 1.0 / 240);
  for (int i = 0; i < 50; ++i) step(m, c, 1.0 / 240);
  EXPECT_EQ(std::memcmp(a.x.data(), c.x.data(), sizeof(double) * a.x.size()), 0);
  EXPECT_EQ(std::memcmp(a.v.data(), c.v.data(), sizeof(double) * a.v.size()), 0);
}

TEST(Implicit, GrabPullsItsPatchTowardsTheHandle) {
  Ball ball;
  ball.organ.regions[0].drive.waveform = sim::Waveform::kNone;
  sim::InteractionParams grab;
  grab.kind = sim::InteractionKind::kGrab;
  grab.at_m = Eigen::Vector3d(0.05, 0, 0);
  grab.radius_m = 0.012;
  grab.path = {{0.0, Eigen::Vector3d(0.05, 0, 0)}, {0.5, Eigen::Vector3d(0.07, 0, 0)}};
  ball.options.interactions.push_back(grab);
  const Model m = ball.model();
  ASSERT_EQ(m.grabs.size(), 1u);
  const State s = run(m, 1.0 / 60, 0.5);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(), rest = Eigen::Vector3d::Zero();
  for (int i : m.grabs[0].particles) centre += s.x.col(i), rest += m.rest_positions.col(i);
  centre /= double(m.grabs[0].particles.size());
  rest /= double(m.grabs[0].particles.size());
  EXPECT_GT(centre.x() - rest.x(), 0.5 * 0.02) << "the patch follows the handle most of the way";
  EXPECT_LT(std::abs(centre.y() - rest.y()) + std::abs(centre.z() - rest.z()), 0.005);
}

}  // namespace
}  // namespace systole::sim

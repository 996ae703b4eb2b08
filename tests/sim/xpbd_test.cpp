#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <numbers>

#include "sim/model.h"
#include "sim/solvers/step.h"
#include "support/beating_ball.h"

namespace systole::sim {
namespace {

/// A 5 cm sphere whose upper half is one driven region (support/beating_ball.h).
struct Ball : test::BeatingBall {
  explicit Ball(double rate_hz = 1.5, double amplitude = 0.15) : BeatingBall(3, rate_hz, amplitude) {}
};

/// Volume after each of `steps` steps.
std::vector<double> volume_series(const Model& m, int steps, double dt) {
  State s = initial_state(m);
  std::vector<double> v;
  for (int i = 0; i < steps; ++i) {
    step(m, s, dt);
    v.push_back(enclosed_volume(s.x, m.volume.triangles.empty() ? std::vector<Eigen::Vector3i>{} : m.volume.triangles));
  }
  return v;
}

TEST(Xpbd, SpringsAreColouredSoNoTwoOfAColourShareAParticle) {
  const Model m = Ball().model();
  ASSERT_GT(m.springs.colors(), 1);
  for (int c = 0; c < m.springs.colors(); ++c) {
    std::vector<int> seen(m.particle_count(), 0);
    for (int j = m.springs.color_begin[c]; j < m.springs.color_begin[c + 1]; ++j) {
      EXPECT_EQ(seen[m.springs.a[j]]++, 0);
      EXPECT_EQ(seen[m.springs.b[j]]++, 0);
    }
  }
}

TEST(Xpbd, AtRestWithoutDriveNothingMoves) {
  Ball ball;
  ball.organ.regions[0].drive.waveform = sim::Waveform::kNone;
  const Model m = ball.model();
  State s = initial_state(m);
  for (int i = 0; i < 240; ++i) step(m, s, 1.0 / 240);
  EXPECT_LT((s.x - m.rest_positions).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Xpbd, VolumeConstraintHoldsTheVolume) {
  Ball stiff;
  stiff.organ.body.volume_stiffness_Pa = 1e7;
  Ball none;
  none.organ.body.volume_stiffness_Pa = 0;
  const Model with_volume = stiff.model();
  Model without_volume = none.model();
  ASSERT_TRUE(with_volume.volume.enabled);
  ASSERT_FALSE(without_volume.volume.enabled);
  const double v0 = enclosed_volume(with_volume.rest_positions, with_volume.volume.triangles);
  // Measure both on the same triangles.
  without_volume.volume.triangles = with_volume.volume.triangles;
  double worst_with = 0, worst_without = 0;
  State a = initial_state(with_volume), b = initial_state(without_volume);
  for (int i = 0; i < 480; ++i) {
    step(with_volume, a, 1.0 / 240);
    step(without_volume, b, 1.0 / 240);
    worst_with = std::max(worst_with, std::abs(enclosed_volume(a.x, with_volume.volume.triangles) / v0 - 1));
    worst_without = std::max(worst_without, std::abs(enclosed_volume(b.x, with_volume.volume.triangles) / v0 - 1));
  }
  EXPECT_LT(worst_with, 0.01) << "a stiff volume constraint keeps the volume within 1%";
  EXPECT_GT(worst_without, 0.05) << "without it the contraction shrinks the ball";
}

TEST(Xpbd, DrivePeriodShowsInTheVolume) {
  Ball ball(1.5, 0.15);
  ball.organ.body.volume_stiffness_Pa = 2000;
  const Model m = ball.model();
  const double dt = 1.0 / 240;
  const int settle = 240, n = 240 * 4;  // 4 s = 6 periods after 1 s of settling.
  const auto v = volume_series(m, settle + n, dt);
  double mean = 0;
  for (int i = settle; i < settle + n; ++i) mean += v[i] / n;
  // The strongest frequency in the volume signal is the drive's.
  double best_f = 0, best_power = 0;
  for (double f = 0.25; f <= 6.0; f += 0.25) {
    std::complex<double> sum = 0;
    for (int i = 0; i < n; ++i) {
      sum += (v[settle + i] - mean) * std::polar(1.0, -2 * std::numbers::pi * f * i * dt);
    }
    if (std::norm(sum) > best_power) best_power = std::norm(sum), best_f = f;
  }
  EXPECT_DOUBLE_EQ(best_f, 1.5);
}

TEST(Xpbd, PinnedParticlesStayPut) {
  Ball ball(1.5, 0.3);
  sim::RegionParams pin;
  pin.name = "pin";
  pin.pinned = true;
  ball.organ.regions.push_back(pin);
  for (std::size_t i = 0; i < ball.geometry.vertex_region.size(); ++i) {
    if (ball.geometry.mesh.surface.positions[i].y() < -0.04) ball.geometry.vertex_region[i] = 1;
  }
  const Model m = ball.model();
  State s = initial_state(m);
  for (int i = 0; i < 240; ++i) step(m, s, 1.0 / 240);
  int pinned = 0;
  for (int i = 0; i < m.particle_count(); ++i) {
    if (m.vertex_region[i] != 1) continue;
    ++pinned;
    EXPECT_EQ(s.x.col(i), m.rest_positions.col(i));
  }
  EXPECT_GT(pinned, 0);
  EXPECT_GT((s.x - m.rest_positions).cwiseAbs().maxCoeff(), 1e-3) << "the rest moves";
}

TEST(Xpbd, SameInputsGiveBitIdenticalStates) {
  const Model m = Ball().model();
  State a = initial_state(m), b = initial_state(m);
  for (int i = 0; i < 100; ++i) step(m, a, 1.0 / 240);
  for (int i = 0; i < 100; ++i) step(m, b, 1.0 / 240);
  EXPECT_EQ(std::memcmp(a.x.data(), b.x.data(), sizeof(double) * a.x.size()), 0);
}

TEST(Health, NonFiniteStateIsDiagnosed) {
  const Model m = Ball().model();
  State s = initial_state(m);
  EXPECT_FALSE(diagnose(m, s).has_value());
  s.x(1, 7) = std::nan("");
  const auto d = diagnose(m, s);
  ASSERT_TRUE(d.has_value());
  EXPECT_NE(d->find("particle 7"), std::string::npos) << *d;
}

TEST(Health, ExplodedExtentIsDiagnosed) {
  const Model m = Ball().model();
  State s = initial_state(m);
  s.x.col(3) *= 100.0;
  const auto d = diagnose(m, s);
  ASSERT_TRUE(d.has_value());
  EXPECT_NE(d->find("rest size"), std::string::npos) << *d;
}

}  // namespace
}  // namespace systole::sim

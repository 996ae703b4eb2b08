// ctest-labels: slow-under-sanitizers
// Contact between bodies (sim/contact/): the geometry kernels against brute force, the
// broad phase against every triangle, and the properties of the response - surfaces kept
// apart, no energy gained, no force once apart, the same bits at 1 and 2 threads, and hard
// pairs that stay stable or are diagnosed.

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <random>

#include "sim/contact/geometry.h"
#include "sim/contact/spatial_hash.h"
#include "support/two_bodies.h"

namespace systole::sim::contact {
namespace {

using test::TwoBodies;

Eigen::Matrix3Xd positions(const mesh::TriangleMesh& m) {
  Eigen::Matrix3Xd y(3, static_cast<Eigen::Index>(m.positions.size()));
  for (std::size_t i = 0; i < m.positions.size(); ++i) y.col(static_cast<Eigen::Index>(i)) = m.positions[i];
  return y;
}

TEST(ContactGeometry, ClosestPointMatchesADenseSearchOverTheTriangle) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0.2, 0.9, 0.1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 2);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    const ClosestPoint cp = closest_on_triangle(p, a, b, c);
    EXPECT_NEAR(cp.bary.sum(), 1.0, 1e-12);
    EXPECT_GE(cp.bary.minCoeff(), -1e-12);
    const double found = (p - (cp.bary[0] * a + cp.bary[1] * b + cp.bary[2] * c)).norm();
    double best = 1e9;
    for (int i = 0; i <= 200; ++i)
      for (int j = 0; i + j <= 200; ++j) {
        const double s = i / 200.0, t = j / 200.0;
        best = std::min(best, (p - ((1 - s - t) * a + s * b + t * c)).norm());
      }
    EXPECT_LE(found, best + 1e-12) << "trial " << trial;
    EXPECT_GT(found, best - 0.01) << "trial " << trial;
  }
}

TEST(ContactGeometry, WindingNumberIsOneInsideAndZeroOutsideAClosedSurface) {
  const mesh::TriangleMesh sphere = test::icosphere(0.05, 2);
  const Eigen::Matrix3Xd y = positions(sphere);
  EXPECT_NEAR(winding_number(Eigen::Vector3d(0.01, -0.02, 0.03), y, sphere.triangles), 1.0, 1e-9);
  EXPECT_NEAR(winding_number(Eigen::Vector3d(0.06, 0.0, 0.0), y, sphere.triangles), 0.0, 1e-9);
}

TEST(ContactGeometry, PseudoNormalSignsEveryPointNearASphereCorrectly) {
  const mesh::TriangleMesh sphere = test::icosphere(0.05, 2);
  const Eigen::Matrix3Xd y = positions(sphere);
  Eigen::Matrix3Xd face, vertex;
  pseudo_normals(y, sphere.triangles, face, vertex);
  const auto neighbours = edge_neighbours(sphere.triangles, static_cast<int>(y.cols()));
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d dir = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    const double r = 0.05 + (trial % 2 ? 1 : -1) * 0.004;  // 4 mm outside or inside.
    const Eigen::Vector3d p = r * dir;
    double best = 1e9;
    int best_t = -1;
    ClosestPoint best_cp;
    for (std::size_t t = 0; t < sphere.triangles.size(); ++t) {
      const auto& tri = sphere.triangles[t];
      const ClosestPoint cp = closest_on_triangle(p, y.col(tri[0]), y.col(tri[1]), y.col(tri[2]));
      const double d = (p - (cp.bary[0] * y.col(tri[0]) + cp.bary[1] * y.col(tri[1]) + cp.bary[2] * y.col(tri[2]))).norm();
      if (d < best) best = d, best_t = static_cast<int>(t), best_cp = cp;
    }
    const auto& tri = sphere.triangles[best_t];
    const Eigen::Vector3d q = best_cp.bary[0] * y.col(tri[0]) + best_cp.bary[1] * y.col(tri[1]) + best_cp.bary[2] * y.col(tri[2]);
    const double sign = (p - q).dot(feature_normal(best_cp, best_t, sphere.triangles, neighbours, face, vertex));
    EXPECT_EQ(sign > 0, trial % 2 == 1) << "trial " << trial;
  }
}

TEST(ContactBroadPhase, AQueryFindsEveryTriangleWithinReach) {
  const mesh::TriangleMesh sphere = test::icosphere(0.05, 3);
  const Eigen::Matrix3Xd y = positions(sphere);
  const double reach = 0.006;
  TriangleGrid grid;
  grid.build(y, sphere.triangles, 0.012, reach);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.06, 0.06);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    const auto [first, last] = grid.candidates(p);
    for (std::size_t t = 0; t < sphere.triangles.size(); ++t) {
      const auto& tri = sphere.triangles[t];
      const ClosestPoint cp = closest_on_triangle(p, y.col(tri[0]), y.col(tri[1]), y.col(tri[2]));
      const double d = (p - (cp.bary[0] * y.col(tri[0]) + cp.bary[1] * y.col(tri[1]) + cp.bary[2] * y.col(tri[2]))).norm();
      if (d > reach) continue;
      ++checked;
      EXPECT_TRUE(std::binary_search(first, last, static_cast<int>(t))) << "triangle " << t << " at " << d << " m";
    }
  }
  EXPECT_GT(checked, 100);
}

/// Ball a above ball b, 1 mm apart, moving together at `speed_m_per_s` each.
TwoBodies approaching(Method method, double speed_m_per_s, int threads = 1) {
  const Eigen::Vector3d centre[2] = {{0, 0.031, 0}, {0, -0.031, 0}};
  const double radius[2] = {0.03, 0.03}, k[2] = {400, 400}, mass[2] = {0.2, 0.2};
  TwoBodies t(method, centre, radius, k, mass, 0.002, 0.1, threads);
  t.state[0].v.colwise() = Eigen::Vector3d(0, -speed_m_per_s, 0);
  t.state[1].v.colwise() = Eigen::Vector3d(0, speed_m_per_s, 0);
  return t;
}

class ContactResponse : public ::testing::TestWithParam<Method> {};

TEST_P(ContactResponse, PressedTogetherTheySettleApartWithoutStickingJitterOrEnergyGain) {
  TwoBodies t = approaching(GetParam(), 0.3);
  const double start_energy = t.kinetic_energy();
  double most_energy_after_impact = 0, deepest = 0;
  int last_pushed_step = -1;
  for (int k = 0; k < 180; ++k) {  // 3 s.
    t.step(1.0 / 60);
    if (k >= 10) most_energy_after_impact = std::max(most_energy_after_impact, t.kinetic_energy());
    if (t.work.stats.active > 0) last_pushed_step = k;
    deepest = std::max(deepest, deepest_inside_m(t.bodies, t.params.pairs[0]));
  }
  EXPECT_LT(most_energy_after_impact, start_energy) << "contact must not add energy";
  EXPECT_LT(t.kinetic_energy(), 0.05 * start_energy) << "the motion after release decays";
  EXPECT_LE(deepest, 0.002) << "no vertex deeper than the thickness";
  // Apart at the end, and no contact has pushed since they separated: no sticking force.
  EXPECT_GT(t.gap_m(), 0.002);
  EXPECT_LT(last_pushed_step, 150) << "a force acted after the surfaces had separated";
  EXPECT_EQ(t.work.stats.active, 0);
}

INSTANTIATE_TEST_SUITE_P(Solvers, ContactResponse, ::testing::Values(Method::kXpbd, Method::kProjective),
                         [](const auto& info) { return std::string(method_name(info.param)); });

bool same_bits(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

TEST(ContactDeterminism, OneAndTwoThreadsGiveTheSameBits) {
  TwoBodies one = approaching(Method::kXpbd, 0.3, 1), two = approaching(Method::kXpbd, 0.3, 2);
  ASSERT_GT(one.state[0].x.cols(), 256) << "enough vertices for the detection to be split between threads";
  int pushed = 0;
  for (int k = 0; k < 20; ++k) {
    one.step(1.0 / 60);
    two.step(1.0 / 60);
    pushed += one.work.stats.active;
  }
  EXPECT_GT(pushed, 0) << "the bodies touched";
  for (int b = 0; b < 2; ++b) {
    EXPECT_TRUE(same_bits(one.state[b].x, two.state[b].x)) << "positions of body " << b;
    EXPECT_TRUE(same_bits(one.state[b].v, two.state[b].v)) << "velocities of body " << b;
  }
}

/// Whether a run of `steps` stayed healthy and apart, or stopped with a diagnosis: the two
/// outcomes the health check allows (never a silent blow-up).
struct Outcome {
  bool diagnosed = false;
  std::string message;
  double deepest_m = 0;
};

Outcome run_hard(TwoBodies& t, int steps) {
  Outcome out;
  for (int k = 0; k < steps; ++k) {
    t.step(1.0 / 60);
    for (int b = 0; b < 2; ++b) {
      if (auto problem = diagnose(t.model[b], t.state[b])) {
        out.diagnosed = true;
        out.message = *problem;
        return out;
      }
    }
    out.deepest_m = std::max(out.deepest_m, deepest_inside_m(t.bodies, t.params.pairs[0]));
  }
  return out;
}

TEST(ContactHardCases, StiffnessRatioOf1e4StaysApart) {
  const Eigen::Vector3d centre[2] = {{0, 0.031, 0}, {0, -0.031, 0}};
  const double radius[2] = {0.03, 0.03}, k[2] = {40, 4e5}, mass[2] = {0.2, 0.2};
  TwoBodies t(Method::kXpbd, centre, radius, k, mass);
  t.state[0].v.colwise() = Eigen::Vector3d(0, -0.3, 0);
  const Outcome o = run_hard(t, 90);
  ASSERT_FALSE(o.diagnosed) << o.message;
  EXPECT_LE(o.deepest_m, 0.002);
}

TEST(ContactHardCases, AThinBodyPressedByAHeavyOneStaysApartOrIsDiagnosed) {
  // A 2 kg ball falling at 0.5 m/s onto a 6 mm thin disc held still (a static collider).
  const Eigen::Vector3d centre[2] = {{0, 0.031, 0}, {0, -0.004, 0}};
  const double radius[2] = {0.03, 0.05}, k[2] = {400, 400}, mass[2] = {2.0, 0.1};
  const bool movable[2] = {true, false};
  TwoBodies t(Method::kXpbd, centre, radius, k, mass, 0.002, 0.1, 1, movable, 0.06);
  t.state[0].v.colwise() = Eigen::Vector3d(0, -0.5, 0);
  const Outcome o = run_hard(t, 60);
  if (o.diagnosed) {
    EXPECT_FALSE(o.message.empty());
    std::cout << "diagnosed: " << o.message << "\n";
  } else {
    EXPECT_LE(o.deepest_m, 0.002) << "the ball went into the disc undiagnosed";
  }
}

TEST(ContactHardCases, AFastDriveAgainstAWallIsStoppedOrDiagnosed) {
  // A ball thrown at 3 m/s (5 cm a step) against a static wall.
  const Eigen::Vector3d centre[2] = {{0, 0.031, 0}, {0, -0.031, 0}};
  const double radius[2] = {0.03, 0.03}, k[2] = {400, 400}, mass[2] = {0.2, 0.2};
  const bool movable[2] = {true, false};
  TwoBodies t(Method::kXpbd, centre, radius, k, mass, 0.002, 0.1, 1, movable);
  t.state[0].v.colwise() = Eigen::Vector3d(0, -3.0, 0);
  const Outcome o = run_hard(t, 60);
  if (o.diagnosed) {
    EXPECT_FALSE(o.message.empty());
    std::cout << "diagnosed: " << o.message << "\n";
  } else {
    EXPECT_LE(o.deepest_m, 0.002) << "the ball passed into the wall undiagnosed";
  }
}

}  // namespace
}  // namespace systole::sim::contact

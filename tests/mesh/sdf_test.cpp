// Signed distance fields for procedural organs (mesh/procedural/sdf.h): the primitives'
// distances where they are known exactly, the smooth minimum's bounds, and the field's
// union, carving, gradient and ownership.

#include "mesh/procedural/sdf.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace systole::mesh::procedural {
namespace {

/// Points spread over a cube of half-side `half` about `centre` (a fixed lattice).
std::vector<Eigen::Vector3d> samples(const Eigen::Vector3d& centre, double half) {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      for (int k = 0; k < 7; ++k)
        out.push_back(centre + half * Eigen::Vector3d(i / 3.0 - 1, j / 3.0 - 1.03, k / 3.0 - 0.97));
  return out;
}

double segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (p - (a + t * (b - a))).norm();
}

TEST(Sdf, AnEllipsoidWithEqualRadiiIsASphereExactly) {
  const Eigen::Vector3d c(0.01, -0.02, 0.03);
  const Primitive sphere = ellipsoid(0, c, axes_along(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d::UnitZ()),
                                     Eigen::Vector3d::Constant(0.04), 0);
  for (const Eigen::Vector3d& p : samples(c, 0.1)) EXPECT_NEAR(sphere.distance(p), (p - c).norm() - 0.04, 1e-12);
}

TEST(Sdf, AnEllipsoidIsZeroOnItsSurfaceNegativeInsidePositiveOutside) {
  const Eigen::Vector3d c(0.0, 0.01, 0.0), radii(0.05, 0.03, 0.02);
  const Eigen::Matrix3d axes = axes_along(Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 0, 1));
  const Primitive e = ellipsoid(2, c, axes, radii, 0);
  EXPECT_EQ(e.part, 2);
  EXPECT_EQ(e.kind, Primitive::Kind::kEllipsoid);
  for (int i = 0; i < 50; ++i) {
    const double theta = 0.3 + 0.05 * i, phi = 0.7 * i;
    const Eigen::Vector3d u(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    const Eigen::Vector3d on = c + axes * radii.cwiseProduct(u);
    EXPECT_NEAR(e.distance(on), 0.0, 1e-12);
    EXPECT_LT(e.distance(c + axes * radii.cwiseProduct(0.9 * u)), 0.0);
    EXPECT_GT(e.distance(c + axes * radii.cwiseProduct(1.1 * u)), 0.0);
  }
  // Along an axis, the distance to the surface is exact.
  EXPECT_NEAR(e.distance(c + 0.08 * axes.col(0)), 0.03, 1e-12);
  EXPECT_NEAR(e.distance(c + 0.01 * axes.col(2)), -0.01, 1e-12);
  EXPECT_NEAR(e.distance(c), -0.02, 1e-12);  // The centre: the least radius in.
}

TEST(Sdf, ARoundConeOfEqualRadiiIsACapsule) {
  const Eigen::Vector3d a(0, 0, 0), b(0.02, 0.05, -0.01);
  const Primitive capsule = round_cone(1, a, 0.015, b, 0.015, 0);
  EXPECT_EQ(capsule.kind, Primitive::Kind::kRoundCone);
  for (const Eigen::Vector3d& p : samples(0.5 * (a + b), 0.08)) {
    EXPECT_NEAR(capsule.distance(p), segment_distance(p, a, b) - 0.015, 1e-12) << p.transpose();
  }
}

TEST(Sdf, ARoundConeIsItsEndSpheresBeyondItsEnds) {
  // Far beyond each end, along the axis, the nearest surface is that end's sphere.
  const Eigen::Vector3d a(0, 0, 0), b(0, 0, 0.1);
  const Primitive cone = round_cone(0, a, 0.03, b, 0.01, 0);
  EXPECT_NEAR(cone.distance(Eigen::Vector3d(0, 0, -0.05)), 0.05 - 0.03, 1e-12);
  EXPECT_NEAR(cone.distance(Eigen::Vector3d(0, 0, 0.15)), 0.05 - 0.01, 1e-12);
  EXPECT_LT(cone.distance(Eigen::Vector3d(0, 0, 0.05)), 0.0);
  // Between the ends the radius tapers: a point 0.025 from the axis is inside near a, outside near b.
  EXPECT_LT(cone.distance(Eigen::Vector3d(0.025, 0, 0.005)), 0.0);
  EXPECT_GT(cone.distance(Eigen::Vector3d(0.025, 0, 0.095)), 0.0);
}

TEST(Sdf, AxesAlongAreARightHandedFrameFacingTheWayAsked) {
  const Eigen::Vector3d along(0.3, -1.2, 0.4), towards(1, 1, 1);
  const Eigen::Matrix3d m = axes_along(along, towards);
  EXPECT_TRUE((m.transpose() * m).isIdentity(1e-12));
  EXPECT_NEAR(m.determinant(), 1.0, 1e-12);
  EXPECT_TRUE(m.col(0).isApprox(along.normalized(), 1e-12));
  // The second axis is `towards` without its part along the first.
  const Eigen::Vector3d rest = (towards - towards.dot(m.col(0)) * m.col(0)).normalized();
  EXPECT_TRUE(m.col(1).isApprox(rest, 1e-12));
}

TEST(Sdf, SmoothMinIsTheMinimumFarApartAndNeverAboveIt) {
  const double k = 0.01;
  EXPECT_EQ(smooth_min(0.3, 0.1, k), 0.1);
  EXPECT_EQ(smooth_min(-0.2, 0.5, k), -0.2);
  EXPECT_EQ(smooth_min(0.004, 0.001, 0), 0.001);  // k = 0: the hard minimum.
  for (double x = -0.02; x <= 0.02; x += 0.0011) {
    for (double y = -0.02; y <= 0.02; y += 0.0013) {
      const double s = smooth_min(x, y, k);
      EXPECT_LE(s, std::min(x, y));
      EXPECT_GE(s, std::min(x, y) - 0.25 * k);  // At most k/4 below, where x = y.
      EXPECT_DOUBLE_EQ(s, smooth_min(y, x, k));
    }
  }
  EXPECT_DOUBLE_EQ(smooth_min(0.0, 0.0, k), -0.25 * k);
}

TEST(Sdf, AFieldIsTheUnionOfItsPrimitivesAndCarvingRemoves) {
  Field f;
  const Eigen::Vector3d c1(-0.1, 0, 0), c2(0.1, 0, 0);
  f.primitives.push_back(ellipsoid(0, c1, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.04), 0));
  f.primitives.push_back(ellipsoid(1, c2, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.03), 0));
  for (const Eigen::Vector3d& p : samples(Eigen::Vector3d::Zero(), 0.2)) {
    EXPECT_NEAR(f.distance(p), std::min((p - c1).norm() - 0.04, (p - c2).norm() - 0.03), 1e-12);
  }
  EXPECT_EQ(f.nearest_primitive(c1 + Eigen::Vector3d(0, 0.01, 0)), 0);
  EXPECT_EQ(f.nearest_primitive(c2 - Eigen::Vector3d(0.05, 0, 0)), 1);

  // A hollow: a smaller sphere carved out of the first.
  f.primitives.push_back(carved(ellipsoid(0, c1, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.02), 0)));
  EXPECT_TRUE(f.primitives.back().carve);
  EXPECT_NEAR(f.distance(c1), 0.02, 1e-12);                            // In the hole: outside.
  EXPECT_NEAR(f.distance(c1 + Eigen::Vector3d(0.03, 0, 0)), -0.01, 1e-12);  // In the shell.
  EXPECT_EQ(f.nearest_primitive(c1 + Eigen::Vector3d(0.03, 0, 0)), 0);

  // A carving primitive owns no surface, even where its own distance is the least.
  Field g;
  g.primitives.push_back(ellipsoid(0, c1, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.01), 0));
  g.primitives.push_back(carved(ellipsoid(1, c1, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.05), 0)));
  EXPECT_EQ(g.nearest_primitive(c1), 0);
}

TEST(Sdf, TheGradientOfASphereIsTheUnitRadial) {
  Field f;
  const Eigen::Vector3d c(0.01, 0.02, -0.03);
  f.primitives.push_back(ellipsoid(0, c, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.05), 0));
  for (const Eigen::Vector3d& p : samples(c + Eigen::Vector3d(0.001, 0, 0), 0.09)) {
    if ((p - c).norm() < 0.005) continue;
    EXPECT_TRUE(f.gradient(p).isApprox((p - c).normalized(), 1e-6)) << p.transpose();
  }
}

TEST(Sdf, BlendingFillsTheCreaseBetweenTwoSpheres) {
  // Two touching spheres: with a blend radius the saddle between them is inside the surface.
  Field hard, soft;
  const Eigen::Vector3d c1(-0.03, 0, 0), c2(0.03, 0, 0);
  for (Field* f : {&hard, &soft}) {
    f->primitives.push_back(ellipsoid(0, c1, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.03), 0));
    f->primitives.push_back(ellipsoid(0, c2, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.03),
                                      f == &soft ? 0.02 : 0.0));
  }
  const Eigen::Vector3d saddle(0, 0.005, 0);
  EXPECT_GT(hard.distance(saddle), 0.0);
  EXPECT_LT(soft.distance(saddle), 0.0);
  // Far from the crease the blend changes nothing.
  EXPECT_DOUBLE_EQ(soft.distance(Eigen::Vector3d(-0.07, 0, 0)), hard.distance(Eigen::Vector3d(-0.07, 0, 0)));
}

}  // namespace
}  // namespace systole::mesh::procedural

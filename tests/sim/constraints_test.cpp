// The constraint kernels alone: a distance projection restores the rest length, the volume
// gradient is the derivative of the volume, an attachment moves a particle by its share.

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "sim/constraints/attachment.h"
#include "sim/constraints/distance.h"
#include "sim/constraints/volume.h"
#include "support/shapes.h"

namespace systole::sim {
namespace {

TEST(DistanceConstraint, RigidProjectionRestoresTheRestLengthSymmetricallyForEqualMasses) {
  double a[3] = {0, 0, 0}, b[3] = {2, 0, 0};
  const double still[3] = {0, 0, 0};
  solve_distance(a, b, still, still, 1.0, 1.0, 1.0, 0.0, 0.0);
  EXPECT_NEAR(b[0] - a[0], 1.0, 1e-15);
  EXPECT_NEAR(a[0], 0.5, 1e-15);
  EXPECT_NEAR(b[0], 1.5, 1e-15);
}

TEST(DistanceConstraint, CompliancePullsOnlyPartWayAndAPinnedEndStays) {
  double a[3] = {0, 0, 0}, b[3] = {2, 0, 0};
  const double still[3] = {0, 0, 0};
  // alpha_tilde = w: C = 1, dlambda = -1 / (1 + 1): the free end moves half the error.
  const double dlambda = solve_distance(a, b, still, still, 0.0, 1.0, 1.0, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(dlambda, -0.5);
  EXPECT_DOUBLE_EQ(a[0], 0.0);
  EXPECT_DOUBLE_EQ(b[0], 1.5);
}

TEST(VolumeConstraint, GradientIsTheDerivativeOfTheEnclosedVolume) {
  const mesh::TriangleMesh sphere = test::icosphere(0.05, 2);
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(sphere.positions.size()));
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) x.col(static_cast<Eigen::Index>(i)) = sphere.positions[i];
  x(0, 3) += 0.004;  // Not the symmetric sphere: a generic point.
  Eigen::Matrix3Xd g(3, x.cols());
  const double v = volume_and_gradient(x, sphere.triangles, g);
  EXPECT_DOUBLE_EQ(v, enclosed_volume(x, sphere.triangles));
  const double h = 1e-7;
  for (const Eigen::Index i : {Eigen::Index(0), Eigen::Index(3), Eigen::Index(17)}) {
    for (int k = 0; k < 3; ++k) {
      Eigen::Matrix3Xd xp = x, xm = x;
      xp(k, i) += h;
      xm(k, i) -= h;
      const double fd = (enclosed_volume(xp, sphere.triangles) - enclosed_volume(xm, sphere.triangles)) / (2 * h);
      EXPECT_NEAR(g(k, i), fd, 1e-9 * std::abs(fd) + 1e-12) << i << "," << k;
    }
  }
}

TEST(VolumeConstraint, RigidProjectionRestoresTheVolumeToFirstOrder) {
  const mesh::TriangleMesh sphere = test::icosphere(0.05, 2);
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(sphere.positions.size()));
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) x.col(static_cast<Eigen::Index>(i)) = 0.999 * sphere.positions[i];
  const double v0 = enclosed_volume(x, sphere.triangles) / (0.999 * 0.999 * 0.999);
  Eigen::Matrix3Xd g(3, x.cols());
  const double before = volume_and_gradient(x, sphere.triangles, g) - v0;
  solve_volume(x, Eigen::VectorXd::Ones(x.cols()), g, before, 0.0, 0.0);
  const double after = enclosed_volume(x, sphere.triangles) - v0;
  EXPECT_LT(std::abs(after), 0.01 * std::abs(before));
}

TEST(AttachmentConstraint, MovesAFreeParticleByItsShareAndLeavesAPinnedOne) {
  Eigen::Vector3d x(1, 0, 0);
  const Eigen::Vector3d target(0, 0, 0);
  const Eigen::Vector3d dlambda = solve_attachment(x, target, 1.0, 1.0);  // w = alpha_tilde: halfway.
  EXPECT_DOUBLE_EQ(x.x(), 0.5);
  EXPECT_DOUBLE_EQ(dlambda.x(), -0.5);
  Eigen::Vector3d pinned(1, 0, 0);
  EXPECT_EQ(solve_attachment(pinned, target, 0.0, 1.0), Eigen::Vector3d::Zero());
  EXPECT_EQ(pinned, Eigen::Vector3d(1, 0, 0));
}

}  // namespace
}  // namespace systole::sim

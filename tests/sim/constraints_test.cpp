// The constraint kernels alone: a distance projection restores the rest length, the volume
// gradient is the derivative of the volume, an attachment moves a particle by its share, and
// a cell's embedded points pull its corners together, in no order.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>

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

/// One unit cell (corner k at the bits of k) holding `n`^3 points on a grid inside it, at
/// their trilinear weights.
struct Cell {
  Eigen::Matrix3Xd corners = Eigen::Matrix3Xd(3, 8);
  Embedding points;
  Eigen::Matrix3Xd rest;  ///< The points where the corners are now.
  Eigen::Matrix3Xd lambda = Eigen::Matrix3Xd::Zero(3, 8), pull = lambda;
  Eigen::VectorXd hold = Eigen::VectorXd::Zero(8);

  /// One pass of the cell's points towards `targets`.
  void solve(const Eigen::Matrix3Xd& targets, const Eigen::VectorXd& inverse_mass) {
    solve_embedded_attachments(corners, points, targets, inverse_mass, 0.0, lambda, pull, hold);
  }

  explicit Cell(int n) {
    for (int k = 0; k < 8; ++k) corners.col(k) = Eigen::Vector3d(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    const int count = n * n * n;
    points.node.resize(8, count);
    points.weight.resize(8, count);
    rest.resize(3, count);
    for (int v = 0; v < count; ++v) {
      const Eigen::Vector3d u((v % n + 0.5) / n, (v / n % n + 0.5) / n, (v / (n * n) + 0.5) / n);
      rest.col(v) = u;
      for (int k = 0; k < 8; ++k) {
        points.node(k, v) = k;
        points.weight(k, v) = (k & 1 ? u.x() : 1 - u.x()) * ((k >> 1) & 1 ? u.y() : 1 - u.y()) *
                              ((k >> 2) & 1 ? u.z() : 1 - u.z());
      }
    }
  }
};

TEST(EmbeddedAttachments, ACellFollowsItsPointsToWhereTheyAreAllAsked) {
  Cell cell(4);
  const Eigen::Vector3d shift(0.1, -0.2, 0.05);
  const Eigen::Matrix3Xd targets = cell.rest.colwise() + shift;
  for (int pass = 0; pass < 30; ++pass) cell.solve(targets, Eigen::VectorXd::Ones(8));
  Eigen::Matrix3Xd reached;
  embed(cell.points, cell.corners, reached);
  EXPECT_LT((reached - targets).colwise().norm().maxCoeff(), 1e-6 * shift.norm());
}

TEST(EmbeddedAttachments, PointsAreProjectedTogetherSoTheirOrderDoesNotMatter) {
  // Targets that disagree (noise about a shift): projected one after another, the last
  // points would have the corners their way; together, the order is only rounding.
  Cell cell(3);
  const Eigen::Matrix3Xd before = cell.corners;
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  Eigen::Matrix3Xd targets = cell.rest.colwise() + Eigen::Vector3d(0.1, 0, 0);
  for (Eigen::Index v = 0; v < targets.cols(); ++v) {
    targets.col(v) += Eigen::Vector3d(noise(random), noise(random), noise(random));
  }
  Cell reversed = cell;
  Eigen::Matrix3Xd reversed_targets = targets;
  const Eigen::Index n = targets.cols();
  for (Eigen::Index v = 0; v < n; ++v) {
    reversed.points.node.col(v) = cell.points.node.col(n - 1 - v);
    reversed.points.weight.col(v) = cell.points.weight.col(n - 1 - v);
    reversed_targets.col(v) = targets.col(n - 1 - v);
  }
  cell.solve(targets, Eigen::VectorXd::Ones(8));
  reversed.solve(reversed_targets, Eigen::VectorXd::Ones(8));
  EXPECT_LT((cell.corners - reversed.corners).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT((cell.corners.row(0) - before.row(0)).minCoeff(), 0.05);  // All moved along.
}

TEST(EmbeddedAttachments, APinnedCornerStaysAndEachMultiplierIsItsParticlesMove) {
  Cell cell(3);
  const Eigen::Matrix3Xd before = cell.corners;
  const Eigen::Matrix3Xd targets = cell.rest.colwise() + Eigen::Vector3d(0, 0, 0.2);
  Eigen::VectorXd inverse_mass = Eigen::VectorXd::Constant(8, 0.5);
  inverse_mass[0] = 0;
  cell.solve(targets, inverse_mass);
  EXPECT_EQ(cell.corners.col(0), before.col(0));
  EXPECT_GT(cell.lambda(2, 0), 0);  // The pinned corner still takes its share of the force.
  for (int k = 1; k < 8; ++k) {
    EXPECT_NEAR((cell.corners(2, k) - before(2, k)), inverse_mass[k] * cell.lambda(2, k), 1e-15);
    EXPECT_GT(cell.corners(2, k), before(2, k));
  }
}

}  // namespace
}  // namespace systole::sim

// The implicit solver's kernels: a spring's linearization against finite differences, its
// stiffness block's definiteness, the Sherman-Morrison update.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "sim/forces.h"
#include "sim/solvers/implicit_euler.h"

namespace systole::sim {
namespace {

TEST(ImplicitKernels, SpringJacobianMatchesFiniteDifferences) {
  const Eigen::Vector3d d(0.03, -0.01, 0.02), w(0.2, 0.1, -0.3);
  const double k = 400, c = 4, rest = 0.02;  // Stretched: the geometric term is not clamped.
  const SpringLinearization lin = linearize_spring(d, w, k, c, rest);
  const double eps = 1e-7;
  for (int col = 0; col < 3; ++col) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[col] = eps;
    // Moving b by e changes d by e; the stiffness block is the derivative at fixed w
    // without the damper's position term (dropped by design), so compare with c = 0.
    const Eigen::Vector3d fd =
        (linearize_spring(d + e, w, k, 0, rest).force_a_N - linearize_spring(d - e, w, k, 0, rest).force_a_N) /
        (2 * eps);
    EXPECT_LT((fd - lin.stiffness_N_per_m.col(col)).norm(), 1e-5 * k) << "column " << col;
    const Eigen::Vector3d fv =
        (linearize_spring(d, w + e, k, c, rest).force_a_N - linearize_spring(d, w - e, k, c, rest).force_a_N) /
        (2 * eps);
    EXPECT_LT((fv - lin.damping_N_s_per_m.col(col)).norm(), 1e-6 * c) << "column " << col;
  }
}

TEST(ImplicitKernels, CompressedSpringStiffnessStaysPositiveSemidefinite) {
  const SpringLinearization lin = linearize_spring(Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d::Zero(), 400, 4, 0.03);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(lin.stiffness_N_per_m);
  EXPECT_GE(eig.eigenvalues().minCoeff(), 0.0);
  EXPECT_DOUBLE_EQ(eig.eigenvalues().maxCoeff(), 400.0);
}

TEST(ImplicitKernels, ShermanMorrisonSolvesTheRankOneUpdate) {
  Eigen::Matrix3d a;
  a << 4, 1, 0, 1, 3, 1, 0, 1, 2;
  const Eigen::Vector3d u(1, -2, 0.5), b(0.3, 1, -2);
  Eigen::VectorXd y = a.llt().solve(b), z = a.llt().solve(u), uu = u;
  sherman_morrison_update(y, z, uu);
  const Eigen::Matrix3d full = a + u * u.transpose();
  EXPECT_LT((full * y - b).norm(), 1e-12);
}

}  // namespace
}  // namespace systole::sim

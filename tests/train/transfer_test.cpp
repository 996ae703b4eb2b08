// A target of another mesh laid on the organ (train/transfer.h): aligned whatever its
// placement and size, its motion carried onto the organ's vertices, what that loses
// measured, and a target that is not the organ refused.

#include "train/transfer.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "common/error.h"
#include "mesh/icosphere.h"
#include "sim/motion_error.h"

namespace systole::train {
namespace {

RestSurface ball(double radius, int levels) {
  const mesh::TriangleMesh m = mesh::icosphere(radius, levels);
  RestSurface s;
  s.positions.resize(3, static_cast<Eigen::Index>(m.positions.size()));
  for (std::size_t i = 0; i < m.positions.size(); ++i) s.positions.col(static_cast<Eigen::Index>(i)) = m.positions[i];
  s.triangles = m.triangles;
  return s;
}

/// An organ-like shape with no symmetry to confuse an alignment: the ball stretched along
/// each axis differently, with a lobe on one side.
RestSurface lumpy(int levels) {
  RestSurface s = ball(0.03, levels);
  for (Eigen::Index i = 0; i < s.positions.cols(); ++i) {
    Eigen::Vector3d p = s.positions.col(i);
    const double lobe = 0.4 * std::exp(-(p - Eigen::Vector3d(0.02, 0.02, 0.0)).squaredNorm() / (0.015 * 0.015));
    p = Eigen::Vector3d(1.5 * p.x(), p.y(), 0.7 * p.z()) * (1 + lobe);
    s.positions.col(i) = p;
  }
  return s;
}

/// A smooth, non-rigid motion at phase u: stretched along y, pinched in x, bent in z.
Eigen::Matrix3Xd deform(const Eigen::Matrix3Xd& p, double u) {
  const double s = std::sin(2 * M_PI * u);
  Eigen::Matrix3Xd out = p;
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    out(1, i) *= 1 + 0.2 * s;
    out(0, i) *= 1 - 0.1 * s;
    out(2, i) += 0.2 * s * p(1, i) * p(1, i) / 0.03;
  }
  return out;
}

/// The RMS of the difference of two motions (each about its rest), % of `truth`'s motion.
double motion_error_pct(const std::vector<Eigen::Matrix3Xd>& got, const std::vector<Eigen::Matrix3Xd>& truth) {
  double sum = 0, n = 0;
  for (std::size_t k = 0; k < got.size(); ++k) sum += (got[k] - truth[k]).squaredNorm(), n += double(got[k].cols());
  return 100 * std::sqrt(sum / n) / sim::rms_motion_m(truth);
}

TEST(Transfer, TheOrgansOwnMeshIsKeptWhereItIsAndItsMotionComesBackExactly) {
  const RestSurface organ = ball(0.03, 2);
  const Alignment a = align(organ, organ, AlignOptions{}, "own");
  EXPECT_LT(a.misfit, 1e-9);
  EXPECT_TRUE(a.linear.isIdentity(1e-12));
  const SurfaceBinding binding(organ, organ);
  Eigen::Matrix3Xd out;
  const Eigen::Matrix3Xd posed = deform(organ.positions, 0.25);
  binding.apply(posed, out);
  EXPECT_LT((out - posed).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(transfer_loss_pct(organ, {posed, deform(organ.positions, 0.75)}, organ, {posed, deform(organ.positions, 0.75)}), 1e-9);
}

TEST(Transfer, AFinerMeshMovedTurnedAndScaledIsAlignedAndItsMotionCarriedOver) {
  const RestSurface organ = lumpy(2);  // 162 vertices
  RestSurface target = lumpy(4);       // 2,562: another mesh of the same shape
  // Placed elsewhere, turned and 1.3 times as big (within the units' tolerance).
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(0.1, -0.05, 0.2);
  auto place = [&](const Eigen::Matrix3Xd& p) -> Eigen::Matrix3Xd { return ((1.3 * turn) * p).colwise() + shift; };
  RestSurface placed = target;
  placed.positions = place(target.positions);
  const Alignment a = align(placed, organ, AlignOptions{}, "ball");
  EXPECT_LT(a.misfit, 0.01) << a.how;
  EXPECT_NEAR(a.scale_vs_placed, 1 / 1.3, 0.01) << a.how;
  // The organ's vertices follow the target's deformation (the same field, laid on each mesh).
  RestSurface aligned = placed;
  aligned.positions = (a.linear * placed.positions).colwise() + a.offset;
  const SurfaceBinding binding(aligned, organ);
  std::vector<Eigen::Matrix3Xd> target_poses, organ_poses, truth;
  for (double u : {0.0, 0.25, 0.5, 0.75}) {
    target_poses.push_back((a.linear * place(deform(target.positions, u))).colwise() + a.offset);
    Eigen::Matrix3Xd out;
    binding.apply(target_poses.back(), out);
    organ_poses.push_back(out);
    truth.push_back(deform(organ.positions, u));
  }
  // Within a few % of the motion: the alignment's residue and the finer mesh's faceting.
  const double error = motion_error_pct(organ_poses, truth);
  EXPECT_LT(error, 5.0);
  const double loss = transfer_loss_pct(aligned, target_poses, organ, organ_poses);
  EXPECT_LT(loss, 10.0);
  EXPECT_GT(loss, 0.0) << "a coarser organ cannot carry the finer target's motion exactly";
  std::printf("aligned by %s, misfit %.4f %%, motion error %.3f %%, transfer loss %.3f %%\n", a.how.c_str(), 100 * a.misfit, error, loss);
}

TEST(Transfer, AnotherShapeIsRefusedNamingWhatWasCompared) {
  const RestSurface organ = ball(0.03, 2);
  RestSurface rod = ball(0.03, 2);
  for (Eigen::Index i = 0; i < rod.positions.cols(); ++i) rod.positions(1, i) *= 6, rod.positions(0, i) *= 0.2;
  try {
    align(rod, organ, AlignOptions{}, "rod.glb (the target of organ 'ball')");
    FAIL() << "a rod was laid on a ball";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kDataError);
    const std::string m = e.what();
    EXPECT_NE(m.find("rod.glb (the target of organ 'ball'): the target's surface cannot be laid on the organ's"), std::string::npos) << m;
    EXPECT_NE(m.find("the target's 162 rest vertices with the organ's 162 surface vertices"), std::string::npos) << m;
  }
}

TEST(Transfer, ATargetInOtherUnitsIsRefused) {
  const RestSurface organ = ball(0.03, 2);
  RestSurface in_mm = organ;
  in_mm.positions *= 1000;
  try {
    align(in_mm, organ, AlignOptions{}, "mm.glb");
    FAIL() << "a target 1000 times the organ's size was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("other units than the organ's mesh"), std::string::npos) << e.what();
  }
  // The same file declared in its units (its placement scaled) is taken as placed.
  AlignOptions options;
  options.placed_linear = 0.001 * Eigen::Matrix3d::Identity();
  const Alignment a = align(in_mm, organ, options, "mm.glb");
  EXPECT_LT(a.misfit, 1e-9);
  EXPECT_NEAR(a.scale_vs_placed, 1.0, 1e-12);
}

TEST(Transfer, AVertexBindsToItsOwnNamedPartBeforeANearerOne) {
  // Two balls side by side in the target; the organ's ball named "heart/left" lies nearer
  // the target's "right" ball, yet binds to "left" as named.
  RestSurface target = ball(0.03, 2);
  const Eigen::Index n = target.positions.cols();
  RestSurface two;
  two.positions.resize(3, 2 * n);
  two.positions.leftCols(n) = target.positions.colwise() + Eigen::Vector3d(-0.05, 0, 0);
  two.positions.rightCols(n) = target.positions.colwise() + Eigen::Vector3d(0.05, 0, 0);
  for (const auto& t : target.triangles) two.triangles.push_back(t), two.triangles.push_back(t + Eigen::Vector3i::Constant(static_cast<int>(n)));
  two.vertex_part_name.assign(static_cast<std::size_t>(n), "left");
  two.vertex_part_name.resize(static_cast<std::size_t>(2 * n), "right");
  RestSurface organ = ball(0.03, 2);
  organ.positions = organ.positions.colwise() + Eigen::Vector3d(0.04, 0, 0);
  organ.vertex_part_name.assign(static_cast<std::size_t>(n), "heart/left");
  const SurfaceBinding binding(two, organ);
  Eigen::Matrix3Xd moved = two.positions, out;
  moved.leftCols(n).colwise() += Eigen::Vector3d(0, 0.01, 0);  // Only the left ball moves.
  binding.apply(moved, out);
  EXPECT_NEAR((out - organ.positions).rowwise().mean()(1), 0.01, 1e-12);
  organ.vertex_part_name.assign(static_cast<std::size_t>(n), "");  // Unnamed: the nearest, the right ball.
  const SurfaceBinding unnamed(two, organ);
  unnamed.apply(moved, out);
  EXPECT_NEAR((out - organ.positions).rowwise().mean()(1), 0.0, 1e-12);
}

}  // namespace
}  // namespace systole::train

// Catmull-Rom: through every key, held outside the keys, periodic wrap-around, and the
// same kernel for scalars, vectors and matrices.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <vector>

#include "common/spline.h"

namespace systole {
namespace {

struct Key {
  double time_s;
  Eigen::Vector3d p;
};

TEST(Spline, KeyedCurvePassesThroughEveryKeyAndHoldsOutsideThem) {
  const std::vector<Key> keys = {{0, {0, 0, 0}}, {1, {1, 2, 0}}, {3, {0, 5, 1}}, {4, {2, 2, 2}}};
  auto at = [&](double t) { return keyed_curve(keys, t, [](const Key& k) -> const Eigen::Vector3d& { return k.p; }); };
  for (const Key& k : keys) EXPECT_LT((at(k.time_s) - k.p).norm(), 1e-12) << k.time_s;
  EXPECT_EQ(at(-5), keys.front().p);
  EXPECT_EQ(at(99), keys.back().p);
  // Between keys it moves smoothly: no jump either side of a key.
  EXPECT_LT((at(1 - 1e-6) - at(1 + 1e-6)).norm(), 1e-4);
}

TEST(Spline, SegmentOfCollinearEvenlySpacedPointsIsLinear) {
  for (double u : {0.0, 0.25, 0.5, 0.9}) EXPECT_NEAR(catmull_rom(0.0, 1.0, 2.0, 3.0, u), 1.0 + u, 1e-12);
}

TEST(Spline, PeriodicCurveWrapsAroundAndMatricesInterpolateLikeScalars) {
  const std::vector<double> s = {0.0, 1.0, 0.5, 0.2};
  EXPECT_DOUBLE_EQ(periodic_catmull_rom(s, 3, 0.0), 0.2);
  EXPECT_DOUBLE_EQ(periodic_catmull_rom(s, 3, 1.0), 0.0) << "the last segment ends at the first sample";
  Eigen::Matrix3Xd a = Eigen::Matrix3Xd::Constant(3, 2, s[3]), b = Eigen::Matrix3Xd::Constant(3, 2, s[0]);
  Eigen::Matrix3Xd c = Eigen::Matrix3Xd::Constant(3, 2, s[1]), d = Eigen::Matrix3Xd::Constant(3, 2, s[2]);
  const Eigen::Matrix3Xd m = catmull_rom(a, b, c, d, 0.3);
  EXPECT_DOUBLE_EQ(m(2, 1), periodic_catmull_rom(s, 0, 0.3));
}

}  // namespace
}  // namespace systole

// Muscle with fibres contracts by active strain (sim/forces.h): every spring takes the length
// the isochoric stretch diag(1 - c, 1 - k c, 1 / ((1 - c)(1 - k c))) in (fibre, cross-fibre,
// across the wall) gives its direction, so a cell of springs keeps its volume as its fibres shorten.
// A fibre tension t shortens the fibre by a further 1 - t c that the other directions do not take up.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "sim/forces.h"

namespace systole::sim {
namespace {

// A cube's 28 corner pairs, fibres along x, sheet normal along z, the whole cube driven; `d`
// gets each spring's rest vector.
Springs unit_cell(std::vector<Eigen::Vector3d>& d) {
  Springs sp;
  for (int i = 0; i < 8; ++i) {
    for (int j = i + 1; j < 8; ++j) {
      const Eigen::Vector3d a(i & 1, (i >> 1) & 1, (i >> 2) & 1), b(j & 1, (j >> 1) & 1, (j >> 2) & 1);
      d.push_back(b - a);
      sp.rest_m.push_back((b - a).norm());
      sp.region_a.push_back(0);
      sp.region_b.push_back(0);
      const Eigen::Vector3d u = (b - a).normalized();
      sp.fibre_share.push_back(u.x() * u.x());
      sp.normal_share.push_back(u.z() * u.z());
      sp.cross_fibre.push_back(0.6);
    }
  }
  return sp;
}

TEST(ActiveStrain, EverySpringOfACellTakesTheActiveStretch) {
  std::vector<Eigen::Vector3d> d;
  const Springs sp = unit_cell(d);
  const double c = 0.18, k = 0.6;
  Eigen::VectorXd contraction(1);
  contraction << c;
  const Eigen::Vector3d stretch(1 - c, 1 - k * c, 1 / ((1 - c) * (1 - k * c)));
  EXPECT_NEAR(stretch.prod(), 1.0, 1e-12);  // Isochoric.
  for (int j = 0; j < static_cast<int>(d.size()); ++j) {
    EXPECT_NEAR(driven_rest_length(sp, j, contraction), stretch.cwiseProduct(d[j]).norm(), 1e-12) << j;
  }
}

TEST(ActiveStrain, AFibreTensionShortensTheFibreAloneBeyondTheStrain) {
  std::vector<Eigen::Vector3d> d;
  Springs sp = unit_cell(d);
  sp.fibre_tension = 0.5;
  const double c = 0.18, k = 0.6, t = 0.5;
  Eigen::VectorXd contraction(1);
  contraction << c;
  // The fibre pulls to (1 - c)(1 - t c); across the wall the strain's isochoric 1 / ((1 - c)(1 - k c)),
  // which does not make room for the tension's extra shortening.
  const Eigen::Vector3d stretch((1 - c) * (1 - t * c), 1 - k * c, 1 / ((1 - c) * (1 - k * c)));
  for (int j = 0; j < static_cast<int>(d.size()); ++j) {
    EXPECT_NEAR(driven_rest_length(sp, j, contraction), stretch.cwiseProduct(d[j]).norm(), 1e-12) << j;
  }
  // Relaxed muscle (c = 0) keeps its rest lengths whatever the tension.
  contraction << 0;
  for (int j = 0; j < static_cast<int>(d.size()); ++j) EXPECT_DOUBLE_EQ(driven_rest_length(sp, j, contraction), sp.rest_m[j]);
}

TEST(ActiveStrain, WithoutFibresASpringShortensEvenly) {
  Springs sp;
  sp.rest_m = {0.01, 0.01};
  sp.region_a = {0, 0};
  sp.region_b = {0, -1};  // Half driven: half the contraction.
  Eigen::VectorXd contraction(1);
  contraction << 0.2;
  EXPECT_NEAR(driven_rest_length(sp, 0, contraction), 0.008, 1e-15);
  EXPECT_NEAR(driven_rest_length(sp, 1, contraction), 0.009, 1e-15);
  sp.fibre_share = {-1, -1};  // Marked as without fibres in a myocardium: the same.
  sp.normal_share = {0, 0};
  sp.cross_fibre = {0, 0};
  EXPECT_NEAR(driven_rest_length(sp, 0, contraction), 0.008, 1e-15);
}

}  // namespace
}  // namespace systole::sim

// A driven region's signal (study/driven_regions.h): the mean distance of its vertices from
// its organ's rest centroid, which a contraction lowers and a relaxation raises.

#include "study/driven_regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace systole::study {
namespace {

/// `n` points on a circle of `radius` about `centre` in a plane, then `others` far away.
Eigen::Matrix3Xd ring(const Eigen::Vector3d& centre, double radius, int n, int others) {
  Eigen::Matrix3Xd x(3, n + others);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    x.col(i) = centre + radius * Eigen::Vector3d(std::cos(a), 0.3 * std::sin(a), std::sqrt(1 - 0.09) * std::sin(a));
  }
  for (int i = 0; i < others; ++i) x.col(n + i) = centre + Eigen::Vector3d(1.0 + i, 0, 0);
  return x;
}

DrivenRegion region_of(int n, const Eigen::Vector3d& centre) {
  DrivenRegion r;
  r.name = "heart.left_ventricle";
  r.centre = centre;
  r.rate_hz = 1.2;
  for (int i = 0; i < n; ++i) r.vertices.push_back(i);
  return r;
}

TEST(RadialExcursion, IsTheDistanceOfARingFromItsCentre) {
  const Eigen::Vector3d c(0.01, -0.02, 0.03);
  const DrivenRegion r = region_of(12, c);
  EXPECT_NEAR(radial_excursion_m(r, ring(c, 0.04, 12, 5)), 0.04, 1e-15);
}

TEST(RadialExcursion, CountsOnlyTheRegionsVertices) {
  const Eigen::Vector3d c = Eigen::Vector3d::Zero();
  DrivenRegion r = region_of(0, c);
  r.vertices = {0, 2, 4};
  const Eigen::Matrix3Xd x = ring(c, 0.02, 6, 3);  // The far points (1 m and more away) are not in it.
  EXPECT_NEAR(radial_excursion_m(r, x), 0.02, 1e-15);
}

TEST(RadialExcursion, FallsWithAContractionAndRisesWithARelaxation) {
  const Eigen::Vector3d c(0, 0.05, 0);
  const DrivenRegion r = region_of(20, c);
  const Eigen::Matrix3Xd rest = ring(c, 0.03, 20, 0);
  const Eigen::Matrix3Xd contracted = (0.9 * (rest.colwise() - c)).colwise() + c;
  const Eigen::Matrix3Xd relaxed = (1.1 * (rest.colwise() - c)).colwise() + c;
  EXPECT_NEAR(radial_excursion_m(r, contracted), 0.9 * 0.03, 1e-15);
  EXPECT_NEAR(radial_excursion_m(r, relaxed), 1.1 * 0.03, 1e-15);
  // A rigid turn about the centre changes nothing: it measures size, not orientation.
  Eigen::Matrix3d turn;
  turn << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Eigen::Matrix3Xd turned = (turn * (rest.colwise() - c)).colwise() + c;
  EXPECT_NEAR(radial_excursion_m(r, turned), radial_excursion_m(r, rest), 1e-15);
}

}  // namespace
}  // namespace systole::study

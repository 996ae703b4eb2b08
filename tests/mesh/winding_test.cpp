// Winding numbers of closed surfaces: 1 inside, 0 outside, 2 where two overlap, and a ray
// through an edge or a corner counted once.

#include "mesh/winding.h"

#include <gtest/gtest.h>

#include <random>

#include "mesh/icosphere.h"

namespace systole::mesh {
namespace {

/// The unit cube [0, 1]^3 shifted by `at`, its faces split along a diagonal, facing out.
void add_cube(std::vector<Eigen::Vector3d>& x, std::vector<Eigen::Vector3i>& t, const Eigen::Vector3d& at = {0, 0, 0}) {
  const int base = static_cast<int>(x.size());
  for (int i = 0; i < 8; ++i) x.push_back(at + Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    t.emplace_back(base + f[0], base + f[1], base + f[2]);
    t.emplace_back(base + f[0], base + f[2], base + f[3]);
  }
}

Eigen::Matrix3Xd columns(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Matrix3Xd m(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = points[i];
  return m;
}

bool in_unit_cube(const Eigen::Vector3d& p) { return (p.array() > 0).all() && (p.array() < 1).all(); }

TEST(Winding, OneInsideACubeZeroOutside) {
  std::vector<Eigen::Vector3d> x;
  std::vector<Eigen::Vector3i> t;
  add_cube(x, t);
  const std::vector<int> w = winding_numbers(columns(x), t, columns({{0.5, 0.5, 0.5}, {0.01, 0.99, 0.5}, {1.5, 0.5, 0.5}, {-3, -3, -3}}));
  EXPECT_EQ(w, (std::vector<int>{1, 1, 0, 0}));
}

TEST(Winding, TwoWhereTwoSurfacesOverlapAndMinusOneTurnedInsideOut) {
  std::vector<Eigen::Vector3d> x;
  std::vector<Eigen::Vector3i> t;
  add_cube(x, t);
  add_cube(x, t, {0.5, 0.5, 0.5});
  EXPECT_EQ(winding_numbers(columns(x), t, columns({{0.75, 0.75, 0.75}, {0.25, 0.25, 0.25}, {1.25, 1.25, 1.25}})),
            (std::vector<int>{2, 1, 1}));
  for (Eigen::Vector3i& f : t) std::swap(f[1], f[2]);
  EXPECT_EQ(winding_numbers(columns(x), t, columns({{0.25, 0.25, 0.25}})), (std::vector<int>{-1}));
}

TEST(Winding, ARayThroughAnEdgeOrACornerCountsOnce) {
  std::vector<Eigen::Vector3d> x;
  std::vector<Eigen::Vector3i> t;
  add_cube(x, t);
  // Points whose ray passes through a corner, the middle of an edge, or a face's diagonal
  // (the edge two triangles of one face share), from inside and from outside.
  std::vector<Eigen::Vector3d> aims;
  for (int i = 0; i < 8; ++i) aims.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  for (int axis = 0; axis < 3; ++axis) {
    for (int i = 0; i < 4; ++i) {
      Eigen::Vector3d mid(i & 1, (i >> 1) & 1, 0);
      std::swap(mid[2], mid[axis]);
      mid[axis] = 0.5;
      aims.push_back(mid);
    }
  }
  for (int i = 0; i < 6; ++i) aims.push_back(Eigen::Vector3d(0.5, 0.5, 0.5) + 0.5 * Eigen::Vector3d::Unit(i / 2) * (i % 2 ? 1 : -1));
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& aim : aims) {
    for (double back : {1e-9, 0.1, 0.3, 2.0}) points.push_back(aim - back * winding_ray());
  }
  const std::vector<int> w = winding_numbers(columns(x), t, columns(points));
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(w[i], in_unit_cube(points[i]) ? 1 : 0) << points[i].transpose();
  }
}

TEST(Winding, MatchesTheSphereAtManyPoints) {
  const TriangleMesh sphere = icosphere(1.0, 4);
  std::vector<Eigen::Vector3d> points;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.3, 1.3);
  while (points.size() < 20000) {
    const Eigen::Vector3d p(uniform(random), uniform(random), uniform(random));
    if (std::abs(p.norm() - 1) > 0.01) points.push_back(p);  // The facets lie within 0.2 % of the sphere.
  }
  const std::vector<int> w = winding_numbers(columns(sphere.positions), sphere.triangles, columns(points));
  for (std::size_t i = 0; i < points.size(); ++i) ASSERT_EQ(w[i], points[i].norm() < 1 ? 1 : 0) << points[i].transpose();
}

}  // namespace
}  // namespace systole::mesh

// Meshing an implicit surface (mesh/procedural/implicit_mesher.h): the result is closed,
// a sphere's topology, outward-facing, on the surface, near the triangle count asked for,
// with the volume of the shape, and deterministic.

#include "mesh/procedural/implicit_mesher.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "common/error.h"

namespace systole::mesh::procedural {
namespace {

double volume(const TriangleMesh& m) {
  double six = 0;
  for (const Eigen::Vector3i& t : m.triangles) six += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]]));
  return six / 6;
}

/// Every directed edge once and its reverse once: closed, manifold, consistently oriented.
void expect_closed_and_oriented(const TriangleMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const Eigen::Vector3i& t : m.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  int bad = 0;
  for (const auto& [edge, count] : directed) {
    if (count != 1 || !directed.count({edge.second, edge.first})) ++bad;
  }
  EXPECT_EQ(bad, 0);
  // A sphere's topology: V - E + F = 2.
  std::set<int> used;
  for (const Eigen::Vector3i& t : m.triangles) used.insert({t[0], t[1], t[2]});
  EXPECT_EQ(static_cast<int>(used.size()), static_cast<int>(m.positions.size()));  // No loose vertices.
  const long long v = static_cast<long long>(m.positions.size()), f = static_cast<long long>(m.triangles.size());
  const long long e = static_cast<long long>(directed.size()) / 2;
  EXPECT_EQ(v - e + f, 2);
}

double smallest_angle_deg(const TriangleMesh& m) {
  double least = 180;
  for (const Eigen::Vector3i& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = m.positions[t[(k + 1) % 3]] - m.positions[t[k]];
      const Eigen::Vector3d b = m.positions[t[(k + 2) % 3]] - m.positions[t[k]];
      least = std::min(least, std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi);
    }
  }
  return least;
}

Field sphere_field(const Eigen::Vector3d& c, double r) {
  Field f;
  f.primitives.push_back(ellipsoid(0, c, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(r), 0));
  return f;
}

TEST(ImplicitMesher, ASphereBecomesAClosedOutwardSphereOfItsVolume) {
  const Eigen::Vector3d c(0.01, 0.02, -0.01);
  const double r = 0.05;
  const Field f = sphere_field(c, r);
  MesherSettings s;
  s.center = c;
  s.bound_radius = 0.1;
  s.target_triangles = 800;
  const TriangleMesh m = mesh_implicit_surface(f, s);
  expect_closed_and_oriented(m);
  const double exact = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  // Outward (positive volume), and an inscribed polyhedron of ~800 faces is within 2 %.
  EXPECT_GT(volume(m), 0.97 * exact);
  EXPECT_LT(volume(m), exact);
  for (const Eigen::Vector3d& p : m.positions) EXPECT_NEAR((p - c).norm(), r, 1e-6 * r);
  EXPECT_GT(static_cast<int>(m.triangles.size()), 800 / 2);
  EXPECT_LT(static_cast<int>(m.triangles.size()), 800 * 2);
  EXPECT_GT(smallest_angle_deg(m), 10.0);
}

TEST(ImplicitMesher, AnElongatedStarShapedSurfaceKeepsItsShape) {
  // A cigar-shaped ellipsoid, far from a sphere but star-shaped about its centre.
  Field f;
  const Eigen::Vector3d radii(0.08, 0.03, 0.025);
  f.primitives.push_back(ellipsoid(0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), radii, 0));
  MesherSettings s;
  s.bound_radius = 0.15;
  s.target_triangles = 1500;
  const TriangleMesh m = mesh_implicit_surface(f, s);
  expect_closed_and_oriented(m);
  const double exact = 4.0 / 3.0 * std::numbers::pi * radii.prod();
  EXPECT_NEAR(volume(m), exact, 0.03 * exact);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (const Eigen::Vector3d& p : m.positions) {
    EXPECT_NEAR(f.distance(p), 0.0, 1e-6);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // Its extent is the ellipsoid's along each axis.
  EXPECT_TRUE((hi - radii).cwiseAbs().maxCoeff() < 0.05 * radii.minCoeff()) << hi.transpose();
  EXPECT_TRUE((lo + radii).cwiseAbs().maxCoeff() < 0.05 * radii.minCoeff()) << lo.transpose();
}

TEST(ImplicitMesher, TheSameFieldGivesTheSameMesh) {
  const Field f = sphere_field(Eigen::Vector3d::Zero(), 0.04);
  MesherSettings s;
  s.bound_radius = 0.1;
  s.target_triangles = 400;
  const TriangleMesh a = mesh_implicit_surface(f, s), b = mesh_implicit_surface(f, s);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST(ImplicitMesher, MoreTrianglesAskedGivesMoreAndACloserVolume) {
  const double r = 0.05, exact = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const Field f = sphere_field(Eigen::Vector3d::Zero(), r);
  MesherSettings s;
  s.bound_radius = 0.1;
  s.target_triangles = 300;
  const TriangleMesh coarse = mesh_implicit_surface(f, s);
  s.target_triangles = 2000;
  const TriangleMesh fine = mesh_implicit_surface(f, s);
  EXPECT_GT(fine.triangles.size(), 3 * coarse.triangles.size());
  EXPECT_LT(exact - volume(fine), exact - volume(coarse));
}

TEST(ImplicitMesher, ACentreOutsideTheSurfaceIsRefused) {
  const Field f = sphere_field(Eigen::Vector3d::Zero(), 0.02);
  MesherSettings s;
  s.center = Eigen::Vector3d(0.05, 0, 0);
  try {
    mesh_implicit_surface(f, s);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::kInternal);
  }
}

}  // namespace
}  // namespace systole::mesh::procedural

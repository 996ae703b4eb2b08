#include "mesh/normals.h"

#include <gtest/gtest.h>

#include "mesh/weld.h"
#include "test_meshes.h"

namespace systole::mesh {
namespace {

std::vector<float> normals_of(const TriangleMesh& m) {
  std::vector<double> xyz;
  for (const auto& p : m.positions) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  std::vector<float> n(xyz.size(), 7.0f);
  vertex_normals(xyz.data(), static_cast<int>(m.positions.size()), m.triangles, n.data());
  return n;
}

TEST(Normals, SpherePointsOutward) {
  const Eigen::Vector3d center(0.1, -0.2, 0.3);
  OrganMesh sphere{testing::sphere(3, 0.05, center), {}, {}};
  weld(sphere, default_weld_tolerance(sphere.surface));
  const std::vector<float> n = normals_of(sphere.surface);
  for (size_t v = 0; v < sphere.surface.positions.size(); ++v) {
    const Eigen::Vector3d radial = (sphere.surface.positions[v] - center).normalized();
    const Eigen::Vector3d normal(n[3 * v], n[3 * v + 1], n[3 * v + 2]);
    EXPECT_NEAR(normal.norm(), 1.0, 1e-6);
    EXPECT_GT(normal.dot(radial), 0.99);
  }
}

TEST(Normals, IsolatedAndZeroAreaVerticesGetDefault) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}};
  m.triangles = {{0, 1, 2}};  // Zero area; vertex 3 in no triangle.
  const std::vector<float> n = normals_of(m);
  for (int v = 0; v < 4; ++v) {
    EXPECT_EQ(n[3 * v], 0.0f);
    EXPECT_EQ(n[3 * v + 1], 0.0f);
    EXPECT_EQ(n[3 * v + 2], 1.0f);
  }
}

TEST(Normals, Deterministic) {
  const TriangleMesh m = testing::sphere(4, 1.0, Eigen::Vector3d::Zero());
  EXPECT_EQ(normals_of(m), normals_of(m));
}

}  // namespace
}  // namespace systole::mesh

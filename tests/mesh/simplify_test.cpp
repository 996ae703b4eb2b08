// Simplifying a mesh for drawing: fewer triangles over the same vertices, the surface
// within the error asked for, open borders where they were.

#include "mesh/simplify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "mesh/icosphere.h"
#include "support/shapes.h"

namespace systole::mesh {
namespace {

TEST(Simplify, ASphereStaysNearItselfOverItsOwnVertices) {
  const double radius = 0.05, error = 0.0002;
  const TriangleMesh sphere = icosphere(radius, 5);  // 20480 triangles.
  const SimplifiedTriangles s = simplify(sphere, error);
  EXPECT_LT(s.triangles.size(), sphere.triangles.size() / 3);
  EXPECT_GT(s.triangles.size(), 100u);
  EXPECT_LE(s.error_m, error);
  // Every triangle's corners are the sphere's own vertices, and its middle (where an
  // inscribed triangle lies deepest) near the sphere: meshoptimizer bounds the distance of
  // the vertices it removes from the new surface; between them the surface strays up to
  // twice that (measured here: 0.39 mm for 0.2 mm), which clip/render_detail.h allows for.
  double deepest = 0;
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(t[k] >= 0 && t[k] < static_cast<int>(sphere.positions.size()));
    const Eigen::Vector3d centroid = (sphere.positions[t[0]] + sphere.positions[t[1]] + sphere.positions[t[2]]) / 3;
    deepest = std::max(deepest, radius - centroid.norm());
  }
  std::printf("[ simplify ] %zu of %zu triangles; deepest %.3g mm for an error of %.3g mm\n", s.triangles.size(),
              sphere.triangles.size(), deepest * 1e3, s.error_m * 1e3);
  EXPECT_LE(deepest, error * 2.5);
}

TEST(Simplify, AFlatSheetCollapsesButKeepsItsBorder) {
  const TriangleMesh m = test::sheet(40, 0.1);  // 3200 triangles, all in one plane.
  const SimplifiedTriangles s = simplify(m, 1e-4);
  EXPECT_LT(s.triangles.size(), m.triangles.size() / 4);
  std::set<int> used;
  for (const auto& t : s.triangles) used.insert({t[0], t[1], t[2]});
  for (int i = 0; i <= 40; ++i) {
    for (const int v : {i, 40 * 41 + i, i * 41, i * 41 + 40}) EXPECT_TRUE(used.count(v)) << "border vertex " << v;
  }
}

TEST(Simplify, NoErrorAllowedKeepsEveryTriangle) {
  const TriangleMesh sphere = icosphere(0.05, 3);
  EXPECT_EQ(simplify(sphere, 0).triangles.size(), sphere.triangles.size());
}

}  // namespace
}  // namespace systole::mesh

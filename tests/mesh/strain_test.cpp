#include "mesh/strain.h"

#include <gtest/gtest.h>

#include "mesh/icosphere.h"

namespace systole::mesh {
namespace {

TEST(VertexStrain, UniformScaleGivesThatStrainEverywhere) {
  const TriangleMesh sphere = icosphere(0.05, 2);
  const VertexStrain strain(sphere.positions, sphere.triangles);
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(sphere.positions.size()));
  for (std::size_t v = 0; v < sphere.positions.size(); ++v) x.col(static_cast<Eigen::Index>(v)) = 0.9 * sphere.positions[v];
  std::vector<double> out;
  strain.compute(x, out);
  ASSERT_EQ(out.size(), sphere.positions.size());
  for (const double s : out) EXPECT_NEAR(s, -0.1, 1e-12);
}

TEST(VertexStrain, RestIsZeroAndAStretchedEdgeIsPositiveAtItsEnds) {
  // Two triangles sharing edge 1-2; moving vertex 3 away stretches only its two edges.
  const std::vector<Eigen::Vector3d> rest = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<Eigen::Vector3i> triangles = {{0, 1, 2}, {1, 3, 2}};
  const VertexStrain strain(rest, triangles);
  Eigen::Matrix3Xd x(3, 4);
  for (int v = 0; v < 4; ++v) x.col(v) = rest[static_cast<std::size_t>(v)];
  std::vector<double> out;
  strain.compute(x, out);
  for (const double s : out) EXPECT_EQ(s, 0.0);
  x.col(3) = Eigen::Vector3d(2, 2, 0);  // Edges 1-3 and 2-3 grow from 1 to sqrt(5).
  strain.compute(x, out);
  EXPECT_NEAR(out[3], std::sqrt(5.0) - 1, 1e-12);
  EXPECT_EQ(out[0], 0.0);
  EXPECT_GT(out[1], 0.0);
  EXPECT_LT(out[1], out[3]);  // Averaged with its unstretched edges.
}

}  // namespace
}  // namespace systole::mesh

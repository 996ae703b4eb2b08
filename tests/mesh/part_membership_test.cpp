// An organ mesh's named parts (mesh/mesh.h): finding a part by name, which vertices belong
// to it (first part or also), its own surface, and the membership list kept canonical.

#include "mesh/mesh.h"

#include <gtest/gtest.h>

namespace systole::mesh {
namespace {

/// Two squares side by side (vertices 0-5, two triangles each), parts "left" and "right";
/// the middle edge's vertices 1 and 4 belong to both.
OrganMesh two_squares() {
  OrganMesh m;
  m.surface.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  m.surface.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  m.part_names = {"left", "right"};
  m.vertex_part = {0, 0, 1, 0, 0, 1};
  m.also_in = {{1, 1}, {4, 1}};
  return m;
}

TEST(PartMembership, PartsAreFoundByName) {
  const OrganMesh m = two_squares();
  EXPECT_EQ(m.part_index("left"), 0);
  EXPECT_EQ(m.part_index("right"), 1);
  EXPECT_EQ(m.part_index("apex"), -1);
  EXPECT_EQ(m.part_index(""), -1);
}

TEST(PartMembership, AMaskHoldsFirstAndOtherMembers) {
  const OrganMesh m = two_squares();
  EXPECT_EQ(m.part_mask(0), (std::vector<char>{1, 1, 0, 1, 1, 0}));
  EXPECT_EQ(m.part_mask(1), (std::vector<char>{0, 1, 1, 0, 1, 1}));  // 1 and 4 by also_in.
  EXPECT_EQ(m.part_mask(7), std::vector<char>(6, 0));
}

TEST(PartMembership, APartsSurfaceIsTheTrianglesWhollyInIt) {
  const OrganMesh m = two_squares();
  const TriangleMesh left = m.part_surface(0), right = m.part_surface(1);
  EXPECT_EQ(left.positions, m.surface.positions);  // Over the same vertices.
  EXPECT_EQ(left.triangles, (std::vector<Eigen::Vector3i>{{0, 1, 4}, {0, 4, 3}}));
  EXPECT_EQ(right.triangles, (std::vector<Eigen::Vector3i>{{1, 2, 5}, {1, 5, 4}}));
  // Without the shared edge's membership the right part has no whole triangle.
  OrganMesh alone = two_squares();
  alone.also_in.clear();
  EXPECT_TRUE(alone.part_surface(1).triangles.empty());
}

TEST(PartMembership, NormalizingSortsDropsRepeatsAndFirstParts) {
  OrganMesh m = two_squares();
  m.also_in = {{4, 1}, {1, 1}, {4, 1}, {0, 0}, {3, 1}, {-1, 1}};
  m.normalize_membership();
  // (0, 0) repeats vertex 0's first part; (-1, 1) names no vertex.
  EXPECT_EQ(m.also_in, (std::vector<std::pair<int, int>>{{1, 1}, {3, 1}, {4, 1}}));
  const auto again = m.also_in;
  m.normalize_membership();
  EXPECT_EQ(m.also_in, again);  // Idempotent.
}

}  // namespace
}  // namespace systole::mesh

// The part-crossing check on constructed surfaces: a patch lying above a sheet that moves
// down through it is caught with the depth it went through; one that moves away is not;
// groups and repeated names are not checked against their own pieces.

#include "study/part_crossing.h"

#include <gtest/gtest.h>

#include <set>

#include "support/shapes.h"

namespace systole::study {
namespace {

/// Adds an n x n sheet (support/shapes.h) of side `size` centred at `centre` to `mesh` as
/// part `part`.
void add_sheet(mesh::OrganMesh& mesh, int part, const Eigen::Vector3d& centre, double size, int n) {
  const mesh::TriangleMesh s = test::sheet(n, size, centre - Eigen::Vector3d(size / 2, size / 2, 0));
  const int first = static_cast<int>(mesh.surface.positions.size());
  for (const auto& p : s.positions) {
    mesh.surface.positions.push_back(p);
    mesh.vertex_part.push_back(part);
  }
  for (const auto& t : s.triangles) mesh.surface.triangles.push_back(t + Eigen::Vector3i::Constant(first));
}

/// A 2 cm sheet (part "wall") and a 5 mm patch (part "valve") 1 mm above its centre, with
/// a group "both" over the two and a material "tissue" that is exactly the wall.
mesh::OrganMesh wall_and_valve() {
  mesh::OrganMesh m;
  m.part_names = {"wall", "valve", "both", "tissue"};
  add_sheet(m, 0, Eigen::Vector3d::Zero(), 0.02, 20);
  const int wall_vertices = static_cast<int>(m.surface.positions.size());
  add_sheet(m, 1, Eigen::Vector3d(0, 0, 0.001), 0.005, 5);
  for (int v = 0; v < static_cast<int>(m.surface.positions.size()); ++v) {
    m.also_in.emplace_back(v, 2);
    if (v < wall_vertices) m.also_in.emplace_back(v, 3);
  }
  m.normalize_membership();
  return m;
}

Eigen::Matrix3Xd positions(const mesh::OrganMesh& m) {
  Eigen::Matrix3Xd x(3, m.surface.positions.size());
  for (std::size_t v = 0; v < m.surface.positions.size(); ++v) x.col(static_cast<Eigen::Index>(v)) = m.surface.positions[v];
  return x;
}

/// The positions with the valve's vertices moved by dz.
Eigen::Matrix3Xd valve_moved(const mesh::OrganMesh& m, double dz) {
  Eigen::Matrix3Xd x = positions(m);
  for (std::size_t v = 0; v < m.vertex_part.size(); ++v) {
    if (m.vertex_part[v] == 1) x(2, static_cast<Eigen::Index>(v)) += dz;
  }
  return x;
}

TEST(PartCrossing, ChecksTheSmallestPiecesOnly) {
  const PartCrossingWatch watch(wall_and_valve(), 0.003);
  EXPECT_EQ(watch.parts(), (std::vector<std::string>{"wall", "valve"}));
}

TEST(PartCrossing, APartMovedThroughAnotherIsCaughtWithItsDepth) {
  const mesh::OrganMesh m = wall_and_valve();
  PartCrossingWatch watch(m, 0.003);
  watch.check(valve_moved(m, -0.0005), 1);  // Still 0.5 mm above: no crossing.
  EXPECT_EQ(watch.worst().vertex, -1);
  watch.check(valve_moved(m, -0.0016), 2);  // 0.6 mm below the wall.
  EXPECT_NEAR(watch.worst().depth_m, 0.0006, 1e-9);
  EXPECT_EQ(watch.worst().frame, 2);
  // The wall's vertices under the valve are as far through it as the valve's through the wall.
  const std::set<std::string> pair{watch.worst().from, watch.worst().into};
  EXPECT_EQ(pair, (std::set<std::string>{"valve", "wall"}));
}

TEST(PartCrossing, MovingApartOrTogetherWithoutCrossingIsNotACrossing) {
  const mesh::OrganMesh m = wall_and_valve();
  PartCrossingWatch watch(m, 0.003);
  watch.check(valve_moved(m, 0.0015), 1);
  Eigen::Matrix3Xd both_down = positions(m);
  both_down.row(2).array() -= 0.002;
  watch.check(both_down, 2);
  EXPECT_EQ(watch.worst().vertex, -1);
}

TEST(PartCrossing, APartThatWasFarAtRestIsComparedWithWhereItWas) {
  // The valve 12 mm above the wall at rest, moved 13 mm down through it in one step.
  mesh::OrganMesh m = wall_and_valve();
  for (std::size_t v = 0; v < m.vertex_part.size(); ++v) {
    if (m.vertex_part[v] == 1) m.surface.positions[v].z() += 0.011;
  }
  PartCrossingWatch watch(m, 0.003);
  watch.check(valve_moved(m, -0.013), 1);
  EXPECT_NEAR(watch.worst().depth_m, 0.001, 1e-9);
  EXPECT_GT(watch.pairs_compared(), 0u);
}

TEST(PartCrossing, OnePartHasNothingToCheck) {
  mesh::OrganMesh m;
  m.part_names = {"only"};
  add_sheet(m, 0, Eigen::Vector3d::Zero(), 0.02, 4);
  PartCrossingWatch watch(m, 0.003);
  EXPECT_EQ(watch.parts().size(), 1u);
  watch.check(positions(m), 1);
  EXPECT_EQ(watch.worst().vertex, -1);
}

}  // namespace
}  // namespace systole::study
